// CGridVectorMap as the reference map of MRPT's ICP: determineMatching2D's pairs,
// gate, decimation and ratios on a known map; CICP aligning scans against a map
// built from other scans; dynamic vectors (a door state, a person) left out.
#include <gridvector/GridVector.h>
#include <mrpt/math/TPose2D.h>
#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include "map/GlobalMap.h"
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPosePDFGaussian.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/slam/CICP.h>

#include <cmath>
#include <random>
#include <tuple>

#include "corridor_map.h"
#include "test_scans.h"

using gridvector::GridOptions;
using gridvector::GridVector;
using mrpt::maps::CGridVectorMap;
using mrpt::maps::CSimplePointsMap;
using mrpt::maps::TMatchingExtraResults;
using mrpt::maps::TMatchingParams;
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;
using mrpt::poses::CPose2D;
using mrpt::tfest::TMatchingPairList;

namespace
{
/** A map holding exactly these vectors (prior grids: every column reads static). */
CGridVectorMap mapOf(const std::vector<GridVector>& vs, const gridvector::GridVectorConfig& cfg = {})
{
	CGridVectorMap m(cfg);
	m.globalMap().setVectors(vs);
	return m;
}

GridVector wall(double x1, double y1, double x2, double y2) { return GridVector({x1, y1}, {x2, y2}, GridOptions{}); }

/** Columns [c0, c1) of v seen through `times` times after one hit: profile 1 / (1 + times). */
void seenThrough(GridVector& v, int c0, int c1, int times)
{
	for (int c = c0; c < c1; ++c)
		for (int r = 0; r < v.rows(); ++r) v.cell(r, c).n_occupy = 1, v.cell(r, c).n_visit = float(1 + times);
}

CSimplePointsMap pointsOf(const std::vector<TPoint2D>& ps)
{
	CSimplePointsMap m;
	for (const auto& p : ps) m.insertPoint(float(p.x), float(p.y), 0);
	return m;
}

/** Local coordinates of world point w seen from pose x. */
TPoint2D localOf(const TPose2D& x, const TPoint2D& w)
{
	const double c = std::cos(x.phi), s = std::sin(x.phi), dx = w.x - x.x, dy = w.y - x.y;
	return {c * dx + s * dy, -s * dx + c * dy};
}

TMatchingParams gate(double d)
{
	TMatchingParams p;
	p.maxDistForCorrespondence = float(d);
	p.maxAngularDistForCorrespondence = 0;
	return p;
}
}  // namespace

TEST(GridVectorMapMatching, PairsAreThePlacesOnTheVectorWithinTheGate)
{
	const CGridVectorMap map = mapOf({wall(0, 0, 4, 0)});
	const TPose2D pose(1, 0.5, M_PI / 2);
	// world points: above the wall, beyond its end (1 m), before its start (0.36 m), 0.45 m above it
	const std::vector<TPoint2D> world{{2.02, 0.1}, {5, 0}, {-0.3, 0.2}, {3.03, 0.45}};
	std::vector<TPoint2D> local;
	for (const auto& w : world) local.push_back(localOf(pose, w));
	const CSimplePointsMap pts = pointsOf(local);
	TMatchingPairList pairs;
	TMatchingExtraResults extra;
	map.determineMatching2D(&pts, CPose2D(pose), pairs, gate(0.5), extra);
	ASSERT_EQ(pairs.size(), 3u);
	// each point's place on the line: the nearest of the places half a cell apart (0.025, 0.075, ...)
	const TPoint2D feet[] = {{2.025, 0}, {0.025, 0}, {3.025, 0}};
	const size_t idx[] = {0, 2, 3};
	for (size_t k = 0; k < 3; ++k)
	{
		EXPECT_EQ(pairs[k].globalIdx, 0u);
		EXPECT_EQ(pairs[k].localIdx, idx[k]);
		EXPECT_NEAR(pairs[k].global.x, feet[k].x, 1e-5);
		EXPECT_NEAR(pairs[k].global.y, feet[k].y, 1e-5);
		EXPECT_NEAR(pairs[k].local.x, local[idx[k]].x, 1e-5);  // the other map's own frame
		EXPECT_NEAR(pairs[k].local.y, local[idx[k]].y, 1e-5);
		const double d2 = std::pow(world[idx[k]].x - feet[k].x, 2) + std::pow(world[idx[k]].y - feet[k].y, 2);
		EXPECT_NEAR(pairs[k].errorSquareAfterTransformation, d2, 1e-5);
	}
	EXPECT_FLOAT_EQ(extra.correspondencesRatio, 0.75f);
	EXPECT_NEAR(extra.sumSqrDist, 0.010025 + 0.145625 + 0.202525, 1e-5);
}

