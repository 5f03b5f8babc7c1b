// DoorDetector (Sec. 5.4, Fig. 10): the paper's hinges and the rules beyond it, applied in order.
#include "doors/DoorDetector.h"

#include <gtest/gtest.h>

#include "door_vectors.h"

#include <algorithm>
#include <cmath>

using namespace gridvector;
using gvtest::D;
using gvtest::S;
using gvtest::vec;
using mrpt::math::TPoint2D;

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
	// the wall's ends as detected (EmSlam may cut the wall afterwards)
	EXPECT_EQ(doors[0].wallStart, TPoint2D(0, 0));
	EXPECT_EQ(doors[0].wallEnd, TPoint2D(3, 0));
}

TEST(DoorDetector, CornersNeedAStaticWallAndADoorLengthCandidate)
{
	const std::vector<GridVector> v = {vec(0, 0, 3, 0, S), vec(3, 0, 3, 0.9, S), vec(3, 0, 3.64, 0.64, D)};
	const auto cs = DoorDetector().corners(v);
	// the dynamic vector with each static one, and the static 0.9 m vector with the 3 m wall
	// (a static state of door length); the 3 m wall is no leaf
	ASSERT_EQ(cs.size(), 3u);
	size_t dynamicCorners = 0;
	for (const auto& c : cs)
	{
		EXPECT_NE(c.wall, c.leaf);
		EXPECT_NE(c.leaf, 0u);
		EXPECT_NEAR(c.vertex.x, 3.0, 1e-9);
		if (!c.dynamicLeaf) continue;
		++dynamicCorners;
		EXPECT_EQ(c.leaf, 2u);
		EXPECT_NEAR(c.leafAngle, M_PI / 4, 1e-6);
	}
	EXPECT_EQ(dynamicCorners, 2u);
	// a static vector continuing the wall's line is the wall, not a corner
	EXPECT_TRUE(DoorDetector().corners({vec(0, 0, 3, 0, S), vec(3.05, 0, 3.95, 0, S)}).empty());
}

TEST(DoorDetector, ClosedDynamicStateAndStaticOpenStateGiveADoor)
{
	// the doorway (3, 0)-(3.9, 0) in a wall; the closed leaf was seen through (dynamic),
	// the open leaf never (static by Eq. 6): both are states of the door hinged at (3, 0)
	const std::vector<GridVector> v = {vec(0, 0, 3, 0, S), vec(3.9, 0, 6, 0, S), vec(3.02, 0, 3.88, 0, D),
									   vec(3.0, 0.02, 3.0, 0.9, S)};
	const auto doors = DoorDetector().detect(v);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_NEAR(doors[0].hinge.x, 3.0, 0.05);
	EXPECT_NEAR(doors[0].hinge.y, 0.0, 0.05);
	EXPECT_EQ(doors[0].wall, 0u);
	ASSERT_EQ(doors[0].angles.size(), 2u);
	EXPECT_NEAR(doors[0].angles[0], 0.0, 0.05);
	EXPECT_NEAR(doors[0].angles[1], M_PI / 2, 0.05);
	std::vector<size_t> leaves = doors[0].leaves;
	std::sort(leaves.begin(), leaves.end());
	EXPECT_EQ(leaves, (std::vector<size_t>{2, 3}));
}

