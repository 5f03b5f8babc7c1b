// Sec. 3.2: global map building, sequential (insertScan) and batch (buildPerScan + mergeAll).
#include "map/Correspondence.h"
#include "map/GlobalMap.h"
#include "map/OccupancyConversion.h"
#include "extraction/VectorExtractor.h"

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <random>
#include <set>

#include "test_scans.h"
#include "wall_pieces.h"

using namespace gridvector;
using gvtest::wallPiece;
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

namespace
{
double totalPoints(const std::vector<GridVector>& vs)
{
	double s = 0;
	for (const auto& v : vs) s += v.totalPoints();
	return s;
}

struct Sequence
{
	std::vector<TPose2D> poses;
	std::vector<LocalScan> scans;
};

Sequence extractAll(const std::vector<TPose2D>& poses, const std::function<std::vector<gvtest::Seg>(size_t)>& world)
{
	Sequence s;
	const VectorExtractor ex;
	for (size_t t = 0; t < poses.size(); ++t)
	{
		LocalScan l = ex.extract(gvtest::castScan(poses[t], world(t)));
		l.scanIndex = int64_t(t);
		s.poses.push_back(poses[t]);
		s.scans.push_back(std::move(l));
	}
	return s;
}

// The robot drives along y = 0 facing a wall at y = 3; in the first scans a
// person (a 0.5 m wide flat body) walks past 1.5 m in front of the robot.
const int kPersonScans = 6, kScans = 46;
gvtest::Seg personAt(size_t t) { return {-0.85 + 0.3 * t, 1.5, -1.35 + 0.3 * t, 1.5}; }
Sequence personSequence()
{
	std::vector<TPose2D> poses;
	for (int t = 0; t < kScans; ++t) poses.emplace_back(-2.0 + 4.0 * t / (kScans - 1), 0.0, M_PI / 2);
	return extractAll(poses, [](size_t t) {
		std::vector<gvtest::Seg> w{{6, 3, -6, 3}};
		if (t < size_t(kPersonScans)) w.push_back(personAt(t));
		return w;
	});
}

/** The person's footprint cells: points on its body, and how many scans saw each. */
std::vector<std::pair<TPoint2D, int>> personFootprint()
{
	std::vector<std::pair<TPoint2D, int>> pts;
	for (double x = -1.3; x <= 0.5; x += 0.05)
	{
		int seen = 0;
		for (int t = 0; t < kPersonScans; ++t)
		{
			const auto s = personAt(size_t(t));
			seen += x >= s.x2 && x <= s.x1;
		}
		if (seen > 0) pts.push_back({TPoint2D(x, 1.5), seen});
	}
	return pts;
}

void expectPersonFadedAndWallKept(const std::vector<GridVector>& map)
{
	int once = 0;
	for (const auto& [p, seen] : personFootprint())
	{
		const double occ = OccupancyConversion::occupancyAt(map, p);
		if (seen == 1)
		{
			EXPECT_LT(occ, 0.3) << "person cell at x=" << p.x;
			++once;
		}
		EXPECT_LT(occ, 0.5) << "person cell at x=" << p.x << " seen " << seen;
	}
	EXPECT_GE(once, 4);
	for (double x = -2; x <= 2; x += 0.1)
		EXPECT_GT(OccupancyConversion::occupancyAt(map, {x, 3.0}), 0.8) << "wall at x=" << x;
	// between robot and wall: free
	for (double x = -1.5; x <= 1.5; x += 0.3) EXPECT_LE(OccupancyConversion::occupancyAt(map, {x, 2.0}), 0.5) << x;
}
}  // namespace