TEST(GridVectorMapMatching, GateGrowsWithTheDistanceFromThePivot)
{
	const CGridVectorMap map = mapOf({wall(0, 0, 4, 0)});
	const CSimplePointsMap pts = pointsOf({{5, 0}});  // 1 m beyond the wall's end
	TMatchingPairList pairs;
	TMatchingExtraResults extra;
	TMatchingParams p = gate(0.5);
	p.maxAngularDistForCorrespondence = 0.1f;
	p.angularDistPivotPoint = {4.5, 0, 0};  // 0.5 m away: gate 0.55
	map.determineMatching2D(&pts, CPose2D(0, 0, 0), pairs, p, extra);
	EXPECT_TRUE(pairs.empty());
	p.angularDistPivotPoint = {-5, 0, 0};  // 10 m away: gate 1.5
	map.determineMatching2D(&pts, CPose2D(0, 0, 0), pairs, p, extra);
	ASSERT_EQ(pairs.size(), 1u);
	EXPECT_NEAR(pairs[0].global.x, 4, 1e-5);  // the last place, clamped to the vector's end
	EXPECT_FLOAT_EQ(extra.correspondencesRatio, 1.f);
}

TEST(GridVectorMapMatching, DecimationAndOffsetPickThePointsUsed)
{
	const CGridVectorMap map = mapOf({wall(0, 0, 4, 0)});
	// points 0..5 along the wall at 0.1 m, except 3 and 5, 2 m away
	const CSimplePointsMap pts = pointsOf({{0.5, 0.1}, {1, 0.1}, {1.5, 0.1}, {2, 2}, {2.5, 0.1}, {3, 2}});
	TMatchingPairList pairs;
	TMatchingExtraResults extra;
	TMatchingParams p = gate(0.5);
	p.decimation_other_map_points = 2;
	p.offset_other_map_points = 1;  // points 1, 3, 5
	map.determineMatching2D(&pts, CPose2D(0, 0, 0), pairs, p, extra);
	ASSERT_EQ(pairs.size(), 1u);
	EXPECT_EQ(pairs[0].localIdx, 1u);
	EXPECT_FLOAT_EQ(extra.correspondencesRatio, 1.f / 3.f);
	p.offset_other_map_points = 0;  // points 0, 2, 4
	map.determineMatching2D(&pts, CPose2D(0, 0, 0), pairs, p, extra);
	ASSERT_EQ(pairs.size(), 3u);
	EXPECT_EQ(pairs[2].localIdx, 4u);
	EXPECT_FLOAT_EQ(extra.correspondencesRatio, 1.f);
	p.offset_other_map_points = 2;
	EXPECT_THROW(map.determineMatching2D(&pts, CPose2D(0, 0, 0), pairs, p, extra), std::invalid_argument);
}

