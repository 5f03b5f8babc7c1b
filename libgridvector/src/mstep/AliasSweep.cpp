#include "mstep/AliasSweep.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridvector
{
using Eigen::Vector2d;
using mrpt::math::TPose2D;

namespace
{
double clippedLength(double tp, double tq, double len, double lo, double hi)
{
	if (std::abs(tq - tp) < 1e-9) return (tp >= lo && tp <= hi) ? len : 0.0;
	const double a = std::max(std::min(tp, tq), lo), b = std::min(std::max(tp, tq), hi);
	return b > a ? len * (b - a) / std::abs(tq - tp) : 0.0;
}

/** The sweep samples the shifts a final criterion-2 gate apart and scores each under the final gates widened by
 * this: an alias lies within the widened gates of a sample, so its correspondences are found there. */
constexpr double kSampleGateFactor = 2.0;

struct Slab
{
	double lo = std::numeric_limits<double>::infinity(), hi = -std::numeric_limits<double>::infinity();
	void add(double t) { lo = std::min(lo, t), hi = std::max(hi, t); }
};

Vector2d inA(const Vector2d& p, const TPose2D& pose)
{
	const double c = std::cos(pose.phi), s = std::sin(pose.phi);
	return {pose.x + c * p.x() - s * p.y(), pose.y + s * p.x() + c * p.y()};
}

// What the part of segment [p, q] whose projection on v lies in [lo, hi] tells along v: its length times the
// squared component of its normal along v (a wall along v tells nothing there, a crosswise one all its length).
double clipped(const Vector2d& p, const Vector2d& q, const Vector2d& v, double lo, double hi)
{
	const double tp = p.dot(v), tq = q.dot(v), len = (q - p).norm();
	if (len < 1e-9) return 0.0;
	const double nv = ((q - p) / len).x() * v.y() - ((q - p) / len).y() * v.x();
	return nv * nv * clippedLength(tp, tq, len, lo, hi);
}
}  // namespace

Vector2d AliasSweep::weakDirection(const Eigen::Matrix3d& information)
{
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(information.topLeftCorner<2, 2>());
	return es.eigenvectors().col(0).normalized();
}

double AliasSweep::covisibleLength(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
								   const TPose2D& pose, const Vector2d& v)
{
	Slab sa, sb;
	for (const auto& s : a) sa.add(s.s.dot(v)), sa.add(s.e.dot(v));
	for (const auto& s : b) sb.add(inA(s.s, pose).dot(v)), sb.add(inA(s.e, pose).dot(v));
	const double lo = std::max(sa.lo, sb.lo), hi = std::min(sa.hi, sb.hi);
	if (!(hi > lo)) return 0.0;
	double la = 0, lb = 0;
	for (const auto& s : a) la += clipped(s.s, s.e, v, lo, hi);
	for (const auto& s : b) lb += clipped(inA(s.s, pose), inA(s.e, pose), v, lo, hi);
	return std::min(la, lb);
}

// Matched along v: each correspondence's shorter vector weighted as clipped() weighs it; over the covisible part.
double AliasSweep::share(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b, const TPose2D& pose,
						 const std::vector<VectorPair>& pairs, const Vector2d& v) const
{
	const double co = covisibleLength(a, b, pose, v);
	if (!(co > 0)) return 0.0;
	const auto byId = [](const std::vector<MatchSegment>& s, uint64_t id) {
		const auto it = std::find_if(s.begin(), s.end(), [&](const MatchSegment& m) { return m.id == id; });
		return it == s.end() ? nullptr : &*it;
	};
	double matched = 0;
	for (const VectorPair& p : pairs)
	{
		const MatchSegment *sa = byId(a, p.a), *sb = byId(b, p.b);
		if (!sa || !sb || sa->length < 1e-9) continue;
		const Vector2d d = (sa->e - sa->s) / sa->length;
		const double nv = d.x() * v.y() - d.y() * v.x();
		matched += nv * nv * std::min(sa->length, sb->length);
	}
	return std::min(1.0, matched / co);
}

// Local maxima of the covisible share along the weak direction, refined by the matcher, against the registration's.
bool AliasSweep::aliased(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b, const TPose2D& pose,
						 const Eigen::Matrix3d& information, const std::vector<VectorPair>& pairs, double reach) const
{
	if (reach <= kDistinctDistance) return false;
	const Vector2d v = weakDirection(information);
	const double own = share(a, b, pose, pairs, v);
	const MatchGates gates = matcher_.finalGates(kSampleGateFactor);
	const double step = matcher_.options().gateRhoFinal;
	const int n = int(std::floor(reach / step));
	const auto at = [&](double s) { return TPose2D(pose.x + s * v.x(), pose.y + s * v.y(), pose.phi); };
	std::vector<double> sh(size_t(2 * n + 1));
	std::vector<VectorPair> found;
	for (int k = -n; k <= n; ++k)
	{
		const TPose2D q = at(k * step);
		matcher_.correspondences(a, b, q, gates, &found);
		sh[size_t(k + n)] = share(a, b, q, found, v);
	}
	for (int k = -n; k <= n; ++k)
	{
		const double s = k * step, here = sh[size_t(k + n)];
		if (std::abs(s) < kDistinctDistance || here < ambiguity_ * own) continue;
		if ((k > -n && sh[size_t(k + n - 1)] > here) || (k < n && sh[size_t(k + n + 1)] >= here)) continue;
		const MatchResult alt = matcher_.match(a, b, at(s));
		const Vector2d d(alt.pose.x - pose.x, alt.pose.y - pose.y);
		if (alt.ok() && d.norm() >= kDistinctDistance && d.norm() <= reach &&
			share(a, b, alt.pose, alt.pairs, v) >= ambiguity_ * own)
			return true;
	}
	return false;
}

}  // namespace gridvector
