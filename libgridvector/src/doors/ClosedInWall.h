// Beyond the paper (it needs the door seen moving): a door closed in most observations has its
// closed leaf merged into the wall, where Eq. 6 kept it static.
#pragma once

#include "doors/Door.h"

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <vector>

namespace gridvector::doors
{
/** Door d's wall (longer than max_door_length) runs through the hinge (within kMaxWallOffset)
 * and on past it, on the states' side, for a leaf's length (d.length - max_length_diff), and no
 * state lies along it: the closed leaf lies there, inside the wall (d.closedInWall,
 * d.closedAngle). It is no state seen (not in angles); stateSpans makes it dynamic. */
void closedInWall(const std::vector<GridVector>& v, Door& d, const DoorOptions& opts);

}  // namespace gridvector::doors
