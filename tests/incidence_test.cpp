// Incidence of the beams that saw a vector (mstep.register_min_incidence_deg).
#include "mstep/Incidence.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gridvector;

namespace
{
MatchSegment segment(double x1, double y1, double x2, double y2, uint64_t id = 0)
{
	MatchSegment m;
	m.s = {x1, y1};
	m.e = {x2, y2};
	m.length = (m.e - m.s).norm();
	m.id = id;
	return m;
}
double deg(double rad) { return rad * 180 / M_PI; }
}  // namespace

// A wall 0.46 m beside the sensor seen from 1.58 m to 2.58 m ahead (intel seed 8, scan 319's view of the wall it
// puts 0.3 m behind where the scans facing it do): every beam meets it under 16.3 deg or less, the largest at the
// near end; the same wall seen from in front (6.4 m away, its foot inside) is met square.
TEST(Incidence, LargestAtThePointNearestTheSensor)
{
	EXPECT_NEAR(deg(largestIncidence(segment(2.58, 0.46, 1.58, 0.46))), deg(std::asin(0.46 / std::hypot(1.58, 0.46))), 1e-9);
	EXPECT_NEAR(deg(largestIncidence(segment(1.58, 0.46, 2.58, 0.46))), 16.23, 0.01);  // either direction
	EXPECT_NEAR(deg(largestIncidence(segment(6.4, -0.5, 6.4, 0.5))), 90.0, 1e-9);  // foot of the perpendicular inside
	EXPECT_NEAR(deg(largestIncidence(segment(4, 4, 3, 3))), 0.0, 1e-9);  // on a line through the sensor: a beam's own
}

TEST(Incidence, FacingVectorsKeepsThoseSomeBeamMetSteeperThanTheLimit)
{
	const std::vector<std::vector<MatchSegment>> scans = {
		{segment(1.58, 0.46, 2.58, 0.46, 1), segment(6.4, -0.5, 6.4, 0.5, 2)}, {}, {segment(2.0, 1.0, 3.0, 1.0, 3)}};
	const auto at15 = facingVectors(scans, 15.0);
	ASSERT_EQ(at15.size(), 3u);
	ASSERT_EQ(at15[0].size(), 2u);  // 16.2 deg and 90 deg
	EXPECT_TRUE(at15[1].empty());
	ASSERT_EQ(at15[2].size(), 1u);  // 26.6 deg
	const auto at20 = facingVectors(scans, 20.0);
	ASSERT_EQ(at20[0].size(), 1u);
	EXPECT_EQ(at20[0][0].id, 2u);
	EXPECT_EQ(at20[2].size(), 1u);
	EXPECT_EQ(facingVectors(scans, 30.0)[2].size(), 0u);
}
