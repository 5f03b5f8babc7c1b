// PoseGraph (Eq. 21-22): exact solutions, outlier robustness, both optimisers agree.
#include "posegraph/PoseGraph.h"

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace gridvector;
using mrpt::math::TPose2D;

namespace
{
TPose2D relative(const TPose2D& a, const TPose2D& b)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	const double dx = b.x - a.x, dy = b.y - a.y;
	return {c * dx + s * dy, -s * dx + c * dy, mrpt::math::wrapToPi(b.phi - a.phi)};
}

// A square loop of 40 poses; noisy odometry, exact loop-closure edges every 10 poses.
std::vector<TPose2D> squareLoop()
{
	std::vector<TPose2D> p;
	for (int side = 0; side < 4; ++side)
		for (int k = 0; k < 10; ++k)
		{
			const double a = side * M_PI / 2, d = k * 0.5;
			const double cx[4] = {0, 5, 5, 0}, cy[4] = {0, 0, 5, 5};
			p.emplace_back(cx[side] + d * std::cos(a), cy[side] + d * std::sin(a), a);
		}
	return p;
}

PoseGraph buildGraph(const std::vector<TPose2D>& truth, PoseGraphOptions o, unsigned seed)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> n(0, 1);
	PoseGraph g(o);
	std::vector<TPose2D> odo{truth[0]};
	for (size_t i = 1; i < truth.size(); ++i)
	{
		TPose2D z = relative(truth[i - 1], truth[i]);
		z.x += 0.03 * n(rng), z.y += 0.03 * n(rng), z.phi += 0.03 + 0.01 * n(rng);  // biased
		const TPose2D& prev = odo.back();
		const double c = std::cos(prev.phi), s = std::sin(prev.phi);
		odo.emplace_back(prev.x + c * z.x - s * z.y, prev.y + s * z.x + c * z.y, prev.phi + z.phi);
		PoseEdge e;
		e.from = uint32_t(i - 1), e.to = uint32_t(i), e.z = z;
		e.information = PoseGraph::odometryInformation(z, o);
		g.addEdge(e);
	}
	for (size_t i = 10; i < truth.size(); i += 3)
		for (size_t j : {size_t(0), i - 10})
		{
			PoseEdge e;
			e.from = uint32_t(j), e.to = uint32_t(i), e.z = relative(truth[j], truth[i]);
			e.kind = EdgeKind::Overlap;
			e.information = Eigen::Vector3d(1e4, 1e4, 1e5).asDiagonal();
			g.addEdge(e);
		}
	g.setNodes(odo);
	return g;
}

double maxError(const std::vector<TPose2D>& a, const std::vector<TPose2D>& b)
{
	double m = 0;
	for (size_t i = 0; i < a.size(); ++i) m = std::max(m, std::hypot(a[i].x - b[i].x, a[i].y - b[i].y));
	return m;
}
}  // namespace

TEST(PoseGraph, ErrorIsZeroForConsistentEdge)
{
	const TPose2D a(1, 2, 0.5), b(-3, 4, 2.9);
	EXPECT_LT(PoseGraph::error(a, b, relative(a, b)).norm(), 1e-12);
	const Eigen::Vector3d e = PoseGraph::error(a, b, TPose2D(0, 0, 0));
	EXPECT_NEAR(e.z(), mrpt::math::wrapToPi(2.4), 1e-12);
}

TEST(PoseGraph, LoopClosuresRemoveOdometryDrift)
{
	const auto truth = squareLoop();
	PoseGraph g = buildGraph(truth, {}, 3);
	EXPECT_GT(maxError(g.nodes(), truth), 1.0);
	const OptimizeStats st = g.optimize();
	EXPECT_LT(st.finalError, st.initialError);
	EXPECT_LT(maxError(g.nodes(), truth), 0.1);
	EXPECT_EQ(st.rejected, 0u);
}

namespace
{
// the square loop with three confident, wrong loop closures
PoseGraph graphWithWrongLoops(const PoseGraphOptions& o)
{
	PoseGraph g = buildGraph(squareLoop(), o, 4);
	for (auto [i, j] : {std::pair{5, 25}, std::pair{12, 33}, std::pair{2, 38}})
	{
		PoseEdge e;
		e.from = uint32_t(i), e.to = uint32_t(j), e.kind = EdgeKind::Loop;
		e.z = TPose2D(0.5, -0.3, 0.4);
		e.information = Eigen::Vector3d(1e4, 1e4, 1e5).asDiagonal();
		g.addEdge(e);
	}
	return g;
}
}  // namespace

