// The self-check (issue 21, item 3): the pose graph's fit, the map's beams through its own walls, the verdict.
#include "em/SelfCheck.h"

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>
#include <random>

using namespace gridvector;
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

namespace
{
// A circle of 60 poses; every edge (chain and chords) is its true relative pose plus noise of sigma, its
// information 1 / sigma^2: at the optimum chi2 per redundant dimension is about 1.
PoseGraph noisyCircle(double sigma, unsigned seed, double loopBias = 0)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> n(0, sigma);
	std::vector<TPose2D> truth;
	for (int i = 0; i < 60; ++i)
	{
		const double a = 2 * M_PI * i / 60;
		truth.emplace_back(10 * std::cos(a), 10 * std::sin(a), a + M_PI / 2);
	}
	PoseGraphOptions o;
	o.rejectRounds = 0;
	PoseGraph g(o);
	g.setNodes(truth);
	auto add = [&](size_t i, size_t j, EdgeKind kind, double bias) {
		PoseEdge e;
		e.from = uint32_t(i), e.to = uint32_t(j), e.kind = kind;
		e.z = truth[j] - truth[i];
		e.z.x += n(rng) + bias, e.z.y += n(rng), e.z.phi += n(rng);
		e.information = Eigen::Matrix3d::Identity() / (sigma * sigma);
		g.addEdge(e);
	};
	for (size_t i = 1; i < truth.size(); ++i) add(i - 1, i, EdgeKind::Odometry, 0);
	for (size_t i = 0; i + 5 < truth.size(); i += 2) add(i, i + 5, EdgeKind::Overlap, loopBias);
	return g;
}

// The walls of a 10 x 10 m room, open side (left of each vector) inside, each seen along its length (Algorithm 1:
// its cells occupied).
std::vector<GridVector> room()
{
	const GridOptions grid;
	std::vector<GridVector> walls{GridVector({0, 0}, {10, 0}, grid), GridVector({10, 0}, {10, 10}, grid),
								  GridVector({10, 10}, {0, 10}, grid), GridVector({0, 10}, {0, 0}, grid)};
	for (GridVector& w : walls)
		for (double u = 0.01; u < w.length(); u += 0.02)
			w.addEndpoint(TPoint2D(w.start().x + u * w.direction().x, w.start().y + u * w.direction().y));
	return walls;
}

// A scan from (x, y) of the room: 90 beams ending on its walls, in the robot frame (robot at `pose`).
ScanBeams roomScan(double x, double y, const TPose2D& pose)
{
	ScanBeams s;
	s.pose = pose;
	for (int k = 0; k < 90; ++k)
	{
		const double a = 2 * M_PI * (k + 0.5) / 90, c = std::cos(a), si = std::sin(a);
		double r = 1e9;  // the nearest wall along the beam
		if (c > 1e-9) r = std::min(r, (10 - x) / c);
		if (c < -1e-9) r = std::min(r, -x / c);
		if (si > 1e-9) r = std::min(r, (10 - y) / si);
		if (si < -1e-9) r = std::min(r, -y / si);
		const TPoint2D w(x + r * c, y + r * si);  // the world end; into the robot frame
		const double dx = w.x - pose.x, dy = w.y - pose.y, cp = std::cos(pose.phi), sp = std::sin(pose.phi);
		s.ends.emplace_back(cp * dx + sp * dy, -sp * dx + cp * dy);
	}
	return s;
}
}  // namespace

TEST(PoseGraphFit, ConsistentGraphHasNormalisedChi2NearOne)
{
	PoseGraph g = noisyCircle(0.02, 1);
	g.optimize();
	const PoseGraphFit f = poseGraphFit(g);
	EXPECT_EQ(f.nodes, 60u);
	EXPECT_EQ(f.odometryEdges, 59u);
	EXPECT_EQ(f.registrationEdges, 28u);
	EXPECT_EQ(f.odometryDof, 3 * 59.0);
	EXPECT_EQ(f.registrationDof, 3 * 28.0);
	EXPECT_LE(f.downweighted, 3u);  // chi2 > 3 Phi = 9 happens to ~3 % of good 3-dof edges
	EXPECT_GT(f.normalisedChi2(), 0.6);
	EXPECT_LT(f.normalisedChi2(), 1.5);
}

TEST(PoseGraphFit, BiasedEdgesRaiseChi2AndAreDownweighted)
{
	PoseGraph g = noisyCircle(0.02, 2, 0.5);  // every chord 0.5 m (25 sigma) off
	g.optimize();
	const PoseGraphFit f = poseGraphFit(g);
	EXPECT_GT(f.normalisedChi2(), kMaxNormalisedChi2);
	EXPECT_GT(f.downweighted, 0u);
}