TEST(DoorDetector, StaticStatesAloneAreNoDoor)
{
	// two static door-length vectors at a wall end: no dynamic candidate (Sec. 5.4)
	EXPECT_TRUE(DoorDetector().detect({vec(0, 0, 3, 0, S), vec(3, 0, 3, 0.9, S), vec(3, 0, 3.64, 0.64, S)}).empty());
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

TEST(DoorDetector, ClosedLeafReachingIntoTheWallStartsAtTheWallEnd)
{
	// the merged wall overshoots the hinge (3, 0) by 0.2 m and the merged closed state
	// reaches 0.1 m into the wall and 0.2 m beyond the leaf: measured from the wall's end
	// it is 0.9 m, like the open state
	const std::vector<GridVector> v = {vec(0, 0, 3.2, 0, S), vec(3.1, 0, 4.3, 0, D), vec(3.0, 0, 3.0, -0.9, S)};
	const auto doors = DoorDetector().detect(v);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_NEAR(doors[0].hinge.x, 3.1, 0.05);
	EXPECT_NEAR(doors[0].hinge.y, 0.0, 0.05);
	EXPECT_NEAR(doors[0].length, 1.0, 0.05);
	ASSERT_EQ(doors[0].angles.size(), 2u);
	EXPECT_NEAR(doors[0].angles[0], -M_PI / 2, 0.1);
	EXPECT_NEAR(doors[0].angles[1], 0.0, 0.05);
}

TEST(DoorDetector, ClosedLeafReachingFarIntoTheWallStartsAtTheWallEnd)
{
	// gv-sim long-corridor seed 3, door 3 (hinge about (15.0, -1.29) in the map, leaf 0.9 m;
	// vectors as gv-em-slam's final map has them): both walls reach into the doorway (the door
	// was closed most of the run) and the merged closed state reaches 0.34 m back into the wall,
	// more than doors.max_corner_gap; from the wall's end it is 0.96 m, like the 0.93 m open
	// state (static: never seen through after the door closed). The closed state's end inside the
	// wall (1.30 m from its tip) is no hinge here.
	const std::vector<GridVector> v = {
		vec(11.0021, -1.2979, 15.1457, -1.2984, S),  // the wall, 0.15 m into the doorway
		vec(15.6776, -1.2997, 17.3252, -1.2968, S),  // the latch-side wall, also in the doorway
		vec(14.8032, -1.2972, 16.1039, -1.2974, D),  // the closed state, 1.30 m
		vec(15.0003, -1.2711, 15.1447, -2.1892, S),  // the open state, -81 deg
		vec(14.9410, -1.0438, 14.6426, -0.7230, D),  // people in the corridor
		vec(15.4063, -0.7215, 16.0149, -0.6025, D)};
	const auto doors = DoorDetector().detect(v);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_NEAR(doors[0].hinge.x, 15.0, 0.1);
	EXPECT_NEAR(doors[0].hinge.y, -1.29, 0.05);
	EXPECT_NEAR(doors[0].length, 0.94, 0.05);
	ASSERT_EQ(doors[0].angles.size(), 2u);
	EXPECT_NEAR(doors[0].angles[0], -81.1 * M_PI / 180, 0.05);
	EXPECT_NEAR(doors[0].angles[1], 0.0, 0.05);
	EXPECT_EQ(doors[0].wall, 0u);
	// the closed state is one of its leaves, so EmSlam makes it and the open state dynamic
	EXPECT_NE(std::find(doors[0].leaves.begin(), doors[0].leaves.end(), 2u), doors[0].leaves.end());
	EXPECT_NE(std::find(doors[0].leaves.begin(), doors[0].leaves.end(), 3u), doors[0].leaves.end());
	// corridor-loop seed 4, door 0 (hinge about (4.50, -1.20)): the wall reaches 0.31 m into the
	// doorway but the closed state starts at the hinge: its end inside the wall is the hinge
	const std::vector<GridVector> w = {vec(-1.2115, -1.1996, 4.8066, -1.2009, S),  // the wall
									   vec(5.1907, -1.1999, 18.8076, -1.2015, S),  // the latch-side wall
									   vec(4.4987, -1.1991, 5.4100, -1.1993, D),  // the closed state, 0.91 m
									   vec(4.5293, -1.1772, 5.0851, -1.9201, S)};  // the open state, -53 deg
	const auto doors4 = DoorDetector().detect(w);
	ASSERT_EQ(doors4.size(), 1u);
	EXPECT_NEAR(doors4[0].hinge.x, 4.51, 0.05);
	EXPECT_NEAR(doors4[0].length, 0.92, 0.05);
	EXPECT_EQ(doors4[0].angles.size(), 2u);
}

TEST(DoorDetector, HingeInsideAWallMergedAcrossTheDoorway)
{
	// the wall was merged across the doorway (the door closed most of the time): the closed
	// state (dynamic) lies on the wall, the open state (static) leaves the wall's interior
	const std::vector<GridVector> v = {vec(0, 0, 6, 0, S), vec(3.0, 0, 4.1, 0, D), vec(3.0, 0.9, 3.0, 0.01, S),
									   vec(1.5, 0.05, 1.5, 0.35, D)};  // a person by the wall: no door
	const DoorDetector det;
	const auto doors = det.detect(v);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_NEAR(doors[0].hinge.x, 3.0, 0.05);
	EXPECT_NEAR(doors[0].hinge.y, 0.0, 0.05);
	ASSERT_EQ(doors[0].angles.size(), 2u);
	// the closed state on the wall: that stretch of the wall belongs to the door
	const auto spans = det.stateSpans(doors, v[0]);
	ASSERT_EQ(spans.size(), 1u);
	EXPECT_NEAR(spans[0].first, 3.0, 0.05);
	EXPECT_NEAR(spans[0].second, 3.0 + doors[0].length, 0.05);
	EXPECT_TRUE(det.stateSpans(doors, vec(0, 0.3, 6, 0.3, S)).empty());  // a parallel wall 0.3 m away
	EXPECT_TRUE(det.stateSpans(doors, vec(5, 0, 8, 0, S)).empty());  // the same line, past the leaf
	// one state alone inside a wall is no door; the open state ending off the wall's line (more
	// than kMaxWallOffset) makes no T corner: no door either
	EXPECT_TRUE(det.detect({vec(0, 0, 6, 0, S), vec(3.0, 0, 4.1, 0, D)}).empty());
	std::vector<GridVector> off = v;
	off[2] = vec(3.0, 0.9 + 0.12, 3.0, 0.12, S);
	EXPECT_TRUE(det.detect(off).empty());
}

TEST(DoorDetector, VectorsFromTheHingeIntoTheSweptArcJoinTheDoor)
{
	DoorOptions o;
	o.maxCornerGap = 0.1;  // the extra leaves below make no corner with the wall
	const std::vector<GridVector> v = {
		vec(0, 0, 3, 0, S),
		vec(3, 0, 3.9, 0, D),
		vec(3, 0, 3, 0.9, S),  // wall, closed and open states
		vec(3.15, 0.05, 3.93, 0.5, S),  // opened to 30 deg once: 0.16 m from the hinge
		vec(3.15, -0.05, 3.15, -0.95, S),  // from the hinge but away from the swept arc
		vec(3.1, 0.1, 3.4, 0.5, S),  // a leaf seen in part (0.5 m, at 53 deg): part of a state
		vec(3.0, 0.1, 3.0, 1.5, S)};  // longer than the leaf: a wall, not a state
	const auto doors = DoorDetector(o).detect(v);
	ASSERT_EQ(doors.size(), 1u);
	std::vector<size_t> leaves = doors[0].leaves;
	std::sort(leaves.begin(), leaves.end());
	EXPECT_EQ(leaves, (std::vector<size_t>{1, 2, 3, 5}));
	EXPECT_EQ(doors[0].angles.size(), 3u);  // the part is no state of its own
}

TEST(DoorDetector, AWholeLeafJoinsADoorFoundFromLeavesSeenInPart)
{
	// the corners that found the door are leaves seen in part (0.55 and 0.75 m; their mean is
	// 0.65 m); the whole open leaf (0.92 m, static) lies beyond that mean + max_length_diff
	// but within the longest corner leaf's reach: it is a state too
	const std::vector<GridVector> v = {
		vec(0, 0, 3, 0, S), vec(3.9, 0, 6, 0, S),  // the walls either side of the doorway
		vec(3, 0, 3 + 0.55 * std::cos(M_PI / 6), 0.55 * std::sin(M_PI / 6), D),  // 30 deg, in part
		vec(3, 0, 3 + 0.75 * std::cos(M_PI / 3), 0.75 * std::sin(M_PI / 3), D),  // 60 deg, in part
		vec(3, 0, 3 + 0.92 * std::cos(85 * M_PI / 180), 0.92 * std::sin(85 * M_PI / 180), S)};  // whole, 85 deg
	const auto doors = DoorDetector().detect(v);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_NEAR(doors[0].length, 0.65, 1e-6);
	std::vector<size_t> leaves = doors[0].leaves;
	std::sort(leaves.begin(), leaves.end());
	EXPECT_EQ(leaves, (std::vector<size_t>{2, 3, 4}));
	EXPECT_EQ(doors[0].angles.size(), 3u);
}

namespace
{
GridVector polarVec(double x, double y, double fromHinge, double len, double deg, VectorState s)
{
	const double c = std::cos(deg * M_PI / 180), sn = std::sin(deg * M_PI / 180);
	return vec(x + fromHinge * c, y + fromHinge * sn, x + (fromHinge + len) * c, y + (fromHinge + len) * sn, s);
}
}  // namespace

TEST(DoorDetector, ADynamicPieceAndItsCollinearStaticPieceAreOneLeaf)
{
	// the open leaf (-70 deg) was split by Fig. 4: 0.3 m dynamic at the hinge, the rest static
	std::vector<GridVector> v = {vec(0, 0, 3, 0, S), vec(3.9, 0, 6, 0, S), vec(3, 0, 3.9, 0, D),
								 polarVec(3, 0, 0, 0.3, -70, D), polarVec(3, 0, 0.32, 0.58, -70, S)};
	auto doors = DoorDetector().detect(v);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_EQ(doors[0].leaves, (std::vector<size_t>{2, 3, 4}));  // the chain's leaves are its pieces
	ASSERT_EQ(doors[0].angles.size(), 2u);
	EXPECT_NEAR(doors[0].angles[0], -70 * M_PI / 180, 0.03);
	// two dynamic pieces in a line are no leaf (people's tracks): no second state, no door
	v[4].state = D;
	EXPECT_TRUE(DoorDetector().detect(v).empty());
}

TEST(DoorDetector, AStaticLeafActingAsTheWallIsAStateAndTheLongWallIsTheDoorsWall)
{
	// a wall merged across the doorway runs through the hinge (0, 0), the closed leaf inside
	// it (+y); open states at 15 deg (static: Eq. 6 kept it), 33 and 52 deg (dynamic). The T
	// corners on the long wall have no state along it; the 15 deg leaf is the others' wall
	const std::vector<GridVector> v = {vec(0, -2, 0, 3, S), polarVec(0, 0, 0, 0.82, 15, S),
									   polarVec(0, 0, 0, 0.84, 52, D), polarVec(0, 0, 0, 0.87, 33, D)};
	const auto doors = DoorDetector().detect(v);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_EQ(doors[0].wall, 0u);
	EXPECT_EQ(doors[0].wallStart, TPoint2D(0, -2));  // the long wall's ends, not the short leaf's
	EXPECT_EQ(doors[0].wallEnd, TPoint2D(0, 3));
	std::vector<size_t> leaves = doors[0].leaves;
	std::sort(leaves.begin(), leaves.end());
	EXPECT_EQ(leaves, (std::vector<size_t>{1, 2, 3}));
	EXPECT_EQ(doors[0].angles.size(), 3u);
}

TEST(DoorDetector, TheClosedLeafInsideAWallMergedAcrossTheDoorwayIsDynamic)
{
	// as above: the wall runs through the hinge and on past it on the states' side (+y), no
	// state lies along it: the closed leaf is inside the wall, from the hinge up one leaf length
	const std::vector<GridVector> v = {vec(0, -2, 0, 3, S), polarVec(0, 0, 0, 0.82, 15, S),
									   polarVec(0, 0, 0, 0.84, 52, D), polarVec(0, 0, 0, 0.87, 33, D)};
	const DoorDetector det;
	const auto doors = det.detect(v);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_TRUE(doors[0].closedInWall);
	EXPECT_NEAR(doors[0].closedAngle, M_PI / 2, 1e-6);
	EXPECT_EQ(doors[0].angles.size(), 3u);  // no state seen: not among the angles
	const auto spans = det.stateSpans(doors, v[0]);
	ASSERT_EQ(spans.size(), 1u);
	EXPECT_NEAR(spans[0].first, 2.0, 0.03);
	EXPECT_NEAR(spans[0].second, 2.0 + doors[0].length, 0.03);
	// a wall ending at the hinge (the doorway beyond it) holds no closed leaf
	const std::vector<GridVector> atEnd = {vec(0, 0, 3, 0, S), vec(4.0, 0, 6, 0, S), vec(3.02, 0.03, 3.02, 0.92, D),
										   vec(3.01, 0.0, 3.64, 0.64, D)};
	const auto d2 = det.detect(atEnd);
	ASSERT_EQ(d2.size(), 1u);
	EXPECT_FALSE(d2[0].closedInWall);
}

TEST(DoorDetector, TheSweptArcRunsFromTheWallsLineThroughTheStates)
{
	// states -45 and -79 deg, the closed state not among them: the arc runs from the wall's
	// line (0 deg) through them, so a leaf at -5 deg (its end 0.22 m from the hinge: no corner)
	// is a state, one at -150 deg is not
	DoorOptions o;
	o.maxCornerGap = 0.1;
	const std::vector<GridVector> v = {vec(0, 0, 3, 0, S), polarVec(3, 0, 0, 0.9, -45, D),
									   polarVec(3, 0, 0, 0.85, -79, D), polarVec(3, 0, 0.22, 0.8, -5, S),
									   polarVec(3, 0, 0.22, 0.8, -150, S)};
	const auto doors = DoorDetector(o).detect(v);
	ASSERT_EQ(doors.size(), 1u);
	std::vector<size_t> leaves = doors[0].leaves;
	std::sort(leaves.begin(), leaves.end());
	EXPECT_EQ(leaves, (std::vector<size_t>{1, 2, 3}));
}

TEST(DoorDetector, LeavesMakeNoSecondDoorAtTheLatchSide)
{
	// the closed and a slightly open state also meet the wall on the latch side (3.9, 0) with
	// their tips: that is no second hinge, their leaves belong to the door hinged at (3, 0)
	const std::vector<GridVector> v = {vec(0, 0, 3, 0, S), vec(3.9, 0, 6, 0, S), vec(3.0, 0, 3.9, 0, D),
									   vec(3.0, 0, 3.87, -0.23, D), vec(3.0, 0, 3.0, -0.9, S)};
	const auto doors = DoorDetector().detect(v);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_NEAR(doors[0].hinge.x, 3.0, 0.05);
	EXPECT_NEAR(doors[0].hinge.y, 0.0, 0.05);
	EXPECT_EQ(doors[0].leaves, (std::vector<size_t>{2, 3, 4}));
}

TEST(DoorDetector, PeopleByAWallMakeNoDoor)
{
	// two people tracks of door length ending on a wall's interior at nearly one point, at
	// different angles: T corners, but no state along the wall (the closed state a door inside
	// a merged wall has), so no door
	const std::vector<GridVector> v = {vec(0, 5, 0, 15, S), vec(0, 14.1, 0.75, 14.36, D),
									   vec(0, 13.93, 0.72, 13.72, D)};
	EXPECT_TRUE(DoorDetector().detect(v).empty());
}

TEST(DoorDetector, TheSweptArcIsAtLeastARightAngleFromTheClosedState)
{
	// states seen: closed (0 deg, along the wall) and 45 deg; a leaf at 80 deg is the door opened
	// wider, one at -80 deg (the other side of the wall) is not
	DoorOptions o;
	o.maxCornerGap = 0.1;  // the extra vectors below make no corner with the wall
	const std::vector<GridVector> v = {vec(0, 0, 3, 0, S), vec(3, 0, 3.9, 0, D), vec(3, 0, 3.64, 0.64, S),
									   vec(3.15, 0.05, 3.3, 0.94, S), vec(3.15, -0.05, 3.3, -0.94, S)};
	const auto doors = DoorDetector(o).detect(v);
	ASSERT_EQ(doors.size(), 1u);
	std::vector<size_t> leaves = doors[0].leaves;
	std::sort(leaves.begin(), leaves.end());
	EXPECT_EQ(leaves, (std::vector<size_t>{1, 2, 3}));
}

TEST(DoorDetector, ZeroLengthVectorsChangeNothing)
{
	const DoorDetector det;
	EXPECT_TRUE(det.detect({}).empty());
	EXPECT_TRUE(det.corners({}).empty());
	std::vector<GridVector> v = {vec(0, 0, 3, 0, S), vec(4.0, 0, 6, 0, S), vec(3.02, 0.03, 3.02, 0.92, D),
								 vec(3.01, 0.0, 3.64, 0.64, D)};
	const auto want = det.detect(v);
	ASSERT_EQ(want.size(), 1u);
	for (const auto& p : {TPoint2D(3, 0), TPoint2D(3.02, 0.92), TPoint2D(3.64, 0.64)})
		for (const auto s : {S, D}) v.push_back(vec(p.x, p.y, p.x, p.y, s));
	const auto got = det.detect(v);
	ASSERT_EQ(got.size(), 1u);
	EXPECT_EQ(got[0].hinge.x, want[0].hinge.x);
	EXPECT_EQ(got[0].hinge.y, want[0].hinge.y);
	EXPECT_EQ(got[0].length, want[0].length);
	EXPECT_EQ(got[0].angles, want[0].angles);
	EXPECT_EQ(got[0].wall, want[0].wall);
	EXPECT_EQ(got[0].leaves, want[0].leaves);
	for (size_t k = 4; k < v.size(); ++k)
		for (const auto& [u0, u1] : det.stateSpans(got, v[k])) EXPECT_TRUE(u0 == 0 && u1 == 0) << k;
}

TEST(DoorDetector, StatesOnOneStraightLineAreNoDoor)
{
	// a line seen dynamic (grazing rays, a moved object) cut where a short static vector ends on
	// it: two door-length dynamic pieces from that end, at 0 and 180 deg, make corners with equal
	// leaves, but no leaf turned about a hinge (a leaf opened flat onto its own wall is that wall)
	std::vector<GridVector> v = {vec(3, 0, 3, -0.5, S), vec(3, 0, 3.8, 0, D), vec(3, 0, 2.2, 0, D)};
	DoorDetector det;
	EXPECT_TRUE(det.detect(v).empty());
	// a state between them makes it a door
	v.push_back(vec(3.02, 0.02, 3.58, 0.58, D));
	const auto doors = det.detect(v);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_NEAR(doors[0].hinge.x, 3.0, 0.05);
	EXPECT_EQ(doors[0].angles.size(), 3u);
}

TEST(DoorDetector, StatesAllNearTheWallsLineAreNoDoor)
{
	// a wall ending at (3, 0) whose continuation was seen dynamic in two kinked pieces (+-15 deg
	// from the wall's line, as on the real logs' corridor walls): no state turned from the wall
	const std::vector<GridVector> kinked = {vec(0, 0, 3, 0, S),
											vec(3, 0, 3 + 0.8 * std::cos(0.26), 0.8 * std::sin(0.26), D),
											vec(3, 0, 3 + 0.8 * std::cos(-0.26), 0.8 * std::sin(-0.26), D)};
	EXPECT_TRUE(DoorDetector().detect(kinked).empty());
	// a leaf seen open by 40 deg next to the same +15 deg state is a door
	std::vector<GridVector> open = kinked;
	open[2] = vec(3, 0, 3 + 0.8 * std::cos(-0.70), 0.8 * std::sin(-0.70), D);
	const auto doors = DoorDetector().detect(open);
	ASSERT_EQ(doors.size(), 1u);
	EXPECT_NEAR(doors[0].hinge.x, 3.0, 0.05);
	EXPECT_EQ(doors[0].angles.size(), 2u);
}