TEST(GlobalMap, PersonWalkingPastAWallFadesSequential)
{
	const Sequence seq = personSequence();
	GlobalMap map;
	for (size_t t = 0; t < seq.scans.size(); ++t) map.insertScan(seq.poses[t], seq.scans[t]);
	// the person was extracted as vectors in its scans
	bool personSeen = false;
	for (const auto& v : seq.scans[2].vectors) personSeen |= std::abs(v.compose(seq.poses[2]).centre().y - 1.5) < 0.05;
	ASSERT_TRUE(personSeen);
	expectPersonFadedAndWallKept(map.vectors());
	// the wall merged into few vectors, the person's vectors are dynamic-looking
	for (const auto& v : map.vectors())
	{
		if (std::abs(v.centre().y - 1.5) < 0.1)
		{
			EXPECT_LT(v.pStatic(), 0.35);
		}
		if (std::abs(v.centre().y - 3.0) < 0.1)
		{
			EXPECT_GT(v.pStatic(), 0.45);
		}
	}
}

TEST(GlobalMap, PersonWalkingPastAWallFadesBatch)
{
	const Sequence seq = personSequence();
	const auto perScan = GlobalMap::buildPerScan(seq.poses, seq.scans, GridVectorConfig{});
	expectPersonFadedAndWallKept(perScan);
	const MergeResult merged = GlobalMap::mergeAll(perScan, GridVectorConfig{});
	expectPersonFadedAndWallKept(merged.vectors);
	EXPECT_LT(merged.vectors.size(), perScan.size() / 10);
}

TEST(GlobalMap, SequentialMergingConservesPointsAndFindsTheRoom)
{
	const auto walls = gvtest::room(-4, -3, 4, 3);
	std::vector<TPose2D> poses;
	for (int t = 0; t < 12; ++t) poses.emplace_back(-2 + 0.35 * t, 0.3 * std::sin(t), 0.25 * t);
	const Sequence seq = extractAll(poses, [&](size_t) { return walls; });
	GlobalMap map;
	double pts = 0;
	size_t inserted = 0;
	for (size_t t = 0; t < seq.scans.size(); ++t)
	{
		for (const auto& v : seq.scans[t].vectors) pts += v.totalPoints();
		inserted += seq.scans[t].vectors.size();
		map.insertScan(seq.poses[t], seq.scans[t]);
		EXPECT_EQ(map.lastInsertStats().inserted, seq.scans[t].vectors.size());
	}
	EXPECT_NEAR(totalPoints(map.vectors()), pts, 1e-3 * pts);
	EXPECT_LE(map.size(), 8u) << "from " << inserted;
	double len = 0;
	for (const auto& v : map.vectors())
	{
		len += v.length();
		// profile mean over the 3 rows: wall ~1, free row in front ~0, prior behind 0.5
		EXPECT_GT(v.pStatic(), 0.45);
		EXPECT_LT(v.scanIndex, 0);  // all merged
	}
	EXPECT_NEAR(len, 28.0, 1.5);  // the room's perimeter
	// every id is unique
	std::set<uint64_t> ids;
	for (const auto& v : map.vectors()) ids.insert(v.id);
	EXPECT_EQ(ids.size(), map.size());
}

