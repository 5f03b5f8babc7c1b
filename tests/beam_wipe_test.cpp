// Eq. 8 extended (beyond the paper): beams that made no vector update the map vectors they cross.
#include "map/BeamWipe.h"
#include "map/GlobalMap.h"
#include "map/OccupancyConversion.h"
#include "extraction/VectorExtractor.h"

#include <gtest/gtest.h>

#include <vector>

#include "test_scans.h"

using namespace gridvector;
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

namespace
{
struct Visit
{
	int row, col;
	bool last;
};
std::vector<Visit> cellsCrossed(const GridVector& m, TPoint2D a, TPoint2D b)
{
	std::vector<Visit> out;
	BeamWipe::traverse(m, a, b, [&](int r, int c, bool last) { out.push_back({r, c, last}); });
	return out;
}
}  // namespace

TEST(BeamWipe, TraverseVisitsTheCellsCrossedInOrder)
{
	const GridVector m({0, 0}, {1, 0}, GridOptions{});  // 10 columns, rows w = -0.1, 0, 0.1
	// across the grid at u = 0.55, from the open side (row 2) to behind (row 0)
	auto v = cellsCrossed(m, {0.55, 1}, {0.55, -1});
	ASSERT_EQ(v.size(), 3u);
	EXPECT_EQ(v[0].row, 2);
	EXPECT_EQ(v[1].row, 1);
	EXPECT_EQ(v[2].row, 0);
	for (const auto& x : v)
	{
		EXPECT_EQ(x.col, 5);
		EXPECT_FALSE(x.last);
	}
	// ending on the line: the last cell is the one holding the end
	v = cellsCrossed(m, {0.55, 1}, {0.55, 0.02});
	ASSERT_EQ(v.size(), 2u);
	EXPECT_EQ(v[1].row, 1);
	EXPECT_TRUE(v[1].last);
	// along the middle row from outside: every column once, the end cell last
	v = cellsCrossed(m, {-2, 0.01}, {0.42, 0.01});
	ASSERT_EQ(v.size(), 5u);
	for (int k = 0; k < 5; ++k)
	{
		EXPECT_EQ(v[size_t(k)].col, k);
		EXPECT_EQ(v[size_t(k)].row, 1);
	}
	EXPECT_TRUE(v.back().last);
	// missing the grid
	EXPECT_TRUE(cellsCrossed(m, {2, 1}, {3, -1}).empty());
}

TEST(BeamWipe, ScanBeamsKeepsOnlyTheBeamsNoVectorExplains)
{
	// a wall 2 m ahead covering part of the fan, a small post (no vector) and open space
	const std::vector<gvtest::Seg> walls{{2, -1, 2, 1}};
	const auto scan = gvtest::castScan(TPose2D(0, 0, 0), walls, {{1.0, 1.5, 0.03}}, 181, M_PI, 8.0);
	const LocalScan local = VectorExtractor().extract(scan);
	ASSERT_GE(local.vectors.size(), 1u);
	const ScanBeams b = ScanBeams::of(scan, local);
	size_t post = 0, none = 0;
	for (size_t k = 0; k < b.ends.size(); ++k)
	{
		EXPECT_GT(std::abs(b.ends[k].x - 2) + (std::abs(b.ends[k].y) > 1.05 ? 1 : 0), 0.05);  // no wall beam
		if (b.returned[k])
		{
			++post;
			EXPECT_NEAR(std::hypot(b.ends[k].x - 1.0, b.ends[k].y - 1.5), 0.03, 0.01);
		}
		else
		{
			++none;
			EXPECT_NEAR(std::hypot(b.ends[k].x, b.ends[k].y), 8.0, 1e-3);
		}
	}
	EXPECT_GE(post, 1u);
	EXPECT_GT(none, 100u);
}

TEST(BeamWipe, AWallThatDisappearedIsClearedOnlyWithTheOption)
{
	// scans 0-19 see a wall at y = 3; then it is gone for 40 scans and nothing
	// lies behind it within range: no vector, no triangle, only beams without a return
	std::vector<LocalScan> scans;
	std::vector<ScanBeams> beams;
	const VectorExtractor ex;
	for (int t = 0; t < 60; ++t)
	{
		const std::vector<gvtest::Seg> w =
			t < 20 ? std::vector<gvtest::Seg>{{-3, 3, 3, 3}} : std::vector<gvtest::Seg>{};
		const auto scan = gvtest::castScan(TPose2D(0, 0, M_PI / 2), w, {}, 181, M_PI, 8.0);
		scans.push_back(ex.extract(scan));
		scans.back().scanIndex = t;
		beams.push_back(ScanBeams::of(scan, scans.back()));
	}
	GridVectorConfig on;
	on.map.wipeVectorlessBeams = true;
	GlobalMap paper, extended(on);
	for (size_t t = 0; t < scans.size(); ++t)
	{
		paper.insertScan(TPose2D(0, 0, M_PI / 2), scans[t], beams[t]);
		extended.insertScan(TPose2D(0, 0, M_PI / 2), scans[t], beams[t]);
	}
	EXPECT_EQ(paper.lastInsertStats().beams.beams, 0u);
	EXPECT_GT(extended.lastInsertStats().beams.cellsVisited, 0u);
	EXPECT_EQ(extended.lastInsertStats().beams.cellsHit, 0u);
	const TPoint2D onWall(0.5, 3.0);
	EXPECT_GT(OccupancyConversion::occupancyAt(paper.vectors(), onWall), 0.5);  // Eq. 8: never seen through
	EXPECT_LT(OccupancyConversion::occupancyAt(extended.vectors(), onWall), 0.5);  // 20 scans of returns, 40 of passes
	// the counts of the first 20 scans are the same in both maps
	double pts = 0, ptsExt = 0;
	for (const auto& v : paper.vectors()) pts += v.totalPoints();
	for (const auto& v : extended.vectors()) ptsExt += v.totalPoints();
	EXPECT_DOUBLE_EQ(pts, ptsExt);
}

TEST(BeamWipe, ClutterEndingInAMapVectorCountsAsAHit)
{
	// a wall mapped from far; then a post too small for a vector stands on it
	GridVectorConfig on;
	on.map.wipeVectorlessBeams = true;
	GlobalMap map(on);
	const VectorExtractor ex;
	const auto first = gvtest::castScan(TPose2D(0, 0, M_PI / 2), {{-3, 3, 3, 3}}, {}, 181, M_PI, 8.0);
	LocalScan l0 = ex.extract(first);
	l0.scanIndex = 0;
	map.insertScan(TPose2D(0, 0, M_PI / 2), l0, ScanBeams::of(first, l0));
	const double before = map.vectors()[0].totalOccupy();
	// second scan: only a post (2 cm radius) on the wall line, in the beam at 80 deg, is in range
	const double bx = 3.0 / std::tan(80 * M_PI / 180);
	const auto second = gvtest::castScan(TPose2D(0, 0, M_PI / 2), {}, {{bx, 3.0, 0.02}}, 181, M_PI, 8.0);
	LocalScan l1 = ex.extract(second);
	l1.scanIndex = 1;
	ASSERT_TRUE(l1.vectors.empty());
	map.insertScan(TPose2D(0, 0, M_PI / 2), l1, ScanBeams::of(second, l1));
	EXPECT_GE(map.lastInsertStats().beams.cellsHit, 1u);
	EXPECT_GT(map.vectors()[0].totalOccupy(), before);
}
