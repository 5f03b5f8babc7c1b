// Sec. 4.2-4.3: a registration edge <j, i> of Eq. 21-22 with its data association, and an M-step's report.
#pragma once

#include "mstep/VectorMatcher.h"
#include "posegraph/PoseGraph.h"

#include <mrpt/math/TPose2D.h>

#include <functional>
#include <utility>
#include <vector>

namespace gridvector
{
/** An edge of the pose graph with its data association (Eq. 25's M_cor). */
struct Constraint
{
	uint32_t from = 0, to = 0;  //!< from < to
	EdgeKind kind = EdgeKind::Sequential;
	mrpt::math::TPose2D z;  //!< pose of `to` in `from`'s frame
	Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
	std::vector<VectorPair> correspondences;  //!< (vector of `from`, vector of `to`), sorted
	double rms = 0, matchedLength = 0, matchedShare = 0;
	double degeneracy = 1;  //!< smallest / largest translation information eigenvalue
	int dof = 3;  //!< 2: the weak translation direction is marginalised out of `information`
	bool rejected = false;  //!< deactivated by the pose graph's residual test
	uint64_t sigFrom = 0, sigTo = 0;  //!< static-vector signatures of both scans when registered
	mrpt::math::TPose2D checkedAt;  //!< relative pose of the estimate when last checked
};

using EdgeKey = std::pair<uint32_t, uint32_t>;

/** What one M-step did (Fig. 11 uses changedShare). */
struct MStepReport
{
	size_t constraints = 0;  //!< registration edges after the step (active or not)
	size_t active = 0;  //!< ... of which used by the optimiser
	size_t sequential = 0, overlap = 0, loop = 0;  //!< active edges by kind
	size_t added = 0, removed = 0, recomputed = 0;  //!< Eq. 24: the changed constraints
	size_t registrations = 0, failedRegistrations = 0;
	size_t unverified = 0;  //!< overlap and loop edges dropped by the pairwise consistency check
	size_t loopSearches = 0;  //!< pairs given to the loop search
	size_t passesBeyondBound = 0;  //!< (pose, earlier pass) pairs left out by kRecentPasses (overlap and loop search)
	double changedShare = 0;  //!< (added + removed + recomputed) / constraints
	OptimizeStats optimisation;
	double registrationSeconds = 0, seconds = 0;
	double updateSeconds = 0, overlapSeconds = 0, loopSeconds = 0;  //!< parts of registrationSeconds
};

/** Static vectors of each scan in its own frame (MatchSegment ids stable across iterations). */
using Scans = std::vector<std::vector<MatchSegment>>;
using Poses = std::vector<mrpt::math::TPose2D>;

/** Called now and then with the share of the scans processed in a pass. */
using ProgressFn = std::function<void(const char* stage, double fraction)>;
inline void reportProgress(const ProgressFn& f, const char* stage, size_t i, size_t n)
{
	if (f && (i % 16 == 0 || i + 1 == n)) f(stage, double(i + 1) / double(n));
}

}  // namespace gridvector