TEST(GlobalMap, LaterScanWipesEarlierVectorsButNotItsOwn)
{
	const Sequence seq = extractAll({TPose2D(0, 0, M_PI / 2), TPose2D(0, 0, M_PI / 2)}, [](size_t) {
		return std::vector<gvtest::Seg>{{3, 2, -3, 2}};
	});
	for (const bool beams : {false, true})
	{
		GridVectorConfig cfg;
		cfg.map.mergeOnInsert = false;
		GlobalMap map(cfg, beams);
		map.insertScan(seq.poses[0], seq.scans[0]);
		ASSERT_EQ(map.size(), 1u);
		const double occ0 = map.vectors()[0].totalOccupy(), vis0 = map.vectors()[0].totalVisit();
		EXPECT_DOUBLE_EQ(occ0, seq.scans[0].vectors[0].totalOccupy());  // own scan: Algorithm 1 only
		map.insertScan(seq.poses[1], seq.scans[1]);
		ASSERT_EQ(map.size(), 2u);
		const GridVector& first = map.vectors()[0];
		const int cols = first.cols();
		const double points = seq.scans[1].vectors[0].totalPoints();
		if (!beams)
		{
			// wall row hit, front row visited (but for a corner cell or two outside the cone)
			EXPECT_LE(first.totalVisit() - vis0, 2 * cols);
			EXPECT_GE(first.totalVisit() - vis0, 2 * cols - 6);
			EXPECT_NEAR(first.totalOccupy() - occ0, cols, 1);
		}
		else
		{
			// the hits equal the beams that ended on the wall: the second scan's endpoints
			EXPECT_NEAR(first.totalOccupy() - occ0, points, 0.05 * points);
			EXPECT_GT(first.totalVisit() - vis0, 1.9 * points);  // + as many passing the front row
		}
		EXPECT_DOUBLE_EQ(map.vectors()[1].totalOccupy(), seq.scans[1].vectors[0].totalOccupy());
		EXPECT_GT(map.lastInsertStats().wipe.cellsHit, 0u);
		// batch: each per-scan vector is wiped by the other scan only, in the batch's unit
		const auto all = GlobalMap::buildPerScan(seq.poses, seq.scans, cfg);
		ASSERT_EQ(all.size(), 2u);
		for (int i = 0; i < 2; ++i)
		{
			const double gain = all[i].totalOccupy() - seq.scans[size_t(i)].vectors[0].totalOccupy();
			const double want =
				GlobalMap::kBatchWipeCountsBeams ? seq.scans[size_t(1 - i)].vectors[0].totalPoints() : all[i].cols();
			EXPECT_NEAR(gain, want, 0.05 * want);
			EXPECT_EQ(all[i].scanIndex, i);
			EXPECT_EQ(all[i].id, uint64_t(i + 1));
		}
		EXPECT_THROW(GlobalMap::buildPerScan({seq.poses[0]}, seq.scans, cfg), std::invalid_argument);
	}
}

TEST(GlobalMap, UpdateCostDependsOnTheNeighbourhoodOnly)
{
	// Rooms far apart: inserting scans in the last room never reaches the others.
	GridVectorConfig cfg;
	GlobalMap map(cfg);
	const VectorExtractor ex;
	size_t maxCandidatesLast = 0, vectorsLastRoom = 0;
	for (int room = 0; room < 6; ++room)
	{
		const double ox = 100.0 * room;
		const auto walls = gvtest::room(ox - 4, -3, ox + 4, 3);
		const size_t before = map.size();
		for (int t = 0; t < 6; ++t)
		{
			const TPose2D pose(ox - 1 + 0.4 * t, 0.2, 0.5 * t);
			LocalScan l = ex.extract(gvtest::castScan(pose, walls));
			l.scanIndex = room * 6 + t;
			map.insertScan(pose, l);
			if (room == 5) maxCandidatesLast = std::max(maxCandidatesLast, map.lastInsertStats().wipe.candidates);
		}
		if (room == 5) vectorsLastRoom = map.size() - before;
	}
	EXPECT_GT(map.size(), 5 * vectorsLastRoom);
	// each triangle meets at most the (few) vectors of its own room
	EXPECT_LE(maxCandidatesLast, 12 * vectorsLastRoom);
	for (const auto& v : map.vectors())
		EXPECT_LT(std::abs(v.centre().x - 100.0 * std::round(v.centre().x / 100.0)), 5.0);
}

