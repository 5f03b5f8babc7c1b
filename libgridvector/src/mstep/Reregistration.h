// Beyond the paper (mstep.overlap_reregister_moved): overlap registrations that moved beyond the matcher's
// initial gates, registered again from the estimate optimised without them.
#pragma once

#include "mstep/GraphOptimisation.h"
#include "mstep/OverlapEdges.h"

namespace gridvector
{
/** The moved pairs registered again from the optimised `poses`, pairwise-checked (verifyOverlaps) and, if any is
 * added, optimised again; returns whether it optimised (rep.optimisation then sums both optimisations). */
bool reregisterMoved(const OverlapEdges& overlaps, ConstraintSet& book, GraphOptimisation& optimiser,
					 const MStepOptions& opts, const Poses& odometry, const Scans& scans, Poses& poses,
					 const std::vector<MovedPair>& moved, MStepReport& rep);

}  // namespace gridvector