TEST(PoseGraphFit, NoRedundancyIsNaN)
{
	PoseGraph g;
	g.setNodes({TPose2D(0, 0, 0), TPose2D(1, 0, 0)});
	PoseEdge e;
	e.from = 0, e.to = 1, e.z = TPose2D(1, 0, 0);
	g.addEdge(e);
	g.optimize();
	EXPECT_TRUE(std::isnan(poseGraphFit(g).normalisedChi2()));
}

TEST(BeamConsistency, ConsistentScansStopAtTheWalls)
{
	const auto map = room();
	const BeamConsistency b =
		beamConsistency(map, {roomScan(5, 5, TPose2D(5, 5, 0.3)), roomScan(2, 7, TPose2D(2, 7, -1))});
	EXPECT_EQ(b.beams, 180u);
	EXPECT_EQ(b.throughWalls, 0u);
	EXPECT_EQ(b.throughOccupied, 0u);
	EXPECT_EQ(b.share(), 0.0);
}

TEST(BeamConsistency, MisplacedScanSeesThroughWalls)
{
	const auto map = room();
	ScanBeams s = roomScan(5, 5, TPose2D(5, 5, 0));
	s.pose = TPose2D(6, 5, 0);  // placed 1 m off: its beams to the right end 1 m behind the wall x = 10
	const BeamConsistency b = beamConsistency(map, {s});
	EXPECT_GT(b.throughWalls, 10u);
	EXPECT_LT(b.throughWalls, 60u);  // the others end inside the room
	EXPECT_EQ(b.throughOccupied, b.throughWalls);
	EXPECT_DOUBLE_EQ(b.share(), double(b.throughWalls) / 90);
}

TEST(BeamConsistency, AWallWhoseCellsAreFreeIsNoEvidence)
{
	auto map = room();
	for (GridCell& c : map[1].cells()) c.n_occupy = 0.1f * c.n_visit;  // x = 10 seen through: free
	ScanBeams s;
	s.pose = TPose2D(5, 5, 0);
	s.ends = {TPoint2D(6, 0)};  // 1 m behind x = 10
	const BeamConsistency b = beamConsistency(map, {s});
	EXPECT_EQ(b.throughWalls, 1u);
	EXPECT_EQ(b.throughOccupied, 0u);
	EXPECT_EQ(b.share(), 0.0);
	EXPECT_EQ(b.geometricShare(), 1.0);
}

TEST(BeamConsistency, EndpointsJustBehindTheWallAreNoise)
{
	const auto map = room();
	ScanBeams s;
	s.pose = TPose2D(5, 5, 0);
	s.ends = {TPoint2D(5 + 0.5 * kThroughWall, 0), TPoint2D(5 + 2 * kThroughWall, 0),  // 0.5x and 2x behind x = 10
			  TPoint2D(0, 5 + 0.1), TPoint2D(4.9, 0)};  // 0.1 m behind y = 10; inside
	const BeamConsistency b = beamConsistency(map, {s});
	EXPECT_EQ(b.beams, 4u);
	EXPECT_EQ(b.throughWalls, 1u);
	EXPECT_EQ(b.throughOccupied, 1u);
}

TEST(BeamConsistency, SensorOffsetCounts)
{
	const auto map = room();
	ScanBeams s;
	s.pose = TPose2D(9.5, 5, 0);
	s.origin = TPoint2D(1, 0);  // the sensor itself is behind the wall x = 10: a beam back into the room crosses it
	s.ends = {TPoint2D(-1, 0)};
	EXPECT_EQ(beamConsistency(map, {s}).throughOccupied, 1u);
}

TEST(SelfCheckEvidence, SumsTheMStepsAndCountsTheFinalEdges)
{
	MStepReport a, b;
	a.registrations = 100, a.failedRegistrations = 10;
	b.registrations = 20, b.failedRegistrations = 2;
	b.constraints = 50, b.active = 45;
	PoseGraphFit fit;
	fit.downweighted = 5;
	BeamConsistency beams;
	b.sequential = 40;
	beams.beams = 1000, beams.throughWalls = 9, beams.throughOccupied = 7;
	const GridOptions grid;
	std::vector<GridVector> map{GridVector({0, 0}, {3, 0}, grid), GridVector({0, 1}, {1, 1}, grid)};
	map[0].state = VectorState::Static, map[1].state = VectorState::Dynamic;
	const SelfCheckEvidence e = selfCheckEvidence(true, {a, b}, 51, fit, beams, map);
	EXPECT_EQ(e.iterations, 2u);
	EXPECT_EQ(e.registrations, 120u);
	EXPECT_EQ(e.failedRegistrations, 12u);
	EXPECT_DOUBLE_EQ(e.failedShare(), 0.1);
	EXPECT_EQ(e.edges, 50u);
	EXPECT_EQ(e.rejectedEdges, 10u);
	EXPECT_DOUBLE_EQ(e.rejectedShare(), 0.2);
	EXPECT_DOUBLE_EQ(e.beams.share(), 0.007);
	EXPECT_EQ(e.keyframes, 51u);
	EXPECT_EQ(e.sequentialEdges, 40u);
	EXPECT_DOUBLE_EQ(e.unlinkedShare(), 0.2);
	EXPECT_DOUBLE_EQ(e.dynamicShare(), 0.25);
}