TEST(GlobalMap, MergeAllReportsSourcesAndConserves)
{
	const auto walls = gvtest::room(-4, -3, 4, 3);
	std::vector<TPose2D> poses;
	for (int t = 0; t < 10; ++t) poses.emplace_back(-2 + 0.4 * t, 0.1 * t - 0.5, 0.3 * t);
	const Sequence seq = extractAll(poses, [&](size_t) { return walls; });
	const GridVectorConfig cfg;
	const auto all = GlobalMap::buildPerScan(seq.poses, seq.scans, cfg);
	const MergeResult r = GlobalMap::mergeAll(all, cfg);
	ASSERT_EQ(r.vectors.size(), r.sources.size());
	EXPECT_LE(r.vectors.size(), 8u);
	std::multiset<uint64_t> seen;
	double occIn = 0, occOut = 0, visIn = 0, visOut = 0;
	for (const auto& v : all) occIn += v.totalOccupy(), visIn += v.totalVisit();
	for (size_t k = 0; k < r.vectors.size(); ++k)
	{
		occOut += r.vectors[k].totalOccupy(), visOut += r.vectors[k].totalVisit();
		EXPECT_TRUE(std::is_sorted(r.sources[k].begin(), r.sources[k].end()));
		seen.insert(r.sources[k].begin(), r.sources[k].end());
		if (r.sources[k].size() == 1)
			EXPECT_EQ(r.vectors[k].id, r.sources[k][0]);
		else
		{
			EXPECT_GT(r.vectors[k].id, all.size());
			EXPECT_EQ(r.vectors[k].mergedCount, r.sources[k].size());
		}
	}
	EXPECT_EQ(seen.size(), all.size());
	for (const auto& v : all) EXPECT_EQ(seen.count(v.id), 1u);
	EXPECT_NEAR(occOut, occIn, 1e-4 * occIn);
	EXPECT_NEAR(visOut, visIn, 1e-4 * visIn);
	EXPECT_NEAR(totalPoints(r.vectors), totalPoints(all), 1e-3);
	// Eq. 6 on the walls agrees before and after the merge
	for (double x = -3.5; x <= 3.5; x += 0.25)
		for (const TPoint2D p : {TPoint2D(x, 3.0), TPoint2D(x, -3.0), TPoint2D(x, 2.9)})
		{
			const double before = OccupancyConversion::occupancyAt(all, p);
			const double after = OccupancyConversion::occupancyAt(r.vectors, p);
			EXPECT_NEAR(after, before, 0.1) << p.x << " " << p.y;
			if (std::abs(before - 0.5) > 0.15)
			{
				EXPECT_EQ(after > 0.5, before > 0.5) << p.x << " " << p.y;
			}
		}
}

TEST(GlobalMap, MergeCascadesThroughTheMergedVector)
{
	// a and b: the same wall, not overlapping: two map vectors. c (seen with
	// fewer points) overlaps both but lies 0.1 m off (a corresponds, b is
	// 0.16 m from c: no); the merge of a and c, dominated by a's points, matches
	// b: Algorithm 2 goes on with the merged vector until nothing corresponds.
	GlobalMap map;
	map.insertVector(wallPiece({0, 0}, {4, 0}));
	map.insertVector(wallPiece({5, -0.06}, {8, -0.06}));
	ASSERT_EQ(map.size(), 2u);
	const GridVector c = wallPiece({3, 0.1}, {5.5, 0.1}, 0.08);
	ASSERT_EQ(map.correspondents(c).size(), 1u);
	map.insertVector(c);
	ASSERT_EQ(map.size(), 1u);
	EXPECT_EQ(map.vectors()[0].mergedCount, 3u);
	EXPECT_NEAR(map.vectors()[0].start().x, 0, 0.05);
	EXPECT_NEAR(map.vectors()[0].end().x, 8, 0.05);
	EXPECT_GE(map.lastInsertStats().merges, 2u);
}

