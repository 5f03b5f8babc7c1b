#include "mstep/LoopSearch.h"
#include "mstep/AliasSweep.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace gridvector
{
using Eigen::Vector2d;
using mrpt::math::TPose2D;

namespace
{
constexpr double kDeg = M_PI / 180.0;
/** Corners only from static vectors this long [m]: shorter ones give directions too noisy to turn by. */
constexpr double kCornerMinLength = 0.3;
/** A corner's two vectors differ in direction by at least this [deg] (else their lines meet ill-defined). */
constexpr double kCornerMinAngleDeg = 30.0;
/** ... and their lines meet within this of both segments [m] (a corner of the place, not of two far walls). */
constexpr double kCornerMaxGap = 1.0;
/** Two scans' corners pair into a hypothesis when their turns agree within this [deg] (extraction noise). */
constexpr double kCornerTurnToleranceDeg = 10.0;
/** Hypotheses closer than this [m] and turned less than kDuplicateDeg are one (the matcher refines both alike). */
constexpr double kDuplicateDistance = 0.1;
constexpr double kDuplicateDeg = 2.0;
/** Hypotheses are ranked by the length matched under the final matcher gates widened by this (they are not refined
 * yet). */
constexpr double kScoreGateFactor = 2.0;
/** Refined solutions further apart than AliasSweep::kDistinctDistance or turned more than this [deg] are distinct
 * places (aliasing). */
constexpr double kDistinctDeg = 5.0;
inline double wrap(double a) { return mrpt::math::wrapToPi(a); }

// Indices of the `n` longest segments at least `minLength` long.
std::vector<size_t> longest(const std::vector<MatchSegment>& s, size_t n, double minLength)
{
	std::vector<size_t> idx;
	for (size_t k = 0; k < s.size(); ++k)
		if (s[k].length >= minLength) idx.push_back(k);
	std::sort(idx.begin(), idx.end(),
			  [&](size_t a, size_t b) { return s[a].length > s[b].length || (s[a].length == s[b].length && a < b); });
	if (idx.size() > n) idx.resize(n);
	return idx;
}

// Distance from p to the segment [s, e].
double toSegment(const Vector2d& p, const Vector2d& s, const Vector2d& e)
{
	const Vector2d d = e - s;
	const double t = std::clamp((p - s).dot(d) / std::max(1e-12, d.squaredNorm()), 0.0, 1.0);
	return (s + t * d - p).norm();
}
}  // namespace

LoopSearch::LoopSearch(const MatcherOptions& matcher, const MStepOptions& opts) : matcher_(matcher), opts_(opts) {}

// Corners: two long vectors at least kCornerMinAngleDeg apart whose lines meet near both.
std::vector<LoopSearch::Corner> LoopSearch::corners(const std::vector<MatchSegment>& s) const
{
	const auto idx = longest(s, size_t(std::max(2, opts_.loopSearchVectors)), kCornerMinLength);
	std::vector<Corner> out;
	for (size_t i = 0; i < idx.size(); ++i)
		for (size_t j = 0; j < idx.size(); ++j)
		{
			if (i == j) continue;
			const MatchSegment &u = s[idx[i]], &v = s[idx[j]];
			const Vector2d du = (u.e - u.s).normalized(), dv = (v.e - v.s).normalized();
			const double cross = du.x() * dv.y() - du.y() * dv.x();
			if (std::abs(cross) < std::sin(kCornerMinAngleDeg * kDeg)) continue;
			// u.s + a du = v.s + b dv
			const Vector2d w = v.s - u.s;
			const double a = (w.x() * dv.y() - w.y() * dv.x()) / cross;
			const Vector2d p = u.s + a * du;
			if (toSegment(p, u.s, u.e) > kCornerMaxGap || toSegment(p, v.s, v.e) > kCornerMaxGap) continue;
			Corner c;
			c.p = p;
			c.psi1 = std::atan2(du.y(), du.x());
			c.psi2 = std::atan2(dv.y(), dv.x());
			c.turn = wrap(c.psi2 - c.psi1);
			out.push_back(c);
		}
	return out;
}

// Beyond the paper (Sec. 5.1: "loop detection" is not specified): corner pairs inside the window.
std::vector<TPose2D> LoopSearch::hypotheses(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
											const TPose2D& prior, const LoopWindow& w) const
{
	struct Scored
	{
		TPose2D pose;
		double score = 0;
	};
	std::vector<Scored> cand{{prior, 0}};
	const auto ca = corners(a), cb = corners(b);
	const double turnTol = kCornerTurnToleranceDeg * kDeg;
	for (const Corner& A : ca)
		for (const Corner& B : cb)
		{
			if (std::abs(wrap(A.turn - B.turn)) > turnTol) continue;
			const double phi = wrap(A.psi1 - B.psi1);
			if (std::abs(wrap(phi - prior.phi)) > w.rotation) continue;
			const double c = std::cos(phi), s = std::sin(phi);
			const Vector2d t = A.p - Vector2d(c * B.p.x() - s * B.p.y(), s * B.p.x() + c * B.p.y());
			if (std::hypot(t.x() - prior.x, t.y() - prior.y) > w.translation) continue;
			bool dup = false;
			for (const Scored& h : cand)
				if (std::hypot(h.pose.x - t.x(), h.pose.y - t.y()) < kDuplicateDistance &&
					std::abs(wrap(h.pose.phi - phi)) < kDuplicateDeg * kDeg)
				{
					dup = true;
					break;
				}
			if (!dup) cand.push_back({TPose2D(t.x(), t.y(), phi), 0});
		}
	const MatchGates gates = matcher_.finalGates(kScoreGateFactor);
	for (Scored& h : cand) h.score = matcher_.correspondences(a, b, h.pose, gates, nullptr);
	std::stable_sort(cand.begin(), cand.end(), [](const Scored& x, const Scored& y) { return x.score > y.score; });
	std::vector<TPose2D> out;
	for (const Scored& h : cand)
	{
		if (int(out.size()) >= std::max(1, opts_.loopSearchHypotheses)) break;
		out.push_back(h.pose);
	}
	return out;
}

// Refined solutions of the hypotheses: accepted by the matcher and inside the window.
std::vector<MatchResult> LoopSearch::solutions(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
											   const TPose2D& prior, const LoopWindow& w) const
{
	std::vector<MatchResult> out;
	for (const TPose2D& h : hypotheses(a, b, prior, w))
	{
		MatchResult r = matcher_.match(a, b, h);
		if (!r.ok()) continue;
		const TPose2D& p = r.pose;
		if (std::hypot(p.x - prior.x, p.y - prior.y) > w.translation || std::abs(wrap(p.phi - prior.phi)) > w.rotation)
			continue;
		out.push_back(std::move(r));
	}
	return out;
}

// Aliasing (repeated doors, corridors): a distinct solution that matches almost
// as much as `best` makes the place ambiguous.
bool LoopSearch::ambiguous(const MatchResult& best, const std::vector<MatchResult>& others) const
{
	for (const MatchResult& r : others)
		if ((std::hypot(r.pose.x - best.pose.x, r.pose.y - best.pose.y) > AliasSweep::kDistinctDistance ||
			 std::abs(wrap(r.pose.phi - best.pose.phi)) > kDistinctDeg * kDeg) &&
			r.matchedLength >= opts_.loopSearchAmbiguity * best.matchedLength)
			return true;
	return false;
}

// Beyond the paper: the hypotheses refined by the matcher (Sec. 4.2), kept if unambiguous and non-degenerate.
MatchResult LoopSearch::search(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
							   const TPose2D& prior, const LoopWindow& w) const
{
	const std::vector<MatchResult> results = solutions(a, b, prior, w);
	MatchResult best;
	for (const MatchResult& r : results)
		if (!best.ok() || r.matchedLength > best.matchedLength) best = r;
	// a loop edge must match enough, fix the translation in both directions (no
	// corridor slide) and be unambiguous, also along its weakest direction (AliasSweep)
	if (best.ok() && (best.matchedShare < opts_.loopSearchMinShare ||
					  best.translationDegeneracy < matcher_.options().degenerateRatio || ambiguous(best, results) ||
					  AliasSweep(matcher_, opts_.loopSearchAmbiguity)
						  .aliased(a, b, best.pose, best.information, best.pairs, w.translation)))
		best.status = MatchStatus::TooFewMatches;
	return best;
}

}  // namespace gridvector
