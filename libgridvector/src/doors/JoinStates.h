// Beyond the paper (Fig. 10 shows the states that make corners): vectors from a found door's
// hinge into its swept arc are more states of it, or parts of one.
#pragma once

#include "doors/Door.h"

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <vector>

namespace gridvector::doors
{
/** Vector k from the hinge, its tip at angle a and distance r, is a leaf of door d (taken); a
 * whole leaf (r at least d.length - max_length_diff) min_state_diff_deg from every state is a
 * state too. */
void addLeaf(Door& d, size_t k, double a, double r, std::vector<bool>& taken, const DoorOptions& opts);

/** Every vector not taken with an end within max_vertex_distance of the hinge and its tip in
 * the swept arc (inSweep), reaching no farther than `reach` (the longest leaf of the door's
 * corners + max_length_diff): one more state (a door opened to different angles; a state whose
 * corner went to another wall piece) or part of one (a leaf seen in part: occluded, or cut by
 * Fig. 4's split). */
void joinStates(const std::vector<GridVector>& v, Door& d, double reach, std::vector<bool>& taken,
				const DoorOptions& opts);

}  // namespace gridvector::doors