TEST(GridVectorMapMatching, AllCorrespondencesOrTheClosestOrOnePerMapPlace)
{
	// two parallel walls 0.3 m apart; a point between them, 0.1 m from the lower one
	const CGridVectorMap map = mapOf({wall(0, 0, 4, 0), wall(4, 0.3, 0, 0.3)});
	const CSimplePointsMap pts = pointsOf({{2.03, 0.1}, {2.04, 0.12}});
	TMatchingPairList pairs;
	TMatchingExtraResults extra;
	TMatchingParams p = gate(0.5);
	p.onlyKeepTheClosest = false;
	map.determineMatching2D(&pts, CPose2D(0, 0, 0), pairs, p, extra);
	EXPECT_EQ(pairs.size(), 4u);  // each point to both walls
	EXPECT_NEAR(extra.sumSqrDist, 0.010025 + 0.014625, 1e-5);  // the closest per point (the place at 2.025)
	p.onlyKeepTheClosest = true;
	map.determineMatching2D(&pts, CPose2D(0, 0, 0), pairs, p, extra);
	ASSERT_EQ(pairs.size(), 2u);
	EXPECT_EQ(pairs[0].globalIdx, 0u);
	EXPECT_EQ(pairs[1].globalIdx, 0u);
	p.onlyUniqueRobust = true;  // both feet in column 20 of the lower wall: the closer point stays
	map.determineMatching2D(&pts, CPose2D(0, 0, 0), pairs, p, extra);
	ASSERT_EQ(pairs.size(), 1u);
	EXPECT_EQ(pairs[0].localIdx, 0u);
	EXPECT_FLOAT_EQ(extra.correspondencesRatio, 1.f);
}

TEST(GridVectorMapMatching, DynamicVectorsAndSeenThroughColumnsGiveNoCorrespondence)
{
	GridVector door = wall(0, 1, 1, 1);
	door.state = gridvector::VectorState::Dynamic;  // Eq. 14: c = 0
	GridVector w = wall(0, 0, 4, 0);
	seenThrough(w, 0, 10, 9);  // its first metre reads 0.1
	gridvector::GridVectorConfig half;
	half.matching.staticThreshold = 0.5;
	const CGridVectorMap map = mapOf({w, door}, half);
	const CSimplePointsMap pts = pointsOf({{0.52, 1.05}, {0.52, 0.1}, {2.03, 0.1}});
	TMatchingPairList pairs;
	TMatchingExtraResults extra;
	map.determineMatching2D(&pts, CPose2D(0, 0, 0), pairs, gate(1.5), extra);
	ASSERT_EQ(pairs.size(), 3u);
	for (const auto& m : pairs) EXPECT_EQ(m.globalIdx, 0u);  // never the door
	EXPECT_NEAR(pairs[1].global.x, 1.025, 1e-5);  // the static stretch starts at 1 m: its first place
	EXPECT_NEAR(pairs[2].global.x, 2.025, 1e-5);
	// with static_threshold 0 (the default) the seen-through stretch takes part (the dynamic vector still not)
	const CGridVectorMap mapAll = mapOf({w, door});
	mapAll.determineMatching2D(&pts, CPose2D(0, 0, 0), pairs, gate(1.5), extra);
	ASSERT_EQ(pairs.size(), 3u);
	EXPECT_NEAR(pairs[1].global.x, 0.525, 1e-5);
}

TEST(GridVectorMapMatching, NearestDistanceAndMatchingRatio)
{
	const CGridVectorMap map = mapOf({wall(0, 0, 4, 0)});
	// to the nearest place (0.025, 0.075, ..., the ends clamped)
	EXPECT_NEAR(map.squareDistanceToClosestCorrespondence(2, 10), 100.000625, 1e-3);  // beyond every index query box
	EXPECT_NEAR(map.squareDistanceToClosestCorrespondence(7, 4), 25, 1e-3);
	EXPECT_NEAR(map.squareDistanceToClosestCorrespondence(1, -0.2f), 0.040625, 1e-6);
	const CSimplePointsMap pts = pointsOf({{1, 0.05}, {2, 0.3}, {3, -0.02}, {9, 0}});
	mrpt::maps::TMatchingRatioParams rp;
	rp.maxDistForCorr = 0.1f;
	EXPECT_FLOAT_EQ(map.compute3DMatchingRatio(&pts, mrpt::poses::CPose3D(), rp), 0.5f);
	EXPECT_FLOAT_EQ(map.compute3DMatchingRatio(&pts, mrpt::poses::CPose3D(0, -0.3, 0, 0, 0, 0), rp), 0.25f);
	EXPECT_EQ(mapOf({}).squareDistanceToClosestCorrespondence(0, 0), std::numeric_limits<float>::max());
}

