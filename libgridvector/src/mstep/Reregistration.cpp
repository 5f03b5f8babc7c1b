#include "mstep/Reregistration.h"
#include "mstep/Consistency.h"
#include <mrpt/math/TPose2D.h>

#include <algorithm>

namespace gridvector
{
using mrpt::math::TPose2D;

// mstep.overlap_reregister_moved: a registration that had to move beyond the initial gates started
// from an estimate that did not show the overlap; from the estimate the other edges give, the
// matcher starts inside its gates (or, where nothing moved the pair, repeats the first registration).
bool reregisterMoved(const OverlapEdges& overlaps, ConstraintSet& book, GraphOptimisation& optimiser,
					 const MStepOptions& opts, const Poses& odometry, const Scans& scans, Poses& poses,
					 const std::vector<MovedPair>& moved, MStepReport& rep)
{
	std::vector<EdgeKey> again;
	for (const MovedPair& m : moved)
	{
		if (book.edges.count(m.key)) continue;  // the loop search registered the pair
		const TPose2D rel = poses[m.key.second] - poses[m.key.first];
		Constraint c;
		if (overlaps.registerOverlap(m.key, m.nearest, scans, rel, c, rep))
		{
			book.keep(m.key, std::move(c), rep);
			again.push_back(m.key);
		}
		else
			book.fail(m.key, rel);
	}
	verifyOverlaps(book, opts, poses, again, rep);
	if (std::none_of(again.begin(), again.end(), [&](const EdgeKey& k) { return book.edges.count(k) > 0; }))
		return false;
	const OptimizeStats first = rep.optimisation;
	optimiser.optimise(poses, odometry, book.edges, rep);
	rep.optimisation.iterations += first.iterations;
	rep.optimisation.seconds += first.seconds;
	rep.optimisation.initialError = first.initialError;
	return true;
}

}  // namespace gridvector
