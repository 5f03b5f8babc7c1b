#include <gridvector/LineFit.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace gridvector;
using mrpt::math::TPoint2D;

TEST(LineFit, RecoversThetaRhoOfNoiselessLine)
{
	// Line x cos(0.3) + y sin(0.3) = 2.
	const double th = 0.3, rho = 2.0;
	LineMoments m;
	for (int i = -10; i <= 10; ++i)
	{
		const double s = i * 0.1;
		m.add(rho * std::cos(th) - s * std::sin(th), rho * std::sin(th) + s * std::cos(th));
	}
	Line2D l;
	ASSERT_TRUE(m.fit(l));
	EXPECT_NEAR(l.theta, th, 1e-9);
	EXPECT_NEAR(l.rho, rho, 1e-9);
	EXPECT_NEAR(m.residual(l), 0.0, 1e-9);
}

TEST(LineFit, RhoIsNonNegativeAndProjectionLiesOnLine)
{
	LineMoments m;
	for (int i = 0; i < 5; ++i) m.add(-1.0 + 0.5 * i, -3.0);  // y = -3
	Line2D l;
	ASSERT_TRUE(m.fit(l));
	EXPECT_GE(l.rho, 0.0);
	EXPECT_NEAR(l.rho, 3.0, 1e-9);
	const TPoint2D p = l.project(TPoint2D(0.7, 1.0));
	EXPECT_NEAR(p.x, 0.7, 1e-9);
	EXPECT_NEAR(p.y, -3.0, 1e-9);
	EXPECT_NEAR(l.distance(p), 0.0, 1e-12);
}

TEST(LineFit, WeightsDownweightOutliers)
{
	LineMoments heavy, light;
	for (int i = 0; i < 10; ++i) heavy.add(i * 0.1, 1.0, 1.0), light.add(i * 0.1, 1.0, 1.0);
	heavy.add(0.5, 1.5, 1.0);  // outlier at full weight
	light.add(0.5, 1.5, 0.01);  // same outlier nearly ignored
	Line2D lh, ll;
	ASSERT_TRUE(heavy.fit(lh));
	ASSERT_TRUE(light.fit(ll));
	EXPECT_GT(std::abs(lh.rho - 1.0), std::abs(ll.rho - 1.0));
	EXPECT_NEAR(ll.rho, 1.0, 0.01);
}

TEST(LineFit, PrefixMomentsMatchDirectSums)
{
	std::vector<TPoint2D> pts;
	for (int i = 0; i < 20; ++i) pts.emplace_back(i * 0.3, std::sin(i * 0.7));
	PrefixMoments pm(pts);
	LineMoments direct;
	for (int i = 5; i < 14; ++i) direct.add(pts[size_t(i)].x, pts[size_t(i)].y);
	const LineMoments r = pm.range(5, 14);
	EXPECT_NEAR(r.w, direct.w, 1e-12);
	EXPECT_NEAR(r.sxy, direct.sxy, 1e-9);
	EXPECT_NEAR(r.syy, direct.syy, 1e-9);
}

TEST(LineFit, DegenerateInputIsRejected)
{
	LineMoments m;
	Line2D l;
	EXPECT_FALSE(m.fit(l));
	m.add(1, 1);
	m.add(1, 1);
	EXPECT_FALSE(m.fit(l));
}