TEST(GridVectorMapMatching, OtherMapMustBeAPointsMap)
{
	const CGridVectorMap map = mapOf({wall(0, 0, 4, 0)});
	TMatchingPairList pairs;
	TMatchingExtraResults extra;
	EXPECT_THROW(map.determineMatching2D(&map, CPose2D(), pairs, gate(0.5), extra), std::invalid_argument);
	EXPECT_THROW(map.compute3DMatchingRatio(&map, mrpt::poses::CPose3D(), {}), std::invalid_argument);
}

// ---------------------------------------------------------------------------------------------
// CICP against a map built from simulated scans.

namespace
{
using gvtest::corridorMap;
using gvtest::corridorWorld;
using gvtest::kDoorClosed;
using gvtest::kTrolley;
using gvtest::scanOf;
using gvtest::scanPoints;

/** CICP from `guess` to the pose of the scan's points against the map. */
TPose2D icpAlign(const CGridVectorMap& map, const CSimplePointsMap& pts, const TPose2D& guess,
				 mrpt::slam::TICPAlgorithm algo)
{
	mrpt::slam::CICP icp;
	icp.options.ICP_algorithm = algo;
	icp.options.maxIterations = 100;
	icp.options.thresholdDist = 0.75f;
	icp.options.thresholdAng = float(0.15 * M_PI / 180);
	icp.options.ALFA = 0.5f;
	icp.options.smallestThresholdDist = 0.05f;
	icp.options.corresponding_points_decimation = 1;
	mrpt::slam::CICP::TReturnInfo info;
	const auto pdf = icp.Align(&map, &pts, CPose2D(guess), info);
	return pdf->getMeanVal().asTPose();
}

double angleErr(double a, double b) { return std::abs(std::remainder(a - b, 2 * M_PI)); }
}  // namespace

TEST(GridVectorMapMatching, IcpClassicRecoversTheScanPoseFromA30cm5degGuess)
{
	const CGridVectorMap map = corridorMap();
	// poses between the mapping poses, the scene as the later scans saw it (door open, nobody)
	auto walls = corridorWorld();
	walls.push_back({4, 0, 4, -0.9});
	const TPose2D truths[] = {{2.3, 1.1, 0.3}, {4.6, 0.7, -0.2}, {7.2, 1.2, 0.1}, {8.0, 0.6, 2.8}};
	const TPose2D offsets[] = {{0.3, 0, 5 * M_PI / 180},
							   {0, -0.3, -5 * M_PI / 180},
							   {-0.21, 0.21, 5 * M_PI / 180},
							   {0.21, 0.21, -5 * M_PI / 180}};
	for (size_t k = 0; k < 4; ++k)
	{
		const CSimplePointsMap pts = scanPoints(scanOf(truths[k], walls, {}, 7 + k));
		const TPose2D guess = truths[k] + offsets[k];
		const TPose2D est = icpAlign(map, pts, guess, mrpt::slam::icpClassic);
		// 1 cm range noise on ~500 points and walls fitted from 12 such scans: a few mm; the
		// tolerance is ICP's last correspondence gate's tenth (smallestThresholdDist 5 cm)
		EXPECT_LT(std::hypot(est.x - truths[k].x, est.y - truths[k].y), 0.01)
			<< "pose " << k << " est " << est.asString();
		EXPECT_LT(angleErr(est.phi, truths[k].phi), 0.2 * M_PI / 180) << "pose " << k << " est " << est.asString();
	}
}