namespace
{
SelfCheckEvidence goodRun()
{
	SelfCheckEvidence e;
	e.converged = true;
	e.iterations = 4;
	e.registrations = 1000, e.failedRegistrations = 500;  // candidate pairs that do not overlap fail
	e.edges = 500, e.rejectedEdges = 3;
	e.graph.nodes = 101, e.graph.odometryDof = 300, e.graph.registrationDof = 900;
	e.graph.odometryChi2 = 100, e.graph.registrationChi2 = 170;  // 270 / 900: conservative informations
	e.keyframes = 200, e.sequentialEdges = 250;
	e.beams.beams = 10000, e.beams.throughWalls = 900, e.beams.throughOccupied = 800;  // 8 %: glass, clutter
	e.staticLength = 700, e.dynamicLength = 300;
	return e;
}
}  // namespace

TEST(SelfCheckVerdict, GoodRunIsOk)
{
	const SelfCheckVerdict v = judge(goodRun());
	EXPECT_TRUE(v.ok);
	EXPECT_TRUE(v.reasons.empty());
}

TEST(SelfCheckVerdict, EachSignalAloneMakesARunSuspect)
{
	auto expectSuspect = [](const SelfCheckEvidence& e, const std::string& what) {
		const SelfCheckVerdict v = judge(e);
		EXPECT_FALSE(v.ok) << what;
		ASSERT_EQ(v.reasons.size(), 1u) << what;
		EXPECT_NE(v.reasons[0].find(what), std::string::npos) << v.reasons[0];
	};
	SelfCheckEvidence e = goodRun();
	e.graph.registrationChi2 = 900 * (kMaxNormalisedChi2 + 0.1);
	expectSuspect(e, "normalised chi2");
	e = goodRun();
	e.rejectedEdges = size_t((kMaxRejectedShare + 0.01) * double(e.edges));
	expectSuspect(e, "rejected edges");
	e = goodRun();
	e.sequentialEdges = size_t((1 - kMaxUnlinkedShare - 0.01) * double(e.keyframes - 1));
	expectSuspect(e, "keyframes without a sequential edge");
	e = goodRun();
	e.converged = false;
	e.failedRegistrations = size_t((kMaxFailedShareUnconverged + 0.01) * double(e.registrations));
	expectSuspect(e, "EM did not converge and failed registrations");
	e = goodRun();
	e.converged = false;
	e.dynamicLength = e.staticLength * (kMaxDynamicShareUnconverged + 0.01) / (1 - kMaxDynamicShareUnconverged - 0.01);
	expectSuspect(e, "EM did not converge and dynamic share of the map");
}

TEST(SelfCheckVerdict, FailuresOrDynamicMapsOfAConvergedRunAndBeamsAreNoReason)
{
	SelfCheckEvidence e = goodRun();
	e.failedRegistrations = size_t(0.9 * double(e.registrations));  // converged: the failures were candidates
	EXPECT_TRUE(judge(e).ok);
	e.converged = false;  // --max-iterations reached with few failures: not evidence of a broken run either
	e.failedRegistrations = size_t(0.5 * double(e.registrations));
	EXPECT_TRUE(judge(e).ok);
	e = goodRun();
	e.beams.throughOccupied = e.beams.beams / 4;  // reported only
	EXPECT_TRUE(judge(e).ok);
	e = goodRun();
	e.dynamicLength = 3 * e.staticLength;  // converged: a busy world
	EXPECT_TRUE(judge(e).ok);
}

TEST(SelfCheckVerdict, AllReasonsAreListed)
{
	SelfCheckEvidence e = goodRun();
	e.converged = false;
	e.failedRegistrations = e.registrations;
	e.rejectedEdges = e.edges;
	e.graph.registrationChi2 = 1e9;
	e.sequentialEdges = 0;
	e.dynamicLength = 1e6;
	const SelfCheckVerdict v = judge(e);
	EXPECT_FALSE(v.ok);
	EXPECT_EQ(v.reasons.size(), 5u);  // the two unconverged tests are one each
}