TEST(PoseGraph, WrongEdgesAreDownweightedAndRejected)
{
	const auto truth = squareLoop();
	PoseGraph g = graphWithWrongLoops({});
	PoseGraph clean = buildGraph(truth, {}, 4);
	clean.optimize();
	const OptimizeStats st = g.optimize();
	EXPECT_LT(maxError(g.nodes(), clean.nodes()), 0.1);
	EXPECT_LT(maxError(g.nodes(), truth), 0.15);
	EXPECT_GE(st.rejected, 3u);
	for (const auto& e : g.edges()) EXPECT_TRUE(e.kind != EdgeKind::Loop || !e.active) << e.from << "-" << e.to;
}

// The graph as MRPT's CNetworkOfPoses2DInf (what the graphslam deciders hand to MRPT's optimiser).
TEST(PoseGraph, ConvertsToMrptsNetworkOfPoses)
{
	const auto truth = squareLoop();
	PoseGraph own = buildGraph(truth, PoseGraphOptions{}, 5);
	own.optimize();
	const auto net = own.toMrpt();
	EXPECT_EQ(net.nodes.size(), truth.size());
	EXPECT_EQ(net.edges.size(), own.edges().size());
}

TEST(PoseGraph, OdometryInformationGrowsWeakerWithDistance)
{
	const PoseGraphOptions o;
	const auto near = PoseGraph::odometryInformation(TPose2D(0.1, 0, 0), o);
	const auto far = PoseGraph::odometryInformation(TPose2D(2.0, 0, 0), o);
	EXPECT_GT(near(0, 0), far(0, 0));
	EXPECT_GT(near(2, 2), far(2, 2));
}

TEST(PoseGraph, RejectRoundsBoundTheChi2Rejection)
{
	EXPECT_EQ(PoseGraphOptions().rejectRounds, 3);  // the value before it became a key
	PoseGraphOptions o;
	o.rejectRounds = 0;
	PoseGraph none = graphWithWrongLoops(o);
	EXPECT_EQ(none.optimize().rejected, 0u);
	for (const auto& e : none.edges()) EXPECT_TRUE(e.active);
	PoseGraph dflt = graphWithWrongLoops({});
	EXPECT_GE(dflt.optimize().rejected, 3u);
}

namespace
{
struct Outcome
{
	int iterations = 0;
	double offClean = 0;  //!< largest position difference from the clean graph's solution [m]
};

// graphWithWrongLoops without rejection (the robust kernel and its graduation alone), optionally
// started from the clean solution with the wrong edges as overlap edges
Outcome optimiseWrongLoops(PoseGraphOptions o, bool fromClean = false)
{
	o.rejectRounds = 0;
	PoseGraph clean = buildGraph(squareLoop(), {}, 4);
	clean.optimize();
	PoseGraph g = graphWithWrongLoops(o);
	if (fromClean)
	{
		g.setNodes(clean.nodes());
		for (auto& e : g.edges())
			if (e.kind == EdgeKind::Loop) e.kind = EdgeKind::Overlap;
	}
	const OptimizeStats st = g.optimize();
	return {st.iterations, maxError(g.nodes(), clean.nodes())};
}
}  // namespace

TEST(PoseGraph, GraduationFromAWideKernelLetsTheCorrectEdgesOutvoteWrongOnes)
{
	const PoseGraphOptions d;
	EXPECT_EQ(d.graduationTrigger, 10.0);  // the values before they became keys
	EXPECT_EQ(d.graduationStartPhi, 1e4);
	EXPECT_EQ(d.graduationFactor, 0.01);
	const Outcome dflt = optimiseWrongLoops(d);
	EXPECT_LT(dflt.offClean, 0.1);
	PoseGraphOptions o;
	o.graduationTrigger = 1e12;  // never graduate: the wrong loops hold the odometry's drift
	EXPECT_GT(optimiseWrongLoops(o).offClean, 1.0);
	o = {}, o.graduationStartPhi = d.robustKernelWidth;  // the same from the start value
	EXPECT_GT(optimiseWrongLoops(o).offClean, 1.0);
	o = {}, o.graduationFactor = 0.5;  // more, gentler stages
	const Outcome gentle = optimiseWrongLoops(o);
	EXPECT_LT(gentle.offClean, 1e-3);
	EXPECT_NE(gentle.iterations, dflt.iterations);
}