TEST(GridVectorMapMatching, IcpLevenbergMarquardtNeedsAPointsMapAsReferenceInMrpt25)
{
	// MRPT 2.5's CICP::ICP_Method_LM asserts that m1 derives from CPointsMap (it calls
	// CPointsMap::squareDistanceToClosestCorrespondence through the points map's kd-tree): the
	// grid-vector map can be the reference of icpClassic only (doc/mrpt-integration.md).
	const CGridVectorMap map = corridorMap();
	const CSimplePointsMap pts = scanPoints(scanOf({2.3, 1.1, 0.3}, corridorWorld(), {}, 3));
	EXPECT_ANY_THROW(icpAlign(map, pts, {2.3, 1.1, 0.3}, mrpt::slam::icpLevenbergMarquardt));
}

TEST(GridVectorMapMatching, DoorStateAndTrolleySeenOnlyEarlyGetNoCorrespondences)
{
	gridvector::GridVectorConfig half;
	half.matching.staticThreshold = 0.5;  // the E-step's split; the default 0 takes every column
	const CGridVectorMap map = corridorMap(half);
	const CGridVectorMap mapAll = corridorMap();
	// a scan that sees the early scene again: the door closed, the trolley back at its place
	auto walls = corridorWorld();
	walls.push_back(kDoorClosed);
	walls.insert(walls.end(), kTrolley.begin(), kTrolley.end());
	const TPose2D truth(3.0, 1.0, -0.3);
	const CSimplePointsMap pts = scanPoints(scanOf(truth, walls, {}, 42));
	auto onDoor = [](const mrpt::tfest::TMatchingPair& m) {
		return m.global.x > 4.1 && m.global.x < 4.9 && std::abs(m.global.y) < 0.1;
	};
	auto onTrolley = [](const mrpt::tfest::TMatchingPair& m) {
		return m.global.x > 5.5 && m.global.x < 6.5 && m.global.y > 1.2 && m.global.y < 1.8;
	};
	auto count = [&](const CGridVectorMap& m, auto&& on) {
		TMatchingPairList pairs;
		TMatchingExtraResults extra;
		m.determineMatching2D(&pts, CPose2D(truth), pairs, gate(0.3), extra);
		size_t n = 0;
		for (const auto& pr : pairs) n += on(pr);
		return n;
	};
	// with every column, the door's closed state and the trolley are in the map and take points
	EXPECT_GT(count(mapAll, onDoor), 10u);
	EXPECT_GT(count(mapAll, onTrolley), 10u);
	EXPECT_EQ(count(map, onDoor), 0u);
	EXPECT_EQ(count(map, onTrolley), 0u);
	// ICP from a 0.3 m / 5 deg guess in the scene as it is now: the door half open (45 deg), the
	// trolley back but 0.3 m further east. On the static stretches the pose comes out as in the
	// static scene (< 1 cm, 0.2 deg). With every column the trolley's old faces took pairs too;
	// with continuous feet on the lines they pulled the scan 4.5 cm towards where it stood, with
	// the places half a cell apart (StaticFootPoints) 0.6 cm
	auto now = corridorWorld();
	now.push_back({4, 0, 4.64, -0.64});
	const auto moved = gvtest::box(5.9, 1.3, 6.7, 1.7);
	now.insert(now.end(), moved.begin(), moved.end());
	const CSimplePointsMap ptsNow = scanPoints(scanOf(truth, now, {}, 42));
	const TPose2D guess = truth + TPose2D(0.3, 0, 5 * M_PI / 180);
	const TPose2D est = icpAlign(map, ptsNow, guess, mrpt::slam::icpClassic);
	const TPose2D estAll = icpAlign(mapAll, ptsNow, guess, mrpt::slam::icpClassic);
	EXPECT_LT(std::hypot(est.x - truth.x, est.y - truth.y), 0.01) << est.asString();
	EXPECT_LT(angleErr(est.phi, truth.phi), 0.2 * M_PI / 180) << est.asString();
	EXPECT_LT(std::hypot(estAll.x - truth.x, estAll.y - truth.y), 0.03) << estAll.asString();
}

