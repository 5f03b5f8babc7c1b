// Beyond the paper (Sec. 4.3 builds an edge wherever scan ranges cover each other): the pairwise consistency
// check of this M-step's overlap and loop edges before they reach the optimiser.
#pragma once

#include "mstep/ConstraintSet.h"

namespace gridvector
{
/** How many edges near both ends of an edge agree with it (their cycle closes) and how many do not. */
struct Support
{
	int support = 0, against = 0;
};

/** The non-sequential, unrejected edges (j', i') near both ends of `c` (within mstep.overlap_run_gap) whose cycle
 * j -> i -> i' -> j' -> j under the current trajectory closes within mstep.consistency_chi2, and those whose does not.
 */
Support supportOf(const Constraint& c, const std::map<EdgeKey, Constraint>& edges, const Poses& poses,
				  const MStepOptions& opts);

/** Is an edge strong enough to be kept when no other edge supports or contradicts it? */
bool strong(const Constraint& c);

/** Keeps the `fresh` edges with more support than contradiction (or strong and alone); the others are dropped,
 * marked failed and counted in rep.unverified (a loop edge that replaced a weak edge restores it). */
void verifyOverlaps(ConstraintSet& book, const MStepOptions& opts, const Poses& poses,
					const std::vector<EdgeKey>& fresh, MStepReport& rep);

}  // namespace gridvector
