// Beyond the paper (Fig. 10's hinge is at a wall's end): where the static wall was merged across
// the doorway (the door closed most of the time), the hinge lies on the wall's interior.
#pragma once

#include "doors/Door.h"

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <vector>

namespace gridvector::doors
{
/** T corners of wall s (longer than a door) and candidate d: an end of d within kMaxWallOffset
 * of the wall's interior. The candidate leaves the wall (an open state) or, dynamic, lies along
 * it (a closed state inside the merged wall: each of its ends may be the hinge). A closed state
 * running on past the wall's end also makes a corner at that end (the wall merged part way
 * into the doorway or the closed state reaching back into it; the other states' corners decide
 * which is the hinge). Appended to `out`. */
void teeCorners(const std::vector<GridVector>& v, size_t s, size_t d, const DoorOptions& opts,
				std::vector<Corner>& out);

/** A group of T corners only is a hinge with a closed state along the wall (people by a wall
 * make T corners too, none along it); true for a group with an end corner. */
bool teeHingeSeenClosed(const std::vector<Corner>& cs, const std::vector<size_t>& group);

}  // namespace gridvector::doors
