// Sec. 4.2 (issue 5): loop search — registration hypotheses from vector corners within a
// window that grows with the pose uncertainty, for places the current estimate misplaces.
#pragma once

#include <gridvector/GridVectorConfig.h>
#include "mstep/VectorMatcher.h"

#include <mrpt/math/TPose2D.h>

#include <vector>

namespace gridvector
{
/** The search window around the prior relative pose (half-widths). */
struct LoopWindow
{
	double translation = 1.0;  //!< [m]
	double rotation = 0.5;  //!< [rad]
};

/** Registers two scans whose relative pose is only known within a window.
 *
 * Hypotheses: every pair of non-parallel static vectors (a corner) of A matched
 * with a pair of B whose directions turn by the same angle gives a rotation
 * (directions of the directed vectors) and a translation (the lines'
 * intersections); those inside the window are ranked by the matched length of
 * their correspondences (Sec. 3.2 criteria), the best few refined by the
 * VectorMatcher, and the refined result with the most matched length kept
 * unless another distinct one matches almost as much (aliasing). */
class LoopSearch
{
   public:
	LoopSearch(const MatcherOptions& matcher, const MStepOptions& opts);

	/** Candidate poses of B in A inside the window around `prior`, best first
	 * (the prior itself included), at most loop_search_hypotheses. */
	std::vector<mrpt::math::TPose2D> hypotheses(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
												const mrpt::math::TPose2D& prior, const LoopWindow& w) const;

	/** The best registration from the hypotheses: status Ok only if the matcher
	 * accepted it, it matches loop_search_min_share of the shorter scan, fixes the
	 * translation in both directions (degeneracy >= matcher.degenerate_ratio) and
	 * no distinct solution matches almost as much. */
	MatchResult search(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
					   const mrpt::math::TPose2D& prior, const LoopWindow& w) const;

   private:
	std::vector<MatchResult> solutions(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
									   const mrpt::math::TPose2D& prior, const LoopWindow& w) const;
	/** Does a distinct solution (kDistinctDistance / kDistinctDeg away) match at least
	 * loop_search_ambiguity of best's length? (aliasing: repeated doors, corridors) */
	bool ambiguous(const MatchResult& best, const std::vector<MatchResult>& others) const;
	struct Corner
	{
		Eigen::Vector2d p;  //!< intersection of the two lines
		double psi1 = 0, psi2 = 0;  //!< directions of the two vectors
		double turn = 0;  //!< psi2 - psi1, wrapped
	};
	std::vector<Corner> corners(const std::vector<MatchSegment>& s) const;

	VectorMatcher matcher_;
	MStepOptions opts_;
};

}  // namespace gridvector
