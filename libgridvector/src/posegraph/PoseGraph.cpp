#include "posegraph/NormalEquations.h"
#include "posegraph/PoseGraph.h"
#include "posegraph/SparseCholesky.h"

#include <mrpt/math/wrap2pi.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPosePDFGaussianInf.h>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace gridvector
{
namespace
{
constexpr double kGraduationPercentile = 95.0;  // a start fits when 19 of 20 registrations fit (a few outliers may not)
constexpr int kGraduationIterations =
	8;  // LM steps per graduation stage before the last: each stage only follows the kernel
constexpr double kGraduationTolerance = 1e-3;  // relative cost change ending a stage before the last
constexpr double kTolerance = 1e-6;  // relative cost change ending the last stage and each re-optimisation
constexpr double kLmInitialLambda = 1e-4;  // LM damping at each stage's start: nearly Gauss-Newton from a good start
constexpr double kLmMinLambda = 1e-9;  // Nielsen's update never damps below this: a floor far under any H diagonal
constexpr double kLmMaxLambda = 1e8;  // a stage gives up once rejected steps raised the damping this far (steps ~0)
}  // namespace

using Eigen::Matrix3d;
using Eigen::Vector3d;
using mrpt::math::TPose2D;

const char* toString(EdgeKind k)
{
	switch (k)
	{
		case EdgeKind::Odometry:
			return "odometry";
		case EdgeKind::Sequential:
			return "sequential";
		case EdgeKind::Overlap:
			return "overlap";
		case EdgeKind::Loop:
			return "loop";
	}
	return "?";
}

PoseGraph::PoseGraph(const PoseGraphOptions& opts) : opts_(opts) {}

size_t PoseGraph::addEdge(const PoseEdge& e)
{
	edges_.push_back(e);
	return edges_.size() - 1;
}

// Eq. 21: e = z^-1 (+) (x_i^-1 (+) x_j).
Vector3d PoseGraph::error(const TPose2D& xi, const TPose2D& xj, const TPose2D& z)
{
	const double ci = std::cos(xi.phi), si = std::sin(xi.phi);
	const double dx = xj.x - xi.x, dy = xj.y - xi.y;
	const double lx = ci * dx + si * dy, ly = -si * dx + ci * dy;  // R_i^T (t_j - t_i)
	const double cz = std::cos(z.phi), sz = std::sin(z.phi);
	const double ex = lx - z.x, ey = ly - z.y;
	return {cz * ex + sz * ey, -sz * ex + cz * ey, mrpt::math::wrapToPi(xj.phi - xi.phi - z.phi)};
}

// e = z^-1 (+) (z (+) d) for d = (R_z e_t, e_phi): the perturbation of z is D e, D = diag(R_z, 1).
Matrix3d PoseGraph::errorFrameInformation(const Matrix3d& information, const TPose2D& z)
{
	Matrix3d D = Matrix3d::Identity();
	D.topLeftCorner<2, 2>() << std::cos(z.phi), -std::sin(z.phi), std::sin(z.phi), std::cos(z.phi);
	return D.transpose() * information * D;
}

// Eq. 20-21: Sigma^-1 of an odometry (u_t) edge from the motion model (posegraph.odometry_sigma_*).
Matrix3d PoseGraph::odometryInformation(const TPose2D& d, const PoseGraphOptions& o)
{
	const double dist = std::hypot(d.x, d.y);
	const double st = std::max(o.odometrySigmaXYMin, o.odometrySigmaXYPerM * dist);
	const double sr = o.odometrySigmaPhi + o.odometrySigmaPhiPerM * dist;
	Matrix3d I = Matrix3d::Zero();
	I(0, 0) = I(1, 1) = 1.0 / (st * st);
	I(2, 2) = 1.0 / (sr * sr);
	return I;
}

namespace
{
// Upper tail probability of the chi2 distribution with k = 1, 2, 3 degrees of freedom.
double chi2Tail(double x, int k)
{
	if (x <= 0) return 1;
	if (k == 1) return std::erfc(std::sqrt(x / 2));
	if (k == 2) return std::exp(-x / 2);
	return std::erfc(std::sqrt(x / 2)) + std::sqrt(2 * x / M_PI) * std::exp(-x / 2);
}
}  // namespace

double PoseGraph::levelForDof(double level3, int dof)
{
	if (dof >= 3 || dof < 1 || !(level3 > 0)) return level3;
	const double p = chi2Tail(level3, 3);
	if (dof == 2) return p > 0 ? -2 * std::log(p) : level3;
	double lo = 0, hi = level3;  // fewer dof: a lower level at the same tail (bisection)
	for (int it = 0; it < 100; ++it)
	{
		const double mid = 0.5 * (lo + hi);
		(chi2Tail(mid, dof) > p ? lo : hi) = mid;
	}
	return 0.5 * (lo + hi);
}

// A level for 3 dof moved to 1 and 2 dof, indexed by an edge's dof (clamped to 1..3).
std::array<double, 4> PoseGraph::levelsByDof(double level3)
{
	return {level3, levelForDof(level3, 1), levelForDof(level3, 2), level3};
}

// Chi2 of every edge at x; DCS scale s = min(1, 2 Phi / (Phi + chi2)) for registrations
// (Phi moved to the edge's degrees of freedom).
double PoseGraph::updateResiduals(const std::vector<TPose2D>& x, bool robust)
{
	double total = 0;
	const auto phiByDof = levelsByDof(phi_);
	for (auto& e : edges_)
	{
		if (!e.active) continue;
		const Vector3d r = error(x[e.from], x[e.to], e.z);
		e.chi2 = r.dot(e.information * r);
		e.scale = 1;
		const double phi = phiByDof[std::clamp(e.dof, 1, 3)];
		if (robust && e.kind != EdgeKind::Odometry && phi > 0) e.scale = std::min(1.0, 2 * phi / (phi + e.chi2));
		total += e.scale * e.scale * e.chi2;
	}
	return total;
}

double PoseGraph::fixedScaleCost(const std::vector<TPose2D>& x) const
{
	double total = 0;
	for (const auto& e : edges_)
		if (e.active)
		{
			const Vector3d r = error(x[e.from], x[e.to], e.z);
			total += e.scale * e.scale * r.dot(e.information * r);
		}
	return total;
}

size_t PoseGraph::rejectOutliers()
{
	size_t n = 0;
	const auto levelByDof = levelsByDof(opts_.rejectChi2);
	for (auto& e : edges_)
		if (e.active && e.kind != EdgeKind::Odometry && e.chi2 > levelByDof[std::clamp(e.dof, 1, 3)])
			e.active = false, ++n;
	return n;
}

// Eq. 22 (robust kernel and chi2 rejection beyond the paper) by Levenberg-Marquardt, in place of Eq. 23.
OptimizeStats PoseGraph::optimize(bool graduate)
{
	const auto t0 = std::chrono::steady_clock::now();
	phi_ = opts_.robustKernelWidth;
	OptimizeStats st = optimizeGaussNewton(graduate);
	// Iterative edge rejection by chi2, then re-optimisation from the robust solution.
	for (int round = 0; round < opts_.rejectRounds; ++round)
	{
		updateResiduals(nodes_, false);
		const size_t rej = rejectOutliers();
		if (!rej) break;
		st.rejected += rej;
		phi_ = opts_.robustKernelWidth;
		const OptimizeStats again = levenbergMarquardt(opts_.maxIterations, kTolerance);
		st.iterations += again.iterations;
		st.finalError = again.finalError;
	}
	updateResiduals(nodes_, true);
	st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	return st;
}

// Sparse Levenberg-Marquardt on Eq. 22 with x_0 fixed; H assembled from 3x3 blocks.
// Graduated robustness: the DCS width Phi shrinks from wide (almost least squares)
// to robust_kernel_width, so a poor start does not switch off correct edges.
OptimizeStats PoseGraph::optimizeGaussNewton(bool graduate)
{
	OptimizeStats st;
	bool first = true;
	const double target = opts_.robustKernelWidth;
	const double trigger = opts_.graduationTrigger * target;
	// a start where (nearly) every registration already fits needs no graduation
	std::vector<double> chi;
	updateResiduals(nodes_, false);
	bool anyFarLoop = false;  // a loop-search edge that needs a large correction
	for (const auto& e : edges_)
		if (e.active && e.kind != EdgeKind::Odometry)
		{
			chi.push_back(e.chi2);
			anyFarLoop = anyFarLoop || (e.kind == EdgeKind::Loop && farLoop(e.chi2, opts_));
		}
	double pct = 0;  // the chi2 at graduation_percentile
	if (!chi.empty())
	{
		auto k = chi.begin() + long(double(chi.size()) * kGraduationPercentile / 100);
		k = std::min(k, chi.end() - 1);
		std::nth_element(chi.begin(), k, chi.end());
		pct = *k;
	}
	const double phi0 = pct < trigger && !anyFarLoop && !graduate ? target : std::max(target, opts_.graduationStartPhi);
	for (double phi = phi0;; phi = std::max(target, phi * opts_.graduationFactor))
	{
		phi_ = phi;
		const bool last = phi <= target;
		const OptimizeStats s = levenbergMarquardt(last ? opts_.maxIterations : kGraduationIterations,
												   last ? kTolerance : kGraduationTolerance);
		if (first) st.initialError = s.initialError, first = false;
		st.iterations += s.iterations;
		st.finalError = s.finalError;
		if (last) break;
	}
	return st;
}

namespace
{
// H = sum J^T W J, b = sum J^T W r over the active edges at x (J = [A B] = de/d(x_i, x_j)).
void linearise(const std::vector<TPose2D>& x, const std::vector<const PoseEdge*>& active, NormalEquations& eq)
{
	eq.clear();
	for (size_t k = 0; k < active.size(); ++k)
	{
		const PoseEdge& e = *active[k];
		const TPose2D &xi = x[e.from], &xj = x[e.to];
		const Vector3d r = PoseGraph::error(xi, xj, e.z);
		const double ci = std::cos(xi.phi), si = std::sin(xi.phi);
		const double cz = std::cos(e.z.phi), sz = std::sin(e.z.phi);
		Eigen::Matrix2d RzT, RiT, dRiT;
		RzT << cz, sz, -sz, cz;
		RiT << ci, si, -si, ci;
		dRiT << -si, ci, -ci, -si;
		const Eigen::Vector2d dt(xj.x - xi.x, xj.y - xi.y);
		Matrix3d A = Matrix3d::Zero(), B = Matrix3d::Zero();
		A.topLeftCorner<2, 2>() = -RzT * RiT;
		A.topRightCorner<2, 1>() = RzT * dRiT * dt;
		A(2, 2) = -1;
		B.topLeftCorner<2, 2>() = RzT * RiT;
		B(2, 2) = 1;
		eq.add(k, A, B, e.scale * e.scale * e.information, r);
	}
}
}  // namespace

// Eq. 22 by sparse Levenberg-Marquardt (in place of Eq. 23's stochastic gradient descent).
OptimizeStats PoseGraph::levenbergMarquardt(int maxIterations, double minRelativeDecrease)
{
	OptimizeStats st;
	const size_t n = nodes_.size();
	if (n < 2) return st;
	auto col = [](uint32_t node) { return int(node) * 3 - 3; };  // node 0 is fixed
	std::vector<std::pair<uint32_t, uint32_t>> pairs;  // H's pattern: fixed while the active edges are
	std::vector<const PoseEdge*> active;
	for (const auto& e : edges_)
		if (e.active && e.from != e.to) pairs.emplace_back(e.from, e.to), active.push_back(&e);
	NormalEquations eq(n, pairs);
	SparseCholesky solver;
	solver.analyze(eq.H());
	double lambda = kLmInitialLambda, nu = 2;
	double err = updateResiduals(nodes_, true);
	st.initialError = err;
	bool linearised = false;  // H and b are at nodes_ (a rejected step changes only lambda)
	for (int it = 0; it < maxIterations; ++it)
	{
		if (!linearised) linearise(nodes_, active, eq), linearised = true;
		if (!solver.factorize(eq.H(), lambda))
		{
			lambda *= 10;
			continue;
		}
		const Eigen::VectorXd dx = solver.solve(-eq.b());
		std::vector<TPose2D> cand = nodes_;
		for (size_t i = 1; i < n; ++i)
		{
			cand[i].x += dx(col(uint32_t(i)));
			cand[i].y += dx(col(uint32_t(i)) + 1);
			cand[i].phi = mrpt::math::wrapToPi(cand[i].phi + dx(col(uint32_t(i)) + 2));
		}
		// IRLS: a step is judged on the cost it was solved for, at the scales of the linearisation point: it
		// majorises the DCS objective (sum of rho(chi2), rho' = scale^2, concave), which an accepted step lowers;
		// sum scale^2 chi2 with the scales moved to the candidate is not monotone in chi2: pulling a down-weighted
		// edge in raises it, and a stage spent its iterations refusing such steps
		const double cerr = fixedScaleCost(cand);
		++st.iterations;
		// Nielsen's damping update: gain ratio rho = actual / predicted decrease
		if (cerr <= err)
		{
			const double rel = (err - cerr) / std::max(1e-12, err);
			const double predicted = dx.dot(lambda * dx - eq.b());  // r^T W r minus the linear model's
			const double rho = predicted > 0 ? (err - cerr) / predicted : 1;
			lambda = std::max(kLmMinLambda, lambda * std::max(1.0 / 3, 1 - std::pow(2 * rho - 1, 3)));
			nu = 2;
			nodes_.swap(cand);
			err = updateResiduals(nodes_, true);  // the scales at the new estimate
			linearised = false;
			if (rel < minRelativeDecrease || dx.cwiseAbs().maxCoeff() < 1e-7) break;
		}
		else
		{
			// converged as for an accepted step: the cost changes by less than the tolerance
			if ((cerr - err) / std::max(1e-12, err) < minRelativeDecrease) break;
			lambda *= nu, nu *= 2;
			if (lambda > kLmMaxLambda) break;
		}
	}
	st.finalError = err;
	return st;
}

mrpt::graphs::CNetworkOfPoses2DInf PoseGraph::toMrpt(bool activeOnly) const
{
	mrpt::graphs::CNetworkOfPoses2DInf g;
	g.root = 0;
	for (size_t i = 0; i < nodes_.size(); ++i) g.nodes[i] = mrpt::poses::CPose2D(nodes_[i]);
	for (const auto& e : edges_)
	{
		if (activeOnly && !e.active) continue;
		mrpt::math::CMatrixDouble33 inf;
		for (int r = 0; r < 3; ++r)
			for (int c = 0; c < 3; ++c) inf(r, c) = e.information(r, c);
		g.insertEdge(e.from, e.to, mrpt::poses::CPosePDFGaussianInf(mrpt::poses::CPose2D(e.z), inf));
	}
	return g;
}

}  // namespace gridvector
