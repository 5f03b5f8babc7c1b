#include "mstep/SequentialChain.h"
#include "mstep/PoseFusion.h"
#include <mrpt/math/TPose2D.h>

#include <algorithm>
#include <cmath>

namespace gridvector
{
using mrpt::math::TPose2D;

// First M-step: register each scan against its predecessors, chaining the fused poses.
void SequentialChain::chain(const Scans& scans, Poses& poses, MStepReport& rep) const
{
	const size_t n = scans.size();
	poses.assign(n, TPose2D(0, 0, 0));
	if (n == 0) return;
	poses[0] = odometry_[0];
	for (size_t i = 1; i < n; ++i)
	{
		reportProgress(progress_, "sequential registration", i, n);
		const TPose2D odo = odometry_[i] - odometry_[i - 1];
		// information-weighted fusion of the predictions, linearised at the odometry guess
		PoseFusion fusion(poses[i - 1] + odo,
						  PoseFusion::toWorld(PoseGraph::odometryInformation(odo, cfg_.posegraph), poses[i - 1].phi));
		const size_t lo = i > size_t(cfg_.mstep.sequentialWindow) ? i - cfg_.mstep.sequentialWindow : 0;
		for (size_t j = i; j-- > lo;)
		{
			Constraint c;
			if (!registerChained(uint32_t(j), uint32_t(i), scans, fusion.pose() - poses[j], c, rep)) continue;
			fusion.add(poses[j] + c.z, PoseFusion::toWorld(c.information, poses[j].phi));
			book_.edges[{uint32_t(j), uint32_t(i)}] = std::move(c);
			++rep.added;
		}
		poses[i] = fusion.pose();
	}
}

// A sequential pair of the first M-step from the chained guess, else (mstep.sequential_odometry_guess) from the
// odometry between its scans: a guess that does not pass through the predecessors' registered poses.
bool SequentialChain::registerChained(uint32_t j, uint32_t i, const Scans& scans, const TPose2D& chained, Constraint& c,
									  MStepReport& rep) const
{
	if (reg_.registerPair(j, i, EdgeKind::Sequential, scans, chained, c, rep)) return true;
	if (!cfg_.mstep.sequentialOdometryGuess) return false;
	const TPose2D odo = odometry_[i] - odometry_[j];
	return book_.movedSince(chained, odo) && reg_.registerPair(j, i, EdgeKind::Sequential, scans, odo, c, rep);
}

// Later M-steps: sequential pairs not (or no longer) in the graph are retried.
void SequentialChain::addMissing(const Scans& scans, const Poses& poses, MStepReport& rep) const
{
	const size_t w = size_t(std::max(1, cfg_.mstep.sequentialWindow));
	for (size_t i = 1; i < scans.size(); ++i)
		for (size_t j = i > w ? i - w : 0; j < i; ++j)
		{
			const EdgeKey key{uint32_t(j), uint32_t(i)};
			if (book_.edges.count(key)) continue;
			const TPose2D rel = poses[i] - poses[j];
			if (!book_.retry(key, rel)) continue;
			Constraint c;
			if (reg_.registerPair(key.first, key.second, EdgeKind::Sequential, scans, rel, c, rep))
				book_.keep(key, std::move(c), rep);
			else
				book_.fail(key, rel);
		}
}

}  // namespace gridvector
