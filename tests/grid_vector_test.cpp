#include <gridvector/GridVector.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace gridvector;
using mrpt::math::TPoint2D;

namespace
{
GridOptions opts(double res = 0.1, int hw = 1)
{
	GridOptions g;
	g.resolution = res;
	g.halfWidth = hw;
	return g;
}
}  // namespace

TEST(GridVector, DerivedGeometry)
{
	GridVector v(TPoint2D(1, 1), TPoint2D(1, 3), opts());
	EXPECT_NEAR(v.psi(), M_PI / 2, 1e-12);
	EXPECT_NEAR(v.length(), 2.0, 1e-12);
	EXPECT_NEAR(v.centre().x, 1.0, 1e-12);
	EXPECT_NEAR(v.centre().y, 2.0, 1e-12);
	EXPECT_EQ(v.cols(), 20);
	EXPECT_EQ(v.rows(), 3);
	// Normal points right of the direction (+x here): theta = 0, rho = 1.
	EXPECT_NEAR(v.line().theta, 0.0, 1e-12);
	EXPECT_NEAR(v.line().rho, 1.0, 1e-12);
	EXPECT_NEAR(v.leftNormal().x, -1.0, 1e-12);
}

TEST(GridVector, PriorIsHalfOverOne)
{
	GridVector v(TPoint2D(0, 0), TPoint2D(1, 0), opts());
	for (const auto& c : v.cells())
	{
		EXPECT_FLOAT_EQ(c.n_occupy, 0.5f);
		EXPECT_FLOAT_EQ(c.n_visit, 1.0f);
		EXPECT_FLOAT_EQ(c.n_acc, 0.0f);
	}
	EXPECT_NEAR(v.pStatic(), 0.5, 1e-12);
}

TEST(GridVector, Algorithm1CountsAreExact)
{
	GridVector v(TPoint2D(0, 0), TPoint2D(1, 0), opts());
	// Three points in column 2 of the centre row, one in column 7 of the left row, one outside.
	ASSERT_TRUE(v.addEndpoint(TPoint2D(0.21, 0.01)));
	ASSERT_TRUE(v.addEndpoint(TPoint2D(0.25, -0.02)));
	ASSERT_TRUE(v.addEndpoint(TPoint2D(0.29, 0.03)));
	ASSERT_TRUE(v.addEndpoint(TPoint2D(0.75, 0.10)));
	EXPECT_FALSE(v.addEndpoint(TPoint2D(0.5, 0.5)));
	EXPECT_FALSE(v.addEndpoint(TPoint2D(-0.01, 0.0)));
	const GridCell& c = v.cell(1, 2);
	EXPECT_FLOAT_EQ(c.n_acc, 3.f);
	EXPECT_FLOAT_EQ(c.n_occupy, 3.5f);
	EXPECT_FLOAT_EQ(c.n_visit, 4.f);
	const TPoint2D g = v.cellMeanPoint(1, 2);
	EXPECT_NEAR(g.x, 0.25, 1e-6);
	EXPECT_NEAR(g.y, 0.02 / 3, 1e-6);
	EXPECT_FLOAT_EQ(v.cell(2, 7).n_acc, 1.f);
	EXPECT_NEAR(v.cellMeanPoint(2, 7).y, 0.10, 1e-6);
	EXPECT_NEAR(v.totalPoints(), 4.0, 1e-9);
	EXPECT_NEAR(v.totalOccupy(), 0.5 * v.cells().size() + 4, 1e-6);
	EXPECT_NEAR(v.totalVisit(), 1.0 * v.cells().size() + 4, 1e-6);
}

TEST(GridVector, TerminalPointFallsInLastColumn)
{
	GridVector v(TPoint2D(0, 0), TPoint2D(1, 0), opts());
	int r, c;
	ASSERT_TRUE(v.cellOf(TPoint2D(1.0, 0.0), r, c));
	EXPECT_EQ(c, v.cols() - 1);
	EXPECT_EQ(r, 1);
}

TEST(GridVector, ComposeMovesEndpointsAndKeepsGrid)
{
	GridVector v(TPoint2D(1, 0), TPoint2D(2, 0), opts());
	v.addEndpoint(TPoint2D(1.55, 0.0));
	const GridVector m = v.compose(mrpt::math::TPose2D(10, 5, M_PI / 2));
	EXPECT_NEAR(m.start().x, 10, 1e-9);
	EXPECT_NEAR(m.start().y, 6, 1e-9);
	EXPECT_NEAR(m.end().y, 7, 1e-9);
	EXPECT_NEAR(m.psi(), M_PI / 2, 1e-9);
	const TPoint2D g = m.cellMeanPoint(1, 5);
	EXPECT_NEAR(g.x, 10.0, 1e-6);
	EXPECT_NEAR(g.y, 6.55, 1e-6);
	int r, c;
	ASSERT_TRUE(m.cellOf(TPoint2D(10.0, 6.55), r, c));
	EXPECT_EQ(c, 5);
}

TEST(GridVector, ProfileFollowsCounts)
{
	GridVector v(TPoint2D(0, 0), TPoint2D(0.3, 0), opts(0.1, 0));
	v.cell(0, 0).n_occupy = 9.5f, v.cell(0, 0).n_visit = 10.f;
	v.cell(0, 2).n_occupy = 0.5f, v.cell(0, 2).n_visit = 10.f;
	const auto p = v.occupancyProfile();
	ASSERT_EQ(p.size(), 3u);
	EXPECT_NEAR(p[0], 0.95, 1e-6);
	EXPECT_NEAR(p[1], 0.5, 1e-6);
	EXPECT_NEAR(p[2], 0.05, 1e-6);
	EXPECT_NEAR(v.pStatic(), 0.5, 1e-6);
}

TEST(GridVector, FromPartsValidatesCellCount)
{
	EXPECT_THROW(GridVector::fromParts(TPoint2D(0, 0), TPoint2D(1, 0), opts(), 10, {}), std::invalid_argument);
	std::vector<GridCell> cells(30);
	cells[4].n_acc = 2;
	const GridVector v = GridVector::fromParts(TPoint2D(0, 0), TPoint2D(1, 0), opts(), 10, cells);
	EXPECT_FLOAT_EQ(v.cell(0, 4).n_acc, 2.f);
}
