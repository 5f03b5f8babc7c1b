// Eq. 6-7: conversion of the grid vector map to an occupancy grid.
#include "map/OccupancyConversion.h"

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

TEST(OccupancyConversion, GridAtTheVectorResolutionIsEq6AtCellCentres)
{
	// the wall at y = 0.02: rows behind [-0.13, -0.03), wall [-0.03, 0.07), free [0.07, 0.17)
	const std::vector<GridVector> m{wallWithCounts().compose(mrpt::math::TPose2D(0, 0.02, 0))};
	OccupancyConversionOptions opt;
	opt.resolution = 0.1;
	opt.margin = 0.3;
	const auto g = OccupancyConversion::toOccupancyGrid(m, opt);
	EXPECT_NEAR(g.getResolution(), 0.1, 1e-6);
	ASSERT_NEAR(g.getYMin(), -0.4, 1e-6);  // MRPT snaps the grid to multiples of the resolution
	auto occ = [&](double x, double y) { return 1.0 - g.getPos(x, y); };  // MRPT stores p(free)
	for (double x = 0.25; x < 1.8; x += 0.1)
	{
		EXPECT_NEAR(occ(x, -0.05), 0.5, 0.01) << x;  // centre in the prior row behind
		EXPECT_NEAR(occ(x, 0.05), 0.95, 0.01) << x;  // centre in the wall row
		EXPECT_NEAR(occ(x, 0.15), 0.05, 0.01) << x;  // centre in the free row
		EXPECT_EQ(g.getPos(x, 0.5), 0.5f) << x;  // nothing there
	}
	EXPECT_EQ(g.getPos(-0.2, 0.0), 0.5f);
}

TEST(OccupancyConversion, CoarseCellHoldingAnObstacleIsOccupied)
{
	std::vector<GridVector> m{wallWithCounts()};
	for (int c = 0; c < m[0].cols(); ++c) m[0].cell(0, c).n_occupy = 1, m[0].cell(0, c).n_visit = 4;
	// one 0.3 m cell over all three rows: max pooling takes the wall row
	const OccupancyRaster R = OccupancyConversion::rasterise(m, 0.0, -0.15, 0.3, 6, 1, 0, true);
	for (int ix = 0; ix < 6; ++ix) EXPECT_NEAR(R.probability(ix, 0), 0.95, 1e-5);
	// a cell over the prior row behind the wall and the free row of another
	// vector: the prior carries no evidence, the cell is free
	GridVector a({0, 0}, {2, 0}, GridOptions{});  // nothing observed
	GridVector b({2, 0.1}, {0, 0.1}, GridOptions{});  // opposite side, free row at y = 0
	for (int c = 0; c < b.cols(); ++c) b.cell(2, c).n_occupy = 1, b.cell(2, c).n_visit = 20;
	const OccupancyRaster F = OccupancyConversion::rasterise({a, b}, 0.0, -0.05, 0.2, 10, 1, 4, true);
	for (int ix = 1; ix < 9; ++ix)
		EXPECT_NEAR(F.probability(ix, 0), 1.5 / 21.0, 1e-5) << ix;  // prior of a + free row of b
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
		EXPECT_NEAR(R.probability(ix, 0), 0.5, 1e-6);  // the prior behind the wall: no evidence
		EXPECT_FALSE(R.known(ix, 0));
	}
}

TEST(OccupancyConversion, MeanPoolingAveragesTheCounts)
{
	std::vector<GridVector> m{wallWithCounts()};
	for (int c = 0; c < m[0].cols(); ++c) m[0].cell(0, c).n_occupy = 1, m[0].cell(0, c).n_visit = 4;
	// a coarse 0.3 m cell over all three rows: (1 + 9.5 + 0.5) / (4 + 10 + 10) per column
	const OccupancyRaster R = OccupancyConversion::rasterise(m, 0.0, -0.15, 0.3, 6, 1, 0, false);
	for (int ix = 0; ix < 6; ++ix) EXPECT_NEAR(R.probability(ix, 0), 11.0 / 24.0, 1e-5);
	// fine 0.025 m cells: each inside one vector cell
	const OccupancyRaster F = OccupancyConversion::rasterise(m, 0.0, -0.15, 0.025, 80, 12, 0, false);
	EXPECT_NEAR(F.probability(10, 5), 0.95, 1e-6);  // y in [-0.025, 0]
	EXPECT_NEAR(F.probability(10, 8), 0.05, 1e-6);  // y in [0.05, 0.075]
	// rotated vector: the raster agrees with point queries at most cells
	GridVector r({0, 0}, {1.5, 1.5}, GridOptions{});
	for (int c = 0; c < r.cols(); ++c) r.cell(1, c).n_occupy = 5, r.cell(1, c).n_visit = 6;
	const std::vector<GridVector> rv{r};
	const OccupancyRaster G = OccupancyConversion::rasterise(rv, -0.5, -0.5, 0.02, 125, 125, 1);
	int agree = 0, total = 0, unknown = 0;
	for (int iy = 0; iy < G.ny; ++iy)
		for (int ix = 0; ix < G.nx; ++ix)
		{
			const TPoint2D p(-0.5 + (ix + 0.5) * 0.02, -0.5 + (iy + 0.5) * 0.02);
			const double want = OccupancyConversion::occupancyAt(rv, p);
			++(G.known(ix, iy) ? total : unknown);
			agree += std::abs(G.probability(ix, iy) - want) < 1e-6;  // unknown: the prior or nothing, 1/2
		}
	EXPECT_GT(total, 500);  // the observed row: 2.1 m x 0.1 m
	EXPECT_GT(unknown, 10000);
	EXPECT_EQ(agree, total + unknown);
}