TEST(PoseGraph, AStartWhereRegistrationsDoNotFitIsGraduated)
{
	// from the clean solution three of the 21 registration edges (14 %, more than the 5 % above the
	// 95th percentile) are far off: the start does not fit and is graduated
	PoseGraphOptions never;
	never.graduationTrigger = 1e12;
	EXPECT_NE(optimiseWrongLoops({}, true).iterations, optimiseWrongLoops(never, true).iterations);
	// the clean graph from its own solution fits: not graduated, as with graduation switched off
	auto fromSolution = [](const PoseGraphOptions& o) {
		PoseGraph g = buildGraph(squareLoop(), o, 4);
		g.optimize();
		std::vector<TPose2D> x = g.nodes();
		for (auto& p : x) p.x += 0.02;  // a small offset: the registrations still fit
		g.setNodes(x);
		return g.optimize().iterations;
	};
	EXPECT_EQ(fromSolution({}), fromSolution(never));
}

// optimize(true) graduates whatever the start's fit (OnlineEmSlam::finish: edges that join places the
// start misplaces, but are not loop-search edges): from near the clean solution it graduates, optimize() not.
TEST(PoseGraph, GraduateStartsWideWhateverTheFit)
{
	auto fromSolution = [](const PoseGraphOptions& o, bool graduate) {
		PoseGraph g = buildGraph(squareLoop(), o, 4);
		g.optimize();
		std::vector<TPose2D> x = g.nodes();
		for (auto& p : x) p.x += 0.02;
		g.setNodes(x);
		return g.optimize(graduate).iterations;
	};
	PoseGraphOptions never;
	never.graduationTrigger = 1e12;
	EXPECT_EQ(fromSolution({}, false), fromSolution(never, false));
	EXPECT_NE(fromSolution({}, true), fromSolution({}, false));
	EXPECT_EQ(fromSolution({}, true), fromSolution(never, true));  // the trigger plays no part
}

// The graph's chi2 of a registration edge must be the matcher's quadratic form: the matcher's
// information is over z = (x, y, phi) in the earlier pose's frame, error() puts the translation
// in z's frame. Exact for any perturbation d of z: e = z^-1 (+) (z + d) = (R_z^T d_t, d_phi).
TEST(PoseGraph, ErrorFrameInformationIsTheMatchersQuadraticForm)
{
	std::mt19937 rng(3);
	std::normal_distribution<double> n(0, 1);
	for (int trial = 0; trial < 20; ++trial)
	{
		Eigen::Matrix3d L = Eigen::Matrix3d::Random();
		const Eigen::Matrix3d info = L * L.transpose() + 0.1 * Eigen::Matrix3d::Identity();
		const TPose2D xi(n(rng), n(rng), 3 * n(rng));
		const TPose2D z(5 * n(rng), 5 * n(rng), mrpt::math::wrapToPi(3 * n(rng)));
		const Eigen::Vector3d d(0.3 * n(rng), 0.3 * n(rng), 0.05 * n(rng));
		const TPose2D zd(z.x + d.x(), z.y + d.y(), z.phi + d.z());
		const double c = std::cos(xi.phi), s = std::sin(xi.phi);
		const TPose2D xj(xi.x + c * zd.x - s * zd.y, xi.y + s * zd.x + c * zd.y, xi.phi + zd.phi);
		const Eigen::Vector3d e = PoseGraph::error(xi, xj, z);
		const double want = d.dot(info * d);
		EXPECT_NEAR(e.dot(PoseGraph::errorFrameInformation(info, z) * e), want, 1e-9 * (1 + want));
		// unrotated, the form is wrong as soon as z turns (here: the rotation/translation coupling)
		if (std::abs(z.phi) > 1.0 && std::abs(info(0, 2)) + std::abs(info(1, 2)) > 0.1)
		{
			EXPECT_GT(std::abs(e.dot(info * e) - want), 1e-6 * (1 + want));
		}
	}
}

