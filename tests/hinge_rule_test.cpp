// HingeRule (Sec. 5.4, Fig. 10): the paper's corners and hinge, nothing beyond it.
#include "doors/HingeRule.h"

#include <gtest/gtest.h>

#include "door_vectors.h"

#include <cmath>

using namespace gridvector;
using namespace gridvector::doors;
using gvtest::D;
using gvtest::S;
using gvtest::vec;
using mrpt::math::TPoint2D;

namespace
{

Corner corner(size_t wall, size_t leaf, TPoint2D vertex, double angle, double length, bool dynamic = true)
{
	Corner c;
	c.wall = wall, c.leaf = leaf, c.vertex = vertex, c.leafAngle = angle, c.leafLength = length;
	c.dynamicLeaf = dynamic;
	return c;
}
}  // namespace

TEST(HingeRule, ACandidateHasDoorLength)
{
	// min_door_length 0.6, max_door_length 1.4, max_length_diff 0.25 (a leaf seen in part or merged long)
	const HingeRule rule{DoorOptions{}};
	EXPECT_FALSE(rule.isCandidate(vec(0, 0, 0.34, 0, D)));
	EXPECT_TRUE(rule.isCandidate(vec(0, 0, 0.36, 0, D)));
	EXPECT_TRUE(rule.isCandidate(vec(0, 0, 1.64, 0, S)));
	EXPECT_FALSE(rule.isCandidate(vec(0, 0, 1.66, 0, D)));
}

TEST(HingeRule, ACornerIsAWallAndACandidateMeetingAtTheirEnds)
{
	const HingeRule rule{DoorOptions{}};
	// the candidate's nearer end (0.22 m from the wall's end) is the vertex, either way round
	for (const bool reversed : {false, true})
	{
		const std::vector<GridVector> v = {vec(0, 0, 3, 0, S),
										   reversed ? vec(3.2, 1.0, 3.2, 0.1, D) : vec(3.2, 0.1, 3.2, 1.0, D)};
		const auto c = rule.meetingEnds(v, 0, 1);
		ASSERT_TRUE(c.has_value());
		EXPECT_EQ(c->wall, 0u);
		EXPECT_EQ(c->leaf, 1u);
		EXPECT_TRUE(c->dynamicLeaf);
		EXPECT_EQ(c->vertex, TPoint2D(3.2, 0.1));
		EXPECT_EQ(c->tip, TPoint2D(3.2, 1.0));
		EXPECT_NEAR(c->leafAngle, M_PI / 2, 1e-12);
		EXPECT_NEAR(c->leafLength, 0.9, 1e-12);
		EXPECT_TRUE(rule.turns(*c, v[0]));
	}
	// ends 0.36 m apart (max_corner_gap 0.3): no corner
	EXPECT_FALSE(rule.meetingEnds({vec(0, 0, 3, 0, S), vec(3.2, 0.3, 3.2, 1.2, D)}, 0, 1).has_value());
	// the two borders must turn by min_corner_angle_deg (10): 5 deg does not, 15 deg does
	for (const double deg : {5.0, 15.0})
	{
		const double a = deg * M_PI / 180;
		const std::vector<GridVector> v = {vec(0, 0, 3, 0, S), vec(3, 0, 3 + 0.9 * std::cos(a), 0.9 * std::sin(a), D)};
		const auto c = rule.meetingEnds(v, 0, 1);
		ASSERT_TRUE(c.has_value());
		EXPECT_EQ(rule.turns(*c, v[0]), deg > 10);
	}
}

TEST(HingeRule, CornersOfOneDoorShareTheWallACloseVertexAndTheLeafLength)
{
	const HingeRule rule{DoorOptions{}};  // max_vertex_distance 0.25, max_length_diff 0.25
	const Corner a = corner(0, 1, TPoint2D(3, 0), M_PI / 2, 0.9);
	EXPECT_TRUE(rule.sameDoor(a, corner(0, 2, TPoint2D(3.2, 0), M_PI / 4, 1.1)));
	EXPECT_FALSE(rule.sameDoor(a, corner(3, 2, TPoint2D(3, 0), M_PI / 4, 0.9)));  // another wall
	EXPECT_FALSE(rule.sameDoor(a, corner(0, 2, TPoint2D(3.3, 0), M_PI / 4, 0.9)));  // vertices 0.3 m apart
	EXPECT_FALSE(rule.sameDoor(a, corner(0, 2, TPoint2D(3, 0), M_PI / 4, 1.2)));  // leaves 0.3 m apart
}

TEST(HingeRule, TwoDistinctStatesOneOfThemDynamicMakeAHinge)
{
	const HingeRule rule{DoorOptions{}};  // min_state_diff_deg 10
	const std::vector<Corner> cs = {corner(0, 1, TPoint2D(3, 0), 0.50, 0.9),
									corner(0, 2, TPoint2D(3, 0), 0.55, 0.9, false),
									corner(0, 3, TPoint2D(3, 0), 1.00, 0.9, false)};
	// 0.55 rad is within 10 deg of 0.5 rad: one state
	EXPECT_EQ(rule.distinctStates(cs, {0, 1, 2}), (std::vector<double>{0.50, 1.00}));
	EXPECT_EQ(rule.distinctStates(cs, {1, 0}), (std::vector<double>{0.55}));
	EXPECT_TRUE(rule.isHinge(cs, {0, 2}, rule.distinctStates(cs, {0, 2})));
	EXPECT_FALSE(rule.isHinge(cs, {0, 1}, rule.distinctStates(cs, {0, 1})));  // one state
	EXPECT_FALSE(rule.isHinge(cs, {1, 2}, rule.distinctStates(cs, {1, 2})));  // no dynamic candidate
}

TEST(HingeRule, TheHingeIsTheVerticesMeanAndTheLeafTheLengthsMean)
{
	const HingeRule rule{DoorOptions{}};
	const std::vector<Corner> cs = {corner(4, 1, TPoint2D(3, 0), 0.3, 0.8), corner(4, 2, TPoint2D(3.1, 0.1), 1.2, 1.0)};
	const Door d = rule.hingeOf(cs, {0, 1});
	EXPECT_NEAR(d.hinge.x, 3.05, 1e-12);
	EXPECT_NEAR(d.hinge.y, 0.05, 1e-12);
	EXPECT_NEAR(d.length, 0.9, 1e-12);
	EXPECT_EQ(d.wall, 4u);
	EXPECT_EQ(d.leaves, (std::vector<size_t>{1, 2}));
	EXPECT_TRUE(d.angles.empty());
	EXPECT_TRUE(rule.hasDoorLength(d));
	Door shortLeaf = d, longLeaf = d;
	shortLeaf.length = 0.59, longLeaf.length = 1.41;
	EXPECT_FALSE(rule.hasDoorLength(shortLeaf));
	EXPECT_FALSE(rule.hasDoorLength(longLeaf));
}