TEST(GlobalMap, NoisyPassesOfOneWallEndAsOneVector)
{
	// A robot drives 20 times along a 12 m corridor with noisy poses (2 cm,
	// 0.3 deg): each wall side ends as one vector, every beam endpoint kept.
	const std::vector<gvtest::Seg> walls = {{-1, -1.2, 13, -1.2}, {13, 1.2, -1, 1.2}};
	std::mt19937 rng(7);
	std::normal_distribution<double> nxy(0, 0.02), nphi(0, 0.3 * M_PI / 180);
	const VectorExtractor ex;
	GlobalMap map;
	double pts = 0;
	int64_t t = 0;
	for (int pass = 0; pass < 20; ++pass)
		for (double x = 0; x <= 12; x += 0.5)
		{
			const double dir = pass % 2 ? M_PI : 0.0;
			const TPose2D truth(pass % 2 ? 12 - x : x, 0, dir);
			LocalScan l = ex.extract(gvtest::castScan(truth, walls, {}, 361, M_PI, 8.0));
			l.scanIndex = t++;
			for (const auto& v : l.vectors) pts += v.totalPoints();
			map.insertScan(TPose2D(truth.x + nxy(rng), truth.y + nxy(rng), truth.phi + nphi(rng)), l);
		}
	EXPECT_NEAR(totalPoints(map.vectors()), pts, 1e-3 * pts);
	int south = 0, north = 0;
	for (const auto& v : map.vectors())
	{
		const bool s = std::abs(v.centre().y + 1.2) < 0.2, n = std::abs(v.centre().y - 1.2) < 0.2;
		south += s, north += n;
		if (s || n)
		{
			EXPECT_GT(v.length(), 11.5);
		}
		// no drift: the merged walls keep the walls' direction
		if (s)
		{
			EXPECT_LT(std::abs(mrpt::math::wrapToPi(v.psi())), 0.5 * M_PI / 180) << v.psi();
		}
		if (n)
		{
			EXPECT_LT(std::abs(mrpt::math::wrapToPi(v.psi() - M_PI)), 0.5 * M_PI / 180) << v.psi();
		}
	}
	EXPECT_EQ(south, 1);
	EXPECT_EQ(north, 1);
	EXPECT_EQ(map.size(), 2u);
}

TEST(GlobalMap, SetVectorsRebuildsTheIndex)
{
	GlobalMap map;
	map.setVectors({GridVector({0, 0}, {2, 0}, GridOptions{}), GridVector({50, 0}, {52, 0}, GridOptions{})});
	const auto c = map.correspondents(GridVector({1, 0.05}, {3, 0.05}, GridOptions{}));
	ASSERT_EQ(c.size(), 1u);
	EXPECT_EQ(c[0], 0u);
	map.insertVector(GridVector({1, 0.0}, {3, 0.0}, GridOptions{}));
	EXPECT_EQ(map.size(), 2u);  // merged into the first
	EXPECT_EQ(map.index().size(), 2u);
	EXPECT_EQ(map.index().cellSize(), VectorIndex::kCellSize);
	EXPECT_EQ(map.correspondents(GridVector({50.5, 0}, {51, 0}, GridOptions{})).size(), 1u);
	map.clear();
	EXPECT_TRUE(map.empty());
	EXPECT_EQ(map.index().size(), 0u);
}

namespace
{
/** A wall bending along the circle of radius R centred at (0, R), as polyline
 * pieces of 0.2 m, from x0 to x1; distance of a point from that arc. */
std::vector<gvtest::Seg> arcWall(double R, double x0, double x1)
{
	std::vector<gvtest::Seg> w;
	auto y = [&](double x) { return R - std::sqrt(R * R - x * x); };
	for (double x = x0; x < x1 - 1e-9; x += 0.2) w.push_back({x, y(x), x + 0.2, y(x + 0.2)});
	return w;
}
double offArc(double R, const TPoint2D& p) { return std::abs(std::hypot(p.x, p.y - R) - R); }

/** A robot driving twice along a 14 m wall bending with 0.7 m sagitta (R = 36 m, as
 * Intel's corridor walls in its corrected poses), 1.5 m from it, a scan every 0.25 m. */
Sequence curvedCorridor()
{
	const double R = 36;
	std::vector<TPose2D> poses;
	for (int pass = 0; pass < 2; ++pass)
		for (double x = -6; x <= 6; x += 0.25)
		{
			const double a = std::asin(x / (R - 1.5));  // on the circle of radius R - 1.5
			poses.emplace_back((R - 1.5) * std::sin(a), R - (R - 1.5) * std::cos(a), a);
		}
	return extractAll(poses, [](size_t) { return arcWall(36, -7, 7); });
}

/** Largest distance from the arc of a vector's ends and centre, over the vectors longer than 1 m
 * (a 2 m chord of the arc is 0.014 m off at its centre). */
double worstOffArc(const std::vector<GridVector>& vs)
{
	double worst = 0;
	for (const auto& v : vs)
		if (v.length() > 1)
			for (const TPoint2D& p : {v.start(), v.centre(), v.end()}) worst = std::max(worst, offArc(36, p));
	return worst;
}
}  // namespace

