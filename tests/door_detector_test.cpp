// DoorDetector (Sec. 5.4, Fig. 10): hinges from static/dynamic corners.
#include <gridvector/DoorDetector.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace gridvector;
using mrpt::math::TPoint2D;

namespace
{
GridVector vec(double x1, double y1, double x2, double y2, VectorState s)
{
	GridVector v(TPoint2D(x1, y1), TPoint2D(x2, y2), GridOptions{});
	v.state = s;
	return v;
}
constexpr auto S = VectorState::Static;
constexpr auto D = VectorState::Dynamic;
}  // namespace

TEST(DoorDetector, TwoStatesOfOneLeafGiveAHinge)
{
	// wall along x ending at the door frame (3, 0); leaf 0.9 m, seen closed-ish and open
	std::vector<GridVector> v = {vec(0, 0, 3, 0, S), vec(4.0, 0, 6, 0, S),
								 vec(3.02, 0.03, 3.02, 0.92, D),  // open: 90 deg
								 vec(3.01, 0.0, 3.64, 0.64, D),  // half open: 45 deg
								 vec(2, 2, 2.2, 2.1, D)};  // a person: no corner
	DoorDetector det;
	const auto doors = det.detect(v);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_NEAR(doors[0].hinge.x, 3.0, 0.05);
	EXPECT_NEAR(doors[0].hinge.y, 0.0, 0.05);
	EXPECT_NEAR(doors[0].length, 0.9, 0.05);
	ASSERT_EQ(doors[0].angles.size(), 2u);
	EXPECT_NEAR(doors[0].angles[0], M_PI / 4, 0.05);
	EXPECT_NEAR(doors[0].angles[1], M_PI / 2, 0.05);
	EXPECT_EQ(doors[0].wall, 0u);
}

TEST(DoorDetector, CornersNeedAStaticAndADynamicVector)
{
	const std::vector<GridVector> v = {vec(0, 0, 3, 0, S), vec(3, 0, 3, 0.9, S), vec(3, 0, 3.64, 0.64, D)};
	const auto cs = DoorDetector().corners(v);
	ASSERT_EQ(cs.size(), 2u);  // the dynamic vector with each static one; never static-static
	for (const auto& c : cs)
	{
		EXPECT_EQ(c.leaf, 2u);
		EXPECT_NE(c.wall, 2u);
		EXPECT_NEAR(c.leafAngle, M_PI / 4, 1e-6);
		EXPECT_NEAR(c.vertex.x, 3.0, 1e-9);
	}
}

TEST(DoorDetector, UnequalLeavesOrOneStateAreNoDoor)
{
	DoorDetector det;
	// one state only
	EXPECT_TRUE(det.detect({vec(0, 0, 3, 0, S), vec(3, 0, 3, 0.9, D)}).empty());
	// two leaves of different lengths at the same vertex
	EXPECT_TRUE(det.detect({vec(0, 0, 3, 0, S), vec(3, 0, 3, 0.7, D), vec(3, 0, 4.1, 1.1, D)}).empty());
	// two equal leaves in the same direction: one state
	EXPECT_TRUE(det.detect({vec(0, 0, 3, 0, S), vec(3, 0, 3, 0.9, D), vec(3.02, 0, 3.02, 0.9, D)}).empty());
	// vertices too far apart
	EXPECT_TRUE(det.detect({vec(0, 0, 3, 0, S), vec(3, 0, 3, 0.9, D), vec(0, 0, 0.64, 0.64, D)}).empty());
}