// A rank-2 edge (corridor registration, along-corridor marginalised out) is judged with 2
// degrees of freedom: the kernel width and reject_chi2 move to the same tail probability.
TEST(PoseGraph, LevelForDofKeepsTheTailProbability)
{
	EXPECT_DOUBLE_EQ(PoseGraph::levelForDof(50.0, 3), 50.0);
	EXPECT_NEAR(PoseGraph::levelForDof(7.8147, 2), 5.9915, 1e-3);  // 95 % quantiles
	EXPECT_NEAR(PoseGraph::levelForDof(7.8147, 1), 3.8415, 1e-3);
	EXPECT_NEAR(PoseGraph::levelForDof(11.3449, 2), 9.2103, 1e-3);  // 99 %
	EXPECT_NEAR(PoseGraph::levelForDof(11.3449, 1), 6.6349, 1e-3);
	// an edge with chi2 between the 2- and 3-dof levels: rejected only when it has 2 dof
	for (int dof : {2, 3})
	{
		PoseGraphOptions o;
		o.rejectChi2 = 11.3449;
		o.rejectRounds = 1;
		PoseGraph g(o);
		g.setNodes({TPose2D(0, 0, 0), TPose2D(1, 0, 0)});
		PoseEdge odo;
		odo.from = 0, odo.to = 1, odo.z = TPose2D(1, 0, 0);
		odo.information = Eigen::Vector3d(1e6, 1e6, 1e6).asDiagonal();
		g.addEdge(odo);
		PoseEdge reg = odo;
		reg.kind = EdgeKind::Overlap;
		reg.z = TPose2D(1, 0.1, 0);
		reg.information = Eigen::Vector3d(0, 1000, 0).asDiagonal();  // chi2 10 at the odometry's pose
		reg.dof = dof;
		g.addEdge(reg);
		g.optimize();
		EXPECT_EQ(g.edges()[1].active, dof == 3) << dof;
	}
}

namespace
{
/** Largest |d/dx| over the free poses' coordinates of sum scale^2 chi2 with every edge's scale as the graph left it
 * (central differences). */
double fixedScaleGradient(const PoseGraph& g)
{
	auto cost = [&](const std::vector<TPose2D>& x) {
		double c = 0;
		for (const auto& e : g.edges())
			if (e.active)
			{
				const Eigen::Vector3d r = PoseGraph::error(x[e.from], x[e.to], e.z);
				c += e.scale * e.scale * r.dot(e.information * r);
			}
		return c;
	};
	double worst = 0;
	const double h = 1e-6;
	for (size_t i = 1; i < g.nodes().size(); ++i)
		for (int k = 0; k < 3; ++k)
		{
			std::vector<TPose2D> a = g.nodes(), b = g.nodes();
			double* pa[3] = {&a[i].x, &a[i].y, &a[i].phi};
			double* pb[3] = {&b[i].x, &b[i].y, &b[i].phi};
			*pa[k] += h, *pb[k] -= h;
			worst = std::max(worst, std::abs(cost(a) - cost(b)) / (2 * h));
		}
	return worst;
}
}  // namespace

// IRLS: each Levenberg-Marquardt step is judged on the cost it was solved for, sum scale^2 chi2 at the DCS
// scales of its linearisation point (a majoriser of the DCS objective, so an accepted step lowers that too).
// The robust solution is a stationary point of the weighted least squares at its own scales, and a graduated
// restart from it returns to it.
TEST(PoseGraph, TheRobustSolutionIsStationaryAtItsOwnScales)
{
	PoseGraphOptions o;
	o.rejectRounds = 0;  // the wrong loops stay, down-weighted
	PoseGraph g = graphWithWrongLoops(o);
	g.optimize();
	EXPECT_LT(fixedScaleGradient(g), 1e-2);
	const std::vector<TPose2D> robust = g.nodes();
	g.optimize(true);
	EXPECT_LT(maxError(g.nodes(), robust), 1e-3);
	PoseGraph clean = buildGraph(squareLoop(), {}, 4);
	clean.optimize();
	EXPECT_LT(maxError(robust, clean.nodes()), 0.1);  // the wrong loops barely pull
}
