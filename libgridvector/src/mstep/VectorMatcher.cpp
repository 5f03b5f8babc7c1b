#include "mstep/VectorMatcher.h"

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace gridvector
{
using Eigen::Matrix3d;
using Eigen::Vector2d;
using Eigen::Vector3d;
using mrpt::math::TPose2D;

namespace
{
constexpr double kDeg = M_PI / 180.0;
constexpr int kMaxIterations =
	25;  // the gates reach their final values in 5 iterations; Gauss-Newton then converges in a few
constexpr double kGateShrink =
	0.7;  // the gates' factor per iteration: final (0.12 m, 6 deg) from initial (0.6 m, 20 deg) in 5
constexpr double kSigmaFloor =
	0.03;  // residual std. dev. floor [m]: a perfect fit must not claim more than the laser's noise (or its scans' sigma)
constexpr double kConvergenceTranslation = 1e-4;  // a step under 0.1 mm: far below the laser's noise [m]
constexpr double kConvergenceRotation = 1e-5;  // ... and under 0.0006 deg [rad]
constexpr double kRobustScaleGateShare =
	0.5;  // Cauchy scale = half the current line-offset gate: a pair at the gate weighs 1/5
inline double wrap(double a) { return mrpt::math::wrapToPi(a); }
inline Vector2d leftOf(const Vector2d& d) { return {-d.y(), d.x()}; }
}  // namespace

const char* toString(MatchStatus s)
{
	switch (s)
	{
		case MatchStatus::Ok:
			return "ok";
		case MatchStatus::TooFewMatches:
			return "too few matches";
		case MatchStatus::HighResidual:
			return "high residual";
		case MatchStatus::Degenerate:
			return "degenerate";
	}
	return "?";
}

MatchSegment MatchSegment::from(const GridVector& v, double sigma)
{
	MatchSegment m;
	m.s = {v.start().x, v.start().y};
	m.e = {v.end().x, v.end().y};
	m.length = v.length();
	m.id = v.id;
	m.sigma = sigma;
	return m;
}

std::vector<MatchSegment> MatchSegment::fromVectors(const std::vector<GridVector>& v, double sigma)
{
	std::vector<MatchSegment> out;
	out.reserve(v.size());
	for (const auto& g : v) out.push_back(from(g, sigma));
	return out;
}

VectorMatcher::VectorMatcher(const MatcherOptions& opts) : opts_(opts) {}

MatchGates VectorMatcher::finalGates(double factor) const
{
	MatchGates g;
	g.psi = opts_.gatePsiFinalDeg * kDeg * factor;
	g.rho = opts_.gateRhoFinal * factor;
	g.minOverlap = opts_.minOverlap;
	return g;
}

// Gates start wide and shrink geometrically to their final values.
MatchGates VectorMatcher::gatesAt(int iteration) const
{
	const double k = std::pow(kGateShrink, iteration);
	MatchGates g;
	g.psi = std::max(opts_.gatePsiFinalDeg, opts_.gatePsiInitialDeg * k) * kDeg;
	g.rho = std::max(opts_.gateRhoFinal, opts_.gateRhoInitial * k);
	g.minOverlap = opts_.minOverlap;
	return g;
}

void VectorMatcher::geometryOf(const MatchSegment& m, const TPose2D& T, Geom& g)
{
	const double c = std::cos(T.phi), s = std::sin(T.phi);
	const Vector2d t(T.x, T.y);
	g.s = Vector2d(c * m.s.x() - s * m.s.y(), s * m.s.x() + c * m.s.y()) + t;
	const Vector2d e = Vector2d(c * m.e.x() - s * m.e.y(), s * m.e.x() + c * m.e.y()) + t;
	const Vector2d d = e - g.s;
	g.len = d.norm();
	g.d = g.len > 1e-12 ? Vector2d(d / g.len) : Vector2d(1, 0);
	g.n = leftOf(g.d);
	g.c = 0.5 * (g.s + e);
}

void VectorMatcher::prepareA(const std::vector<MatchSegment>& a) const
{
	ga_.resize(a.size());
	for (size_t i = 0; i < a.size(); ++i) geometryOf(a[i], TPose2D(0, 0, 0), ga_[i]);
}

void VectorMatcher::transformB(const std::vector<MatchSegment>& b, const TPose2D& T) const
{
	gb_.resize(b.size());
	for (size_t i = 0; i < b.size(); ++i) geometryOf(b[i], T, gb_[i]);
}

// The three criteria of Sec. 3.2 plus a positive overlap along the line.
void VectorMatcher::gather(const MatchGates& g) const
{
	pairs_.clear();
	// criterion 1 on the unit directions: |psi_a - psi_b| < psi  <=>  d_a . d_b > cos(psi) (no atan2 per vector)
	const bool anyAngle = !(g.psi < M_PI);
	const double minCos = std::cos(g.psi);
	for (size_t ib = 0; ib < gb_.size(); ++ib)
	{
		const Geom& B = gb_[ib];
		if (B.len <= 1e-9) continue;
		for (size_t ia = 0; ia < ga_.size(); ++ia)
		{
			const Geom& A = ga_[ia];
			const double half = 0.5 * (A.len + B.len);
			if ((A.c - B.c).squaredNorm() >= half * half) continue;  // criterion 3
			if (!anyAngle && A.d.dot(B.d) <= minCos) continue;  // criterion 1
			if (std::abs(A.n.dot(B.c - A.s)) >= g.rho) continue;  // criterion 2 (rho at B)
			if (std::abs(B.n.dot(A.c - B.s)) >= g.rho) continue;  // criterion 2 (rho at A)
			const double u0 = A.d.dot(B.s - A.s), u1 = u0 + A.d.dot(B.d) * B.len;
			const double lo = std::max(std::min(u0, u1), 0.0), hi = std::min(std::max(u0, u1), A.len);
			if (hi - lo < g.minOverlap || std::abs(u1 - u0) < 1e-9) continue;
			Pair p;
			p.ia = int(ia);
			p.ib = int(ib);
			p.s0 = (lo - u0) / (u1 - u0);
			p.s1 = (hi - u0) / (u1 - u0);
			if (p.s0 > p.s1) std::swap(p.s0, p.s1);
			p.overlap = hi - lo;
			pairs_.push_back(p);
		}
	}
}

// Rotation from the overlap- and robust-weighted angle differences.
double VectorMatcher::rotationStep() const
{
	double sw = 0, sa = 0;
	for (const Pair& p : pairs_)
	{
		const double w = p.overlap * p.weight;
		sw += w;
		const Eigen::Vector2d &da = ga_[size_t(p.ia)].d, &db = gb_[size_t(p.ib)].d;
		sa += w * std::atan2(db.x() * da.y() - db.y() * da.x(), db.dot(da));  // psi_a - psi_b
	}
	return sw > 0 ? sa / sw : 0.0;
}

// J^T W J and J^T W r of the point-to-line residuals r = n_a . (R q + t) - n_a . s_a,
// integrated along each clipped segment with Simpson's rule (exact: r^2 is quadratic).
void VectorMatcher::normalEquations(const std::vector<MatchSegment>& b, const TPose2D& T, double robustScale,
									Matrix3d& H, Vector3d& g, double& sumW, double& sumWr2) const
{
	H.setZero();
	g.setZero();
	sumW = sumWr2 = 0;
	const double c = std::cos(T.phi), s = std::sin(T.phi);
	const double inv2 = 1.0 / (robustScale * robustScale);
	static constexpr double kSimpson[3] = {1.0 / 6, 4.0 / 6, 1.0 / 6};
	for (Pair& p : pairs_)
	{
		const Geom& A = ga_[size_t(p.ia)];
		const MatchSegment& mb = b[size_t(p.ib)];
		const double d0 = A.n.dot(A.s);
		const double ss[3] = {p.s0, 0.5 * (p.s0 + p.s1), p.s1};
		double pairW = 0, pairR2 = 0;
		for (int k = 0; k < 3; ++k)
		{
			const Vector2d q = mb.s + ss[k] * (mb.e - mb.s);
			const Vector2d Rq(c * q.x() - s * q.y(), s * q.x() + c * q.y());
			const double r = A.n.dot(Rq + Vector2d(T.x, T.y)) - d0;
			const Vector3d J(A.n.x(), A.n.y(), A.n.dot(Vector2d(-Rq.y(), Rq.x())));
			const double w = p.overlap * kSimpson[k] / (1.0 + r * r * inv2);  // Cauchy
			H.noalias() += w * J * J.transpose();
			g.noalias() += w * r * J;
			pairW += w;
			pairR2 += w * r * r;
		}
		p.weight = p.overlap > 0 ? pairW / p.overlap : 0;
		sumW += pairW;
		sumWr2 += pairR2;
	}
}

// The rotation step of the weighted angle differences applied to T about the matched centroid.
void VectorMatcher::rotateAboutMatchedCentre(TPose2D& T) const
{
	const double dphi = rotationStep();
	Vector2d cen(0, 0);
	double sw = 0;
	for (const Pair& p : pairs_) cen += p.overlap * gb_[size_t(p.ib)].c, sw += p.overlap;
	cen /= sw;
	const double cd = std::cos(dphi), sd = std::sin(dphi);
	const Vector2d t0 = Vector2d(T.x, T.y) - cen;
	T.x = cen.x() + cd * t0.x() - sd * t0.y();
	T.y = cen.y() + sd * t0.x() + cd * t0.y();
	T.phi = wrap(T.phi + dphi);
}

// Sec. 3.2's criteria at a fixed pose: an edge's M_cor (Eq. 25) and Sec. 4.3's overlap test.
double VectorMatcher::correspondences(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
									  const TPose2D& pose, const MatchGates& gates, std::vector<VectorPair>* out) const
{
	prepareA(a);
	transformB(b, pose);
	gather(gates);
	double len = 0;
	if (out) out->clear();
	for (const Pair& p : pairs_)
	{
		len += p.overlap;
		if (out) out->push_back({a[size_t(p.ia)].id, b[size_t(p.ib)].id});
	}
	if (out) std::sort(out->begin(), out->end());
	return len;
}

// The share of a Gauss-Newton step (dx, dy, dphi) that stays within the gates its correspondences were gathered in.
double VectorMatcher::stepScale(const Vector3d& delta, const MatchGates& gates)
{
	const double t = delta.head<2>().norm(), r = std::abs(delta.z());
	double k = 1.0;
	if (t > gates.rho) k = gates.rho / t;
	if (r > gates.psi) k = std::min(k, gates.psi / r);
	return k;
}

// Sec. 4.2: the registration of scan b against scan a by vector matching (Sohn & Kim 2008).
MatchResult VectorMatcher::match(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
								 const TPose2D& guess) const
{
	MatchResult res;
	TPose2D T = guess;
	prepareA(a);
	const MatchGates fin = finalGates();
	double floor = kSigmaFloor;  // the laser's noise: at least the noisier scan's range std. dev.
	for (const auto* scan : {&a, &b})
		for (const auto& s : *scan) floor = std::max(floor, s.sigma);
	Matrix3d H;
	Vector3d g;
	double sumW = 0, sumWr2 = 0;
	int it = 0;
	for (; it < kMaxIterations; ++it)
	{
		const MatchGates gates = gatesAt(it);
		transformB(b, T);
		gather(gates);
		if (int(pairs_.size()) < opts_.minMatches) break;
		for (Pair& p : pairs_) p.weight = 1.0;
		const bool tight = gates.rho <= fin.rho + 1e-12 && gates.psi <= fin.psi + 1e-12;
		// rotation from the weighted angle differences while the gates are wide (it brings the rotation into the
		// basin); at the final gates from the Gauss-Newton step alone: short vectors' angles (a wall pieced
		// into short vectors, far walls) are noisy and biased, and a step from them pulls the fit off its optimum
		if (!tight) rotateAboutMatchedCentre(T);
		// joint Gauss-Newton step on point-to-line distances (translation and rotation)
		normalEquations(b, T, std::max(floor, kRobustScaleGateShare * gates.rho), H, g, sumW, sumWr2);
		const double damp = 1e-6 * std::max(1e-12, H.trace());
		Vector3d delta = -(H + damp * Matrix3d::Identity()).ldlt().solve(g);
		if (!delta.allFinite()) break;
		if (opts_.stepWithinGates) delta *= stepScale(delta, gates);  // where its correspondences were gathered
		T.x += delta.x();
		T.y += delta.y();
		T.phi = wrap(T.phi + delta.z());
		if (tight && delta.head<2>().norm() < kConvergenceTranslation &&
			std::abs(delta.z()) < kConvergenceRotation)
		{
			++it;
			break;
		}
	}
	res.iterations = it;
	res.pose = T;
	// final correspondences, Hessian and residual statistics at the solution
	transformB(b, T);
	gather(fin);
	for (Pair& p : pairs_) p.weight = 1.0;
	normalEquations(b, T, floor, H, g, sumW, sumWr2);
	double totalA = 0, totalB = 0;
	for (const auto& s : a) totalA += s.length;
	for (const auto& s : b) totalB += s.length;
	for (const Pair& p : pairs_)
	{
		res.matchedLength += p.overlap;
		res.pairs.push_back({a[size_t(p.ia)].id, b[size_t(p.ib)].id});
	}
	std::sort(res.pairs.begin(), res.pairs.end());
	res.matchedShare = std::min(1.0, res.matchedLength / std::max(1e-9, std::min(totalA, totalB)));
	res.rms = sumW > 0 ? std::sqrt(sumWr2 / sumW) : 0;
	const double var = std::max(floor * floor, res.rms * res.rms);
	res.information = H / var;
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> es(H.topLeftCorner<2, 2>());
	const double lmax = es.eigenvalues()(1);
	res.translationDegeneracy = lmax > 0 ? std::max(0.0, es.eigenvalues()(0)) / lmax : 0;
	// A weakly constrained translation direction (a corridor's axis, a few short
	// crosswise lines) is where wrong associations slide: its information falls
	// off quadratically below degenerate_ratio of the strongest direction.
	const double eps = opts_.degenerateRatio;
	if (eps > 0 && res.translationDegeneracy < eps && lmax > 0)
	{
		const double k = std::sqrt(res.translationDegeneracy / eps);  // information x k^2
		const Eigen::Vector2d v = es.eigenvectors().col(0);
		Matrix3d S = Matrix3d::Identity();
		S.topLeftCorner<2, 2>() += (k - 1) * v * v.transpose();
		res.information = S * res.information * S;
	}
	if (int(res.pairs.size()) < opts_.minMatches || res.matchedLength < opts_.minMatchedLength)
		res.status = MatchStatus::TooFewMatches;
	else if (H(2, 2) <= 1e-9 || lmax <= 1e-9)
		res.status = MatchStatus::Degenerate;
	else if (res.rms > opts_.maxRms)
		res.status = MatchStatus::HighResidual;
	else
		res.status = MatchStatus::Ok;
	return res;
}

}  // namespace gridvector