TEST(GlobalMap, PiecesOfACurvedWallAreNotChainedIntoOneChord)
{
	// Each piece is within the criteria of the merge before it, so without the
	// guard the pieces chain into chords whose ends leave the wall; with it
	// every vector stays within its grid's band of the wall, in both modes.
	const Sequence s = curvedCorridor();
	GridVectorConfig paper;
	paper.map.mergeHoldsWall = false;
	GlobalMap chained(paper), guarded;
	for (size_t t = 0; t < s.scans.size(); ++t)
	{
		chained.insertScan(s.poses[t], s.scans[t]);
		guarded.insertScan(s.poses[t], s.scans[t]);
	}
	EXPECT_GT(worstOffArc(chained.vectors()), 0.3);  // the defect, reproduced (0.37 m)
	EXPECT_LT(worstOffArc(guarded.vectors()), 0.2);  // the band, 0.15 m, at the columns; ends extrapolate
	double pts = 0;
	for (const auto& l : s.scans)
		for (const auto& v : l.vectors) pts += v.totalPoints();
	EXPECT_NEAR(totalPoints(guarded.vectors()), pts, 1e-3 * pts);
	const auto perScan = GlobalMap::buildPerScan(s.poses, s.scans, GridVectorConfig{});
	const MergeResult batch = GlobalMap::mergeAll(perScan, GridVectorConfig{});
	EXPECT_LT(worstOffArc(batch.vectors), 0.2);
	EXPECT_GT(worstOffArc(GlobalMap::mergeAll(perScan, paper).vectors), 0.3);
	EXPECT_NEAR(totalPoints(batch.vectors), pts, 1e-3 * pts);
	std::set<uint64_t> ids;
	for (const auto& src : batch.sources) ids.insert(src.begin(), src.end());
	EXPECT_EQ(ids.size(), perScan.size());  // every input in exactly one output
}

TEST(GlobalMap, InsertScanMergesTheScansOwnOverlappingVectors)
{
	// two overlapping vectors of one scan (a wall seen in two pieces that
	// overlap) into an empty map: nothing corresponds to either when the scan
	// arrives, but the second corresponds to the first once it is in the map
	LocalScan l;
	l.vectors = {wallPiece({0, 2}, {2, 2}), wallPiece({1, 2.05}, {3, 2.05})};
	l.scanIndex = 0;
	GlobalMap map;
	map.insertScan(TPose2D(0, 0, 0), l);
	EXPECT_EQ(map.lastInsertStats().inserted, 2u);
	EXPECT_EQ(map.lastInsertStats().merges, 1u);
	EXPECT_EQ(map.lastInsertStats().absorbed, 1u);
	ASSERT_EQ(map.size(), 1u);
	const GridVector& m = map.vectors()[0];
	EXPECT_EQ(m.scanIndex, -1);  // a merged vector
	EXPECT_NEAR(std::min(m.start().x, m.end().x), 0, 0.05);
	EXPECT_NEAR(std::max(m.start().x, m.end().x), 3, 0.05);
	EXPECT_NEAR(0.5 * (m.start().y + m.end().y), 2.025, 0.03);
}

