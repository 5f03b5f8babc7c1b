// Eq. 6-7: conversion of the grid vector map to an occupancy grid.
#include <gridvector/OccupancyConversion.h>

#include <gtest/gtest.h>

using namespace gridvector;
using mrpt::math::TPoint2D;

namespace
{
GridVector wallWithCounts()
{
	GridVector v({0, 0}, {2, 0}, GridOptions{});  // rows: w = -0.1, 0, +0.1
	for (int c = 0; c < v.cols(); ++c)
	{
		v.cell(1, c).n_occupy = 9.5f, v.cell(1, c).n_visit = 10.f;  // wall: 0.95
		v.cell(2, c).n_occupy = 0.5f, v.cell(2, c).n_visit = 10.f;  // in front: 0.05
	}
	return v;
}
}  // namespace

TEST(OccupancyConversion, PointQueriesSumAllCoveringCells)
{
	const GridVector a = wallWithCounts();
	GridVector b({1, 0}, {3, 0}, GridOptions{});
	for (auto& c : b.cells()) c.n_occupy = 1.f, c.n_visit = 4.f;
	const std::vector<GridVector> m{a, b};
	EXPECT_NEAR(OccupancyConversion::occupancyAt(m, {0.55, 0.01}), 0.95, 1e-6);
	EXPECT_NEAR(OccupancyConversion::occupancyAt(m, {1.55, 0.01}), (9.5 + 1) / 14.0, 1e-6);
	EXPECT_NEAR(OccupancyConversion::occupancyAt(m, {2.55, 0.01}), 0.25, 1e-6);
	EXPECT_EQ(OccupancyConversion::occupancyAt(m, {1.0, 1.0}), 0.5);  // nothing covers it
	const auto [o, v] = OccupancyConversion::countsAt(m, {1.0, 1.0});
	EXPECT_EQ(o, 0);
	EXPECT_EQ(v, 0);
}

TEST(OccupancyConversion, GridAtTheVectorResolution)
{
	const std::vector<GridVector> m{wallWithCounts()};
	OccupancyConversionOptions opt;
	opt.resolution = 0.1;
	opt.margin = 0.3;
	const auto g = OccupancyConversion::toOccupancyGrid(m, opt);
	EXPECT_NEAR(g.getResolution(), 0.1, 1e-6);
	// MRPT snaps the grid to multiples of the resolution: output cells [-0.1, 0]
	// and [0, 0.1] each straddle the wall row [-0.05, 0.05] (area average).
	ASSERT_NEAR(g.getYMin(), -0.4, 1e-6);
	auto occ = [&](double x, double y) { return 1.0 - g.getPos(x, y); };  // MRPT stores p(free)
	for (double x = 0.25; x < 1.8; x += 0.1)
	{
		EXPECT_NEAR(occ(x, -0.05), 10.0 / 11.0, 0.02) << x;  // behind (prior) + wall
		EXPECT_NEAR(occ(x, 0.05), 0.5, 0.02) << x;  // wall + free row in front
		EXPECT_NEAR(occ(x, 0.15), 0.05, 0.02) << x;  // free row only
		EXPECT_EQ(g.getPos(x, 0.5), 0.5f) << x;  // nothing there
	}
	EXPECT_EQ(g.getPos(-0.2, 0.0), 0.5f);
}

TEST(OccupancyConversion, AlignedCellsReproduceEq6Exactly)
{
	// Output cells exactly on the vector's cells: Eq. 6 at the cell centre.
	const std::vector<GridVector> m{wallWithCounts()};
	const OccupancyRaster R = OccupancyConversion::rasterise(m, 0.0, -0.15, 0.1, 20, 3, 4);
	for (int ix = 0; ix < 20; ++ix)
	{
		EXPECT_NEAR(R.probability(ix, 1), 0.95, 1e-6);
		EXPECT_NEAR(R.probability(ix, 2), 0.05, 1e-6);
		EXPECT_NEAR(R.probability(ix, 0), 0.5, 1e-6);  // the prior: behind the wall
		EXPECT_TRUE(R.known(ix, 0));
	}
}

TEST(OccupancyConversion, AnyResolutionAveragesTheCounts)
{
	std::vector<GridVector> m{wallWithCounts()};
	for (int c = 0; c < m[0].cols(); ++c) m[0].cell(0, c).n_occupy = 1, m[0].cell(0, c).n_visit = 4;
	// a coarse 0.3 m cell over all three rows: (1 + 9.5 + 0.5) / (4 + 10 + 10) per column
	const OccupancyRaster R = OccupancyConversion::rasterise(m, 0.0, -0.15, 0.3, 6, 1, 0);
	for (int ix = 0; ix < 6; ++ix) EXPECT_NEAR(R.probability(ix, 0), 11.0 / 24.0, 1e-5);
	// fine 0.025 m cells: each inside one vector cell
	const OccupancyRaster F = OccupancyConversion::rasterise(m, 0.0, -0.15, 0.025, 80, 12, 0);
	EXPECT_NEAR(F.probability(10, 5), 0.95, 1e-6);  // y in [-0.025, 0]
	EXPECT_NEAR(F.probability(10, 8), 0.05, 1e-6);  // y in [0.05, 0.075]
	// rotated vector: the raster agrees with point queries at most cells
	GridVector r({0, 0}, {1.5, 1.5}, GridOptions{});
	for (int c = 0; c < r.cols(); ++c) r.cell(1, c).n_occupy = 5, r.cell(1, c).n_visit = 6;
	const std::vector<GridVector> rv{r};
	const OccupancyRaster G = OccupancyConversion::rasterise(rv, -0.5, -0.5, 0.02, 125, 125, 1);
	int agree = 0, total = 0;
	for (int iy = 0; iy < G.ny; ++iy)
		for (int ix = 0; ix < G.nx; ++ix)
		{
			const TPoint2D p(-0.5 + (ix + 0.5) * 0.02, -0.5 + (iy + 0.5) * 0.02);
			const double want = OccupancyConversion::occupancyAt(rv, p);
			if (!G.known(ix, iy) && want == 0.5) continue;
			++total;
			agree += std::abs(G.probability(ix, iy) - want) < 1e-6;
		}
	EXPECT_GT(total, 1000);
	EXPECT_EQ(agree, total);
}

TEST(OccupancyConversion, EmptyMapIsAllUnknown)
{
	const auto g = OccupancyConversion::toOccupancyGrid({});
	EXPECT_GT(g.getSizeX(), 0u);
	EXPECT_EQ(g.getCell(0, 0), 0.5f);
}
