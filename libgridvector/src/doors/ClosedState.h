// Beyond the paper (its corners have two borders at an angle): a dynamic candidate continuing its
// wall's line is the door seen closed.
#pragma once

#include "doors/Door.h"

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

namespace gridvector::doors
{
/** Corner c (the wall's and the candidate's ends meet, HingeRule::meetingEnds, but the two do
 * not turn) is a closed state when the candidate is dynamic and runs on along the wall's line
 * (its tip within max_corner_gap of it, farther along it than the vertex): c.alongWall. A leaf
 * overlapping the wall (merged closed states reach into it) starts at the wall's end: vertex
 * and length are taken there. False: no corner. */
bool closedStateCorner(const GridVector& wall, Corner& c, const DoorOptions& opts);

}  // namespace gridvector::doors
