// Beyond the paper (its states are the dynamic vectors): a door's states are dynamic also where a
// static wall runs along one (merged across the doorway).
#pragma once

#include "doors/Door.h"

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <utility>
#include <vector>

namespace gridvector::doors
{
/** Where the doors' states (and a closed leaf inside the wall, Door::closedInWall) lie on v:
 * [from, to] in metres from v's start, for every state parallel to v (within
 * min_corner_angle_deg) whose hinge and tip are within kMaxWallOffset of v's line. */
std::vector<std::pair<double, double>> stateSpans(const std::vector<Door>& doors, const GridVector& v,
												  const DoorOptions& opts);

}  // namespace gridvector::doors
