// Sec. 3.2: the three correspondence criteria.
#include "map/Correspondence.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace gridvector;
using mrpt::math::TPoint2D;

namespace
{
GridVector vec(double x1, double y1, double x2, double y2) { return GridVector({x1, y1}, {x2, y2}, GridOptions{}); }
TPoint2D rot(const TPoint2D& p, double a, const TPoint2D& c)
{
	const double dx = p.x - c.x, dy = p.y - c.y;
	return {c.x + std::cos(a) * dx - std::sin(a) * dy, c.y + std::sin(a) * dx + std::cos(a) * dy};
}
}  // namespace

TEST(Correspondence, CollinearOverlappingMatch)
{
	const MapOptions o;
	EXPECT_TRUE(corresponds(vec(0, 0, 2, 0), vec(1, 0, 3, 0), o));
	EXPECT_TRUE(corresponds(vec(0, 0, 2, 0), vec(0.5, 0.1, 1.5, 0.1), o));  // 10 cm apart
}

TEST(Correspondence, OppositeDirectionsNeverMatch)
{
	const MapOptions o;
	// the two faces of a thin wall: same line, open space on different sides
	EXPECT_FALSE(corresponds(vec(0, 0, 2, 0), vec(2, 0, 0, 0), o));
	MapOptions loose;
	loose.maxDirectionDiffDeg = 360;
	loose.maxThetaDiffDeg = 360;
	EXPECT_FALSE(corresponds(vec(0, 0, 2, 0), vec(2, 0, 0, 0), loose));
}

TEST(Correspondence, Criterion1And2Angle)
{
	const MapOptions o;  // 10 deg
	const TPoint2D c(1, 0);
	auto rotated = [&](double deg) {
		const TPoint2D s = rot({0, 0}, deg * M_PI / 180, c), e = rot({2, 0}, deg * M_PI / 180, c);
		return GridVector(s, e, GridOptions{});
	};
	EXPECT_TRUE(corresponds(vec(0, 0, 2, 0), rotated(8), o));
	EXPECT_FALSE(corresponds(vec(0, 0, 2, 0), rotated(12), o));
	const auto t = testCorrespondence(vec(0, 0, 2, 0), rotated(8), o);
	EXPECT_NEAR(t.dPsi, 8 * M_PI / 180, 1e-9);
	EXPECT_NEAR(t.dTheta, 8 * M_PI / 180, 1e-9);
}

TEST(Correspondence, Criterion2Offset)
{
	const MapOptions o;  // 0.15 m
	EXPECT_TRUE(corresponds(vec(0, 0, 2, 0), vec(0, 0.14, 2, 0.14), o));
	EXPECT_FALSE(corresponds(vec(0, 0, 2, 0), vec(0, 0.16, 2, 0.16), o));
	EXPECT_NEAR(testCorrespondence(vec(0, 0, 2, 0), vec(0, 0.14, 2, 0.14), o).dRho, 0.14, 1e-12);
}

TEST(Correspondence, Criterion3CentreDistance)
{
	const MapOptions o;
	// centres 2.9 apart, half the summed lengths 3: match; 3.1 apart: no
	EXPECT_TRUE(corresponds(vec(0, 0, 3, 0), vec(2.9, 0, 5.9, 0), o));
	EXPECT_FALSE(corresponds(vec(0, 0, 3, 0), vec(3.1, 0, 6.1, 0), o));
	EXPECT_FALSE(corresponds(vec(0, 0, 3, 0), vec(3.0, 0, 6.0, 0), o));  // touching ends: strict
}

TEST(Correspondence, IndependentOfWhereTheWorldOriginIs)
{
	// Two pieces of one wall 1 km from the origin, 3 deg apart: locally 2 cm apart.
	const MapOptions o;
	const TPoint2D c(1000, 0);
	const GridVector a({1000, -1}, {1000, 1}, GridOptions{});
	const GridVector b(rot({1000, -1}, 3 * M_PI / 180, c), rot({1000, 1}, 3 * M_PI / 180, c), GridOptions{});
	EXPECT_TRUE(corresponds(a, b, o));
	// rho from the world origin would differ by ~1000 * (1 - cos 3deg) ... and far more off-axis
	EXPECT_GT(std::abs(a.line().rho - b.line().rho), 0.15);
}

TEST(Correspondence, SearchMarginGrowsWithLength)
{
	const MapOptions o;
	EXPECT_NEAR(correspondenceSearchMargin(0, o), o.maxRhoDiff, 1e-12);
	EXPECT_GT(correspondenceSearchMargin(10, o), correspondenceSearchMargin(1, o));
}

TEST(Correspondence, CheapRejectionsDecideAsTheFullTest)
{
	// corresponds() rejects on cosines and squared distances before the full
	// test: on random pairs near each other both decide the same.
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> X(-3, 3), L(0.2, 4), A(-M_PI, M_PI), dA(-0.3, 0.3), off(-0.3, 0.3);
	const MapOptions o;
	int matches = 0;
	for (int i = 0; i < 20000; ++i)
	{
		const double x = X(rng), y = X(rng), a = A(rng), la = L(rng), lb = L(rng);
		const GridVector va = vec(x, y, x + la * std::cos(a), y + la * std::sin(a));
		const double b = a + (i % 7 == 0 ? A(rng) : dA(rng)), s = X(rng) * 0.5, w = off(rng);
		const double bx = x + s * std::cos(a) - w * std::sin(a), by = y + s * std::sin(a) + w * std::cos(a);
		const GridVector vb = vec(bx, by, bx + lb * std::cos(b), by + lb * std::sin(b));
		const bool full = testCorrespondence(va, vb, o).match;
		ASSERT_EQ(corresponds(va, vb, o), full) << i;
		matches += full;
	}
	EXPECT_GT(matches, 1000);
	EXPECT_LT(matches, 19000);
}

TEST(Correspondence, ThetaOfADirectedVectorRepeatsCriterion1)
{
	// Criterion 2's theta is the normal of the directed vector (psi - pi/2):
	// its difference is the difference of the directions, so max_theta_diff_deg
	// decides only where it is below max_direction_diff_deg (doc/paper-fidelity.md).
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> X(-50, 50), A(-M_PI, M_PI), dA(-0.4, 0.4);
	for (int i = 0; i < 1000; ++i)
	{
		const double a = A(rng), b = a + dA(rng), x = X(rng), y = X(rng);
		const auto t = testCorrespondence(vec(x, y, x + 2 * std::cos(a), y + 2 * std::sin(a)),
										  vec(x, y, x + 3 * std::cos(b), y + 3 * std::sin(b)), MapOptions{});
		ASSERT_NEAR(t.dTheta, t.dPsi, 1e-12) << i;
	}
	const TPoint2D c(1, 0);
	const GridVector a = vec(0, 0, 2, 0),
					 b(rot({0, 0}, 7 * M_PI / 180, c), rot({2, 0}, 7 * M_PI / 180, c), GridOptions{});
	MapOptions o;  // both 10 deg: 7 deg apart match
	EXPECT_TRUE(corresponds(a, b, o));
	o.maxThetaDiffDeg = 5;  // below criterion 1's bound: now it decides
	EXPECT_FALSE(corresponds(a, b, o));
	o.maxThetaDiffDeg = 30, o.maxDirectionDiffDeg = 5;  // above it: criterion 1 decides
	EXPECT_FALSE(corresponds(a, b, o));
}
