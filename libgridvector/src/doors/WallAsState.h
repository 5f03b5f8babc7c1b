// Beyond the paper (its wall is the long static vector): a static open state of leaf length from
// the hinge may have served as the other states' wall.
#pragma once

#include "doors/Door.h"

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <vector>

namespace gridvector::doors
{
/** Door d's corners shared a static vector no longer than `reach` (an open state Eq. 6 kept
 * static): the door's wall becomes the longest static vector (longer than max_door_length, not
 * taken) through the hinge, end or interior, and the short one, if it starts at the hinge and
 * lies in the swept arc from that wall, is a state too (addLeaf). Without a longer wall nothing
 * changes. */
void wallAsState(const std::vector<GridVector>& v, Door& d, double reach, std::vector<bool>& taken,
				 const DoorOptions& opts);

}  // namespace gridvector::doors