// The matching calls keep the vectors' static stretches (the Fig. 4 profile against the threshold)
// while the map does not change: after every kind of change their answers are those of a map that
// never answered before.
namespace
{
/** Every pair of a determineMatching2D call (vector, point, squared distance) and a nearest distance. */
std::vector<std::tuple<uint32_t, uint32_t, float>> answersOf(const CGridVectorMap& m, const CSimplePointsMap& pts,
															 const TPose2D& x)
{
	TMatchingPairList pairs;
	TMatchingExtraResults extra;
	m.determineMatching2D(&pts, CPose2D(x), pairs, gate(0.3), extra);
	std::vector<std::tuple<uint32_t, uint32_t, float>> out;
	for (const auto& p : pairs) out.emplace_back(p.globalIdx, p.localIdx, p.errorSquareAfterTransformation);
	out.emplace_back(0, 0, m.squareDistanceToClosestCorrespondence(4.5f, 0.05f));  // on the door's closed state
	return out;
}

/** A map that has never answered a matching call: its stretches come fresh. */
CGridVectorMap fresh(const CGridVectorMap& m)
{
	CGridVectorMap f(m.config());
	f.globalMap().setVectors(m.vectors());
	return f;
}
}  // namespace

TEST(GridVectorMapMatching, AnswersFollowTheMapThroughEveryChange)
{
	gridvector::GridVectorConfig half;
	half.matching.staticThreshold = 0.5;
	CGridVectorMap map = corridorMap();
	auto walls = corridorWorld();
	walls.push_back(kDoorClosed);
	walls.insert(walls.end(), kTrolley.begin(), kTrolley.end());
	const TPose2D truth(3.0, 1.0, -0.3);
	const CSimplePointsMap pts = scanPoints(scanOf(truth, walls, {}, 42));
	const auto all = answersOf(map, pts, truth);
	EXPECT_EQ(answersOf(map, pts, truth), all);  // the second call from the kept stretches
	map.setConfig(half);  // the door's closed state and the trolley drop out
	const auto halfAnswers = answersOf(map, pts, truth);
	EXPECT_NE(halfAnswers, all);
	EXPECT_EQ(halfAnswers, answersOf(corridorMap(half), pts, truth));
	map.setConfig(gridvector::GridVectorConfig{});
	EXPECT_EQ(answersOf(map, pts, truth), all);
	map.setConfig(half);
	const CGridVectorMap copy = map;  // answers as the original, from a cache of its own
	EXPECT_EQ(answersOf(copy, pts, truth), halfAnswers);
	// an insertion (the door seen closed again: its columns read more static), a wipe, an
	// insertVector, new content through globalMap(), deserialisation, clear
	map.insertObservation(scanOf({4.5, 1.0, -1.2}, walls, {}, 43), mrpt::poses::CPose3D(4.5, 1.0, 0, -1.2, 0, 0));
	EXPECT_EQ(answersOf(map, pts, truth), answersOf(fresh(map), pts, truth));
	EXPECT_NE(answersOf(map, pts, truth), halfAnswers);
	map.globalMap().wipe({4.5, 1.5, -1.57}, map.extractLocal(scanOf({4.5, 1.5, -1.57}, corridorWorld(), {}, 44)));
	EXPECT_EQ(answersOf(map, pts, truth), answersOf(fresh(map), pts, truth));
	map.globalMap().insertVector(GridVector({4, 0}, {5, 0}, map.config().grid));
	EXPECT_EQ(answersOf(map, pts, truth), answersOf(fresh(map), pts, truth));
	std::vector<GridVector> few(map.vectors().begin(), map.vectors().begin() + 5);
	map.globalMap().setVectors(few);
	EXPECT_EQ(answersOf(map, pts, truth), answersOf(mapOf(few, half), pts, truth));
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << copy;
	buf.Seek(0);
	arch >> map;  // the .gvmap's half-float counts and 1 mm endpoints (CompactMap): answers as of what was read
	EXPECT_EQ(answersOf(map, pts, truth), answersOf(fresh(map), pts, truth));
	EXPECT_EQ(map.vectors().size(), copy.vectors().size());
	map.clear();
	EXPECT_EQ(answersOf(map, pts, truth).size(), 1u);  // no pairs; the nearest distance: none (float max)
}