TEST(OccupancyConversion, UnobservedMeansAtThePriorNotAtOneHalf)
{
	GridOptions g;
	g.priorOccupy = 1.0 / 3, g.priorVisit = 1;
	// at y = 0.02 (off MRPT's cell edges): rows behind [-0.13, -0.03) never observed, wall, front
	GridVector v({0, 0.02}, {2, 0.02}, g);
	for (int c = 0; c < v.cols(); ++c)
	{
		v.cell(1, c).n_occupy += 9, v.cell(1, c).n_visit += 10;  // wall: 9 hits in 10 observations
		v.cell(2, c).n_occupy = 2.5f, v.cell(2, c).n_visit = 5;  // observed, Eq. 6 exactly 1/2
	}
	const std::vector<GridVector> m{v};
	const double wall = (1.0 / 3 + 9) / 11;
	EXPECT_NEAR(OccupancyConversion::occupancyAt(m, {0.55, 0.02}, g), wall, 1e-6);
	EXPECT_NEAR(OccupancyConversion::occupancyAt(m, {0.55, -0.08}, g), 1.0 / 3, 1e-6);  // the prior's counts
	EXPECT_NEAR(OccupancyConversion::occupancyAt(m, {0.55, 1.0}, g), 1.0 / 3, 1e-6);  // nothing covers it
	// at the vector's own resolution: the prior row stays unknown, the others are Eq. 6
	const OccupancyRaster R = OccupancyConversion::rasterise(m, 0.0, -0.13, 0.1, 20, 3, 0, true, g);
	for (int ix = 0; ix < 20; ++ix)
	{
		EXPECT_FALSE(R.known(ix, 0)) << ix;
		EXPECT_NEAR(R.probability(ix, 1), wall, 1e-6) << ix;
		EXPECT_TRUE(R.known(ix, 2)) << ix;
		EXPECT_EQ(R.probability(ix, 2), 0.5) << ix;
	}
	// one coarse cell over the prior row and the row at 1/2: max pooling takes the observed 1/2
	GridVector u({0, 0}, {2, 0}, g);
	for (int c = 0; c < u.cols(); ++c) u.cell(1, c).n_occupy = 2.5f, u.cell(1, c).n_visit = 5;
	const OccupancyRaster C = OccupancyConversion::rasterise({u}, 0.0, -0.15, 0.3, 6, 1, 0, true, g);
	for (int ix = 0; ix < 6; ++ix) EXPECT_EQ(C.probability(ix, 0), 0.5) << ix;  // not the prior's 1/3
	// the MRPT grid: unknown behind the wall (not p(free) = 2/3), Eq. 6 on it
	OccupancyConversionOptions opt;
	opt.resolution = 0.1, opt.margin = 0.3;
	const auto grid = OccupancyConversion::toOccupancyGrid(m, opt, g);
	for (double x = 0.25; x < 1.8; x += 0.1)
	{
		EXPECT_EQ(grid.getPos(x, -0.05), 0.5f) << x;
		EXPECT_NEAR(1.0 - grid.getPos(x, 0.05), wall, 0.01) << x;
		EXPECT_NEAR(1.0 - grid.getPos(x, 0.15), 0.5, 0.01) << x;
	}
}

TEST(OccupancyConversion, EmptyMapIsAllUnknown)
{
	const auto g = OccupancyConversion::toOccupancyGrid({});
	EXPECT_GT(g.getSizeX(), 0u);
	EXPECT_EQ(g.getCell(0, 0), 0.5f);
}

TEST(OccupancyConversion, RasterTooLargeForItsExtentIsAnErrorNotAnAllocationFailure)
{
	// gv-em-slam with [gridvector_occupancy] resolution = 0.00001 wrote trajectory.txt, the vectors and
	// map.gvmap, then failed as "std::bad_alloc" (margin = 1e9: an OpenCV assertion), leaving those behind
	const std::vector<GridVector> m{wallWithCounts()};
	OccupancyConversionOptions opt;
	opt.resolution = 1e-5;
	try
	{
		OccupancyConversion::toOccupancyGrid(m, opt);
		ADD_FAILURE() << "no error";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()),
				  "occupancy grid of 3 x 1.3 m at resolution 1e-05 m: 3.9e+10 cells, more than 268435456 (raise "
				  "[gridvector_occupancy] resolution, or check the vectors' extent)");
	}
	opt.resolution = 0.1;
	opt.margin = 1e9;
	EXPECT_THROW(OccupancyConversion::toOccupancyGrid(m, opt), std::runtime_error);
	EXPECT_THROW(OccupancyConversion::rasterise(m, opt), std::runtime_error);
	// the sample points count too: 20 x 20 cells with 10^4 x 10^4 samples each
	EXPECT_THROW(OccupancyConversion::rasterise(m, 0, 0, 0.1, 20, 20, 10000), std::runtime_error);
	opt.margin = 0.5;
	EXPECT_NO_THROW(OccupancyConversion::toOccupancyGrid(m, opt));
}