TEST(GlobalMap, MergeAllGroupRoundsLetAGrownSpanReachFurther)
{
	// B (4.2 m, 0.1 m to the side) overlaps A (4 m) by 1.13 mm: too little for criterion 3
	// (|c_A - c_B| >= (l_A + l_B)/2); the short v lies beyond A's other end, far from B (outside
	// its search box) but corresponds to A. A + v's longer span corresponds to B: only a
	// second round of the grouping, searching around the grown span, finds it.
	const double eps = 0.00113;
	std::vector<GridVector> in = {wallPiece({7.5 - eps, 0.1}, {11.7 - eps, 0.1}), wallPiece({3.5, 0}, {7.5, 0}),
								  wallPiece({2, 0}, {4, 0})};
	for (size_t k = 0; k < in.size(); ++k) in[k].id = k + 1;
	const MapOptions opt;
	ASSERT_FALSE(corresponds(in[1], in[0], opt));
	ASSERT_FALSE(corresponds(in[2], in[0], opt));
	ASSERT_TRUE(corresponds(in[2], in[1], opt));
	auto sourcesWith = [&](int rounds) {
		std::vector<std::vector<uint64_t>> s = GlobalMap::mergeAll(in, GridVectorConfig(), rounds).sources;
		std::sort(s.begin(), s.end());
		return s;
	};
	EXPECT_EQ(GlobalMap::kMergeGroupRounds, 16);
	EXPECT_EQ(sourcesWith(1), (std::vector<std::vector<uint64_t>>{{1}, {2, 3}}));
	EXPECT_EQ(sourcesWith(16), (std::vector<std::vector<uint64_t>>{{1, 2, 3}}));
	EXPECT_EQ(sourcesWith(2), sourcesWith(16));
}

TEST(GlobalMap, RefusedMergeStillGetsTheScansHits)
{
	// Eq. 8 in sequential mode: a new vector's triangle gives only part b to the
	// map vectors it corresponds to, since its endpoints reach them through its
	// own Algorithm 1 counts when merged. X (a wall at y = 2) and j (a piece
	// bending away from it by 9 deg, overlapping X over 0.5 m) correspond, but
	// the guard (map.merge_holds_wall) refuses their merge: X must then get
	// j's hits (part c) as if no merge had been considered.
	LocalScan first, second;
	first.vectors = {wallPiece({4, 2}, {0, 2})};
	first.scanIndex = 0;
	second.vectors = {wallPiece({0.5, 2}, {-3.5, 2.63})};
	second.scanIndex = 1;
	ASSERT_TRUE(corresponds(first.vectors[0], second.vectors[0], MapOptions{}));
	for (const bool beams : {false, true})
	{
		GridVectorConfig cfg;
		GridVectorConfig noMerge = cfg;
		noMerge.map.mergeOnInsert = false;
		GlobalMap merging(cfg, beams), separate(noMerge, beams);
		for (GlobalMap* m : {&merging, &separate})
		{
			m->insertScan(TPose2D(0, 0, 0), first);
			m->insertScan(TPose2D(0, 0, 0), second);
		}
		ASSERT_EQ(merging.size(), 2u) << "the merge is refused";
		EXPECT_EQ(merging.lastInsertStats().refused, 1u);
		const GridVector &x = merging.vectors()[0], &want = separate.vectors()[0];
		ASSERT_EQ(x.scanIndex, 0);
		EXPECT_GT(want.totalOccupy(), first.vectors[0].totalOccupy() + 1);  // j's part c reached X
		ASSERT_EQ(x.cells().size(), want.cells().size());
		for (size_t i = 0; i < x.cells().size(); ++i)
		{
			// per beam the same increments, summed in another order
			const GridCell &a = x.cells()[i], &b = want.cells()[i];
			EXPECT_NEAR(a.n_occupy, b.n_occupy, 1e-5 * b.n_occupy) << "beams " << beams << " cell " << i;
			EXPECT_NEAR(a.n_visit, b.n_visit, 1e-5 * b.n_visit) << "beams " << beams << " cell " << i;
		}
	}
}
