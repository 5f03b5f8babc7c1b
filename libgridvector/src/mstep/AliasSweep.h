// Beyond the paper (issue 21, item 2): a registration between passes that repeated structure along its
// weakest translation direction (a corridor's doors and pillars) could have produced elsewhere.
#pragma once

#include "mstep/VectorMatcher.h"

#include <Eigen/Core>
#include <mrpt/math/TPose2D.h>

#include <vector>

namespace gridvector
{
/** Sweeps a registration of scan B in scan A along its weakest translation direction.
 *
 * Two scans of a corridor taken some metres apart share only part of their view, so the matched length
 * prefers the shift that lays one view over the other: at a wrong shift by one period of the corridor's
 * doors it can match more than at the true one. What each shift explains is compared instead as the share
 * of what both scans show along that direction there (covisibleLength: the crosswise vectors): a distinct registration
 * along that direction, within `reach`, accepted by the matcher and explaining `ambiguity` of the registration's share,
 * makes it aliased. Uses the caller's matcher (its workspace: one thread). */
class AliasSweep
{
   public:
	/** Solutions closer than this [m] are one (LoopSearch's test of distinct solutions too). */
	static constexpr double kDistinctDistance = 0.3;

	AliasSweep(const VectorMatcher& matcher, double ambiguity) : matcher_(matcher), ambiguity_(ambiguity) {}

	/** Is the accepted registration `pose` of B in A (its `information`, its correspondences `pairs`) aliased? */
	bool aliased(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
				 const mrpt::math::TPose2D& pose, const Eigen::Matrix3d& information,
				 const std::vector<VectorPair>& pairs, double reach) const;

	/** The unit translation direction the information constrains least (in A's frame). */
	static Eigen::Vector2d weakDirection(const Eigen::Matrix3d& information);
	/** What either scan shows along `v` inside the slab along `v` that both cover with B at `pose` (the smaller):
	 * its vectors' lengths there, each times its normal's squared component along v. */
	static double covisibleLength(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
								  const mrpt::math::TPose2D& pose, const Eigen::Vector2d& v);

   private:
	/** What the correspondences `pairs` explain along v of what both scans show along v at `pose` (<= 1). */
	double share(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
				 const mrpt::math::TPose2D& pose, const std::vector<VectorPair>& pairs, const Eigen::Vector2d& v) const;

	const VectorMatcher& matcher_;
	double ambiguity_;
};

}  // namespace gridvector
