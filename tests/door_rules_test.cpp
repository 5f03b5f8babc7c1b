// The door rules beyond the paper (Sec. 5.4 extended), each on its own: closed state, T corners,
// leaf chains, leaf turns, swept arc, joining states, wall as state, closed leaf in the wall,
// state spans. DoorDetector (door_detector_test) applies them in order.
#include "doors/ClosedInWall.h"
#include "doors/ClosedState.h"
#include "doors/DoorGeometry.h"
#include "doors/HingeRule.h"
#include "doors/JoinStates.h"
#include "doors/LeafChains.h"
#include "doors/LeafTurns.h"
#include "doors/StateSpans.h"
#include "doors/SweptArc.h"
#include "doors/TeeCorners.h"
#include "doors/WallAsState.h"

#include <gtest/gtest.h>

#include "door_vectors.h"

#include <algorithm>
#include <cmath>

using namespace gridvector;
using namespace gridvector::doors;
using gvtest::D;
using gvtest::S;
using gvtest::vec;
using mrpt::math::TPoint2D;

namespace
{
/** From `fromHinge` to `fromHinge + len` along direction deg from (x, y). */
GridVector polarVec(double x, double y, double fromHinge, double len, double deg, VectorState s)
{
	const double c = std::cos(deg * M_PI / 180), sn = std::sin(deg * M_PI / 180);
	return vec(x + fromHinge * c, y + fromHinge * sn, x + (fromHinge + len) * c, y + (fromHinge + len) * sn, s);
}
double rad(double deg) { return deg * M_PI / 180; }

Door doorAt(TPoint2D hinge, double length, std::vector<double> anglesDeg, size_t wall)
{
	Door d;
	d.hinge = hinge, d.length = length, d.wall = wall;
	for (double a : anglesDeg) d.angles.push_back(rad(a));
	std::sort(d.angles.begin(), d.angles.end());
	return d;
}
}  // namespace

TEST(ClosedState, ADynamicLeafContinuingTheWallsLineIsTheClosedState)
{
	const DoorOptions o;
	const HingeRule rule(o);
	const GridVector wall = vec(0, 0, 3, 0, S);
	// past the wall's end: the corner where the ends meet
	std::vector<GridVector> v = {wall, vec(3.02, 0, 3.92, 0, D)};
	auto c = rule.meetingEnds(v, 0, 1);
	ASSERT_TRUE(c && !rule.turns(*c, wall));
	ASSERT_TRUE(closedStateCorner(wall, *c, o));
	EXPECT_TRUE(c->alongWall);
	EXPECT_EQ(c->vertex, TPoint2D(3.02, 0));
	EXPECT_NEAR(c->leafLength, 0.9, 1e-12);
	// overlapping the wall by 0.2 m (merged closed states reach into it): from the wall's end
	v[1] = vec(2.8, 0, 3.9, 0, D);
	c = rule.meetingEnds(v, 0, 1);
	ASSERT_TRUE(c && closedStateCorner(wall, *c, o));
	EXPECT_EQ(c->vertex, TPoint2D(3, 0));
	EXPECT_NEAR(c->leafLength, 0.9, 1e-12);
	// a static one is the wall's continuation; one lying back along the wall is no leaf
	v[1] = vec(3.02, 0, 3.92, 0, S);
	c = rule.meetingEnds(v, 0, 1);
	ASSERT_TRUE(c.has_value());
	EXPECT_FALSE(closedStateCorner(wall, *c, o));
	v[1] = vec(3.0, 0.02, 2.1, 0.02, D);
	c = rule.meetingEnds(v, 0, 1);
	ASSERT_TRUE(c.has_value());
	EXPECT_FALSE(closedStateCorner(wall, *c, o));
}

TEST(TeeCorners, ACandidatesEndOnALongWallsInteriorIsACorner)
{
	const DoorOptions o;
	std::vector<GridVector> v = {vec(0, 0, 6, 0, S), vec(3.0, 0.9, 3.0, 0.01, S)};
	std::vector<Corner> out;
	teeCorners(v, 0, 1, o, out);  // an open state leaving the wall
	ASSERT_EQ(out.size(), 1u);
	EXPECT_TRUE(out[0].tee);
	EXPECT_FALSE(out[0].alongWall);
	EXPECT_EQ(out[0].vertex, TPoint2D(3.0, 0.01));
	EXPECT_NEAR(out[0].leafAngle, M_PI / 2, 1e-12);
	// its end just beyond kMaxWallOffset from the wall's line: none
	out.clear();
	v[1] = vec(3.0, 0.9 + kMaxWallOffset + 0.02, 3.0, kMaxWallOffset + 0.02, S);
	teeCorners(v, 0, 1, o, out);
	EXPECT_TRUE(out.empty());
	// a dynamic closed state lying on the wall: each end may be the hinge
	v[1] = vec(3.0, 0, 4.1, 0, D);
	teeCorners(v, 0, 1, o, out);
	ASSERT_EQ(out.size(), 2u);
	EXPECT_TRUE(out[0].alongWall && out[1].alongWall);
	EXPECT_EQ(out[0].vertex, TPoint2D(3.0, 0));
	EXPECT_EQ(out[1].vertex, TPoint2D(4.1, 0));
	// a static one on the wall is the wall
	out.clear();
	v[1] = vec(3.0, 0, 4.1, 0, S);
	teeCorners(v, 0, 1, o, out);
	EXPECT_TRUE(out.empty());
	// running on past the wall's end: a corner at that end too, its length from there
	v = {vec(0, 0, 3.2, 0, S), vec(3.0, 0, 3.9, 0, D)};
	teeCorners(v, 0, 1, o, out);
	ASSERT_EQ(out.size(), 2u);
	EXPECT_TRUE(out[0].tee);
	EXPECT_EQ(out[0].vertex, TPoint2D(3.0, 0));
	EXPECT_FALSE(out[1].tee);
	EXPECT_EQ(out[1].vertex, TPoint2D(3.2, 0));
	EXPECT_NEAR(out[1].leafLength, 0.7, 1e-12);
}

TEST(TeeCorners, AHingeOfTCornersOnlyNeedsAClosedStateAlongTheWall)
{
	std::vector<Corner> cs(3);
	cs[0].tee = cs[1].tee = true;  // two open states on a wall's interior (or people by a wall)
	EXPECT_FALSE(teeHingeSeenClosed(cs, {0, 1}));
	cs[1].alongWall = true;  // one of them the closed state on the wall
	EXPECT_TRUE(teeHingeSeenClosed(cs, {0, 1}));
	EXPECT_TRUE(teeHingeSeenClosed(cs, {0, 2}));  // an end corner
}

namespace
{
/** A dynamic piece of `dynLen` from (3, 0) at -70 deg, then a static piece `gap` past it,
 * turned by `turnDeg`, of `staticLen`. */
std::vector<GridVector> cutLeaf(double dynLen, double gap, double turnDeg, double staticLen, VectorState second = S)
{
	const GridVector a = polarVec(3, 0, 0, dynLen, -70, D);
	return {vec(0, 0, 3, 0, S), a, polarVec(a.end().x, a.end().y, gap, staticLen, -70 + turnDeg, second)};
}
}  // namespace

TEST(LeafChains, ADynamicPieceAndItsCollinearStaticPieceAreOneCandidate)
{
	const DoorOptions o;
	const auto v = cutLeaf(0.3, 0.02, 0, 0.58);
	const LeafChains chains(v, o);
	ASSERT_EQ(chains.vectors().size(), 4u);
	const GridVector& chain = chains.vectors()[3];
	EXPECT_EQ(chain.state, VectorState::Dynamic);
	EXPECT_EQ(chain.start(), TPoint2D(3, 0));  // from the dynamic piece's far end
	EXPECT_NEAR(chain.length(), 0.9, 1e-9);
	EXPECT_NEAR(chain.psi(), rad(-70), 1e-9);
	EXPECT_EQ(chains.pieces({3, 0}), (std::vector<size_t>{0, 1, 2}));  // the chain is its pieces
	EXPECT_EQ(chains.pieces({1, 3}), (std::vector<size_t>{1, 2}));
	// within the gap and the turn, one chain; beyond either, none
	EXPECT_EQ(LeafChains(cutLeaf(0.3, kLeafChainGap - 0.02, 0, 0.55), o).vectors().size(), 4u);
	EXPECT_EQ(LeafChains(cutLeaf(0.3, kLeafChainGap + 0.02, 0, 0.55), o).vectors().size(), 3u);
	EXPECT_EQ(LeafChains(cutLeaf(0.3, 0.02, kLeafChainMaxTurnDeg - 4, 0.55), o).vectors().size(), 4u);
	EXPECT_EQ(LeafChains(cutLeaf(0.3, 0.02, kLeafChainMaxTurnDeg + 4, 0.55), o).vectors().size(), 3u);
	// two dynamic pieces are people's tracks; a dynamic piece of door length is a candidate
	// itself; together longer than max_door_length (1.4) they are no leaf
	EXPECT_EQ(LeafChains(cutLeaf(0.3, 0.02, 0, 0.58, D), o).vectors().size(), 3u);
	EXPECT_EQ(LeafChains(cutLeaf(0.62, 0.02, 0, 0.3), o).vectors().size(), 3u);
	EXPECT_EQ(LeafChains(cutLeaf(0.5, 0.02, 0, 1.0), o).vectors().size(), 3u);
}

TEST(LeafTurns, StatesOnOneLineAreNoTurningLeaf)
{
	EXPECT_TRUE(statesOnOneLine({0.0, M_PI}, 10));  // either way through the vertex
	EXPECT_TRUE(statesOnOneLine({0.0, M_PI - rad(8)}, 10));
	EXPECT_FALSE(statesOnOneLine({0.0, M_PI - rad(12)}, 10));
	EXPECT_FALSE(statesOnOneLine({0.0, M_PI / 4, M_PI}, 10));
}

TEST(LeafTurns, ADoorHasAStateTurnedFromItsWallsLine)
{
	const GridVector wall = vec(0, 0, 3, 0, S);
	// the wall's continuation seen in kinked pieces, +-15 deg: no state turned from the wall
	EXPECT_FALSE(turnsFromWall(wall, doorAt(TPoint2D(3, 0), 0.8, {15, -15}, 0)));
	EXPECT_FALSE(turnsFromWall(wall, doorAt(TPoint2D(3, 0), 0.8, {15, 180 - (kMinOpenDeg - 1)}, 0)));
	EXPECT_TRUE(turnsFromWall(wall, doorAt(TPoint2D(3, 0), 0.8, {15, -(kMinOpenDeg + 1)}, 0)));
	EXPECT_TRUE(turnsFromWall(wall, doorAt(TPoint2D(3, 0), 0.8, {0, 180 - (kMinOpenDeg + 1)}, 0)));
}

TEST(SweptArc, TheSmallestArcHoldingTheStates)
{
	auto [start, width] = statesArc({0.0, M_PI / 4});
	EXPECT_DOUBLE_EQ(start, 0.0);
	EXPECT_DOUBLE_EQ(width, M_PI / 4);
	std::tie(start, width) = statesArc({-3.0, 3.0});  // across +-pi
	EXPECT_DOUBLE_EQ(start, 3.0);
	EXPECT_NEAR(width, 2 * M_PI - 6.0, 1e-12);
	const GridVector wall = vec(0, 0, 3, 0, S);
	EXPECT_DOUBLE_EQ(closedDirection(M_PI / 8, wall), 0.0);
	EXPECT_DOUBLE_EQ(closedDirection(3 * M_PI / 4, wall), M_PI);
}

TEST(SweptArc, StatesSpanningLessThanKMinSweepDegAreWidenedFromTheClosedLeaf)
{
	const GridVector wall = vec(0, 0, 3, 0, S);
	// states 0 and 45 deg: the arc from the wall's line, kMinSweepDeg wide, +- 10 deg
	const Door d = doorAt(TPoint2D(3, 0), 0.9, {0, 45}, 0);
	ASSERT_EQ(kMinSweepDeg, 90.0);
	EXPECT_TRUE(inSweep(d, wall, rad(80), 10));
	EXPECT_TRUE(inSweep(d, wall, rad(kMinSweepDeg + 8), 10));
	EXPECT_FALSE(inSweep(d, wall, rad(kMinSweepDeg + 12), 10));
	EXPECT_TRUE(inSweep(d, wall, rad(-8), 10));
	EXPECT_FALSE(inSweep(d, wall, rad(-80), 10));  // the other side of the wall
	// states -45 and -79 deg, not the closed one: the arc runs from the wall's line through them
	const Door below = doorAt(TPoint2D(3, 0), 0.9, {-45, -79}, 0);
	EXPECT_TRUE(inSweep(below, wall, rad(-5), 10));
	EXPECT_FALSE(inSweep(below, wall, rad(-150), 10));
	// states spanning more than a right angle: their own arc
	const Door wide = doorAt(TPoint2D(3, 0), 0.9, {0, 120}, 0);
	EXPECT_TRUE(inSweep(wide, wall, rad(128), 10));
	EXPECT_FALSE(inSweep(wide, wall, rad(135), 10));
}

TEST(JoinStates, AWholeLeafAtANewAngleIsAStateAndAShortOneAPart)
{
	const DoorOptions o;  // max_length_diff 0.25, min_state_diff_deg 10
	Door d = doorAt(TPoint2D(3, 0), 0.9, {0, 45}, 0);
	std::vector<bool> taken(5, false);
	addLeaf(d, 1, rad(80), 0.9, taken, o);  // a new state
	addLeaf(d, 2, rad(60), 0.6, taken, o);  // shorter than 0.9 - 0.25: part of a state
	addLeaf(d, 3, rad(83), 0.9, taken, o);  // within 10 deg of 80: the same state
	EXPECT_EQ(d.leaves, (std::vector<size_t>{1, 2, 3}));
	EXPECT_EQ(taken, (std::vector<bool>{false, true, true, true, false}));
	ASSERT_EQ(d.angles.size(), 3u);
	EXPECT_DOUBLE_EQ(d.angles[2], rad(80));
}

TEST(JoinStates, VectorsFromTheHingeIntoTheSweptArcJoinTheDoor)
{
	const DoorOptions o;
	const std::vector<GridVector> v = {
		vec(0, 0, 3, 0, S),
		vec(3.15, 0.05, 3.3, 0.94, S),  // from the hinge at 80 deg: a state
		polarVec(3, 0, 0.1, 0.5, 60, D),  // a leaf seen in part: part of a state
		vec(3.15, -0.05, 3.3, -0.94, S),  // from the hinge, the other side of the wall
		polarVec(3, 0, 0.05, 1.3, 30, S),  // longer than the reach: a wall
		polarVec(3, 0, 0.3, 0.6, 20, S),  // its near end 0.3 m from the hinge (max_vertex_distance 0.25)
		vec(3.05, 0.05, 3.15, 0.15, D)};  // its tip too near the hinge
	Door d = doorAt(TPoint2D(3, 0), 0.9, {0, 45}, 0);
	std::vector<bool> taken(v.size(), false);
	joinStates(v, d, 0.9 + o.maxLengthDiff, taken, o);
	EXPECT_EQ(d.leaves, (std::vector<size_t>{1, 2}));
	EXPECT_EQ(d.angles.size(), 3u);
	// a vector taken by another door stays there
	Door again = doorAt(TPoint2D(3, 0), 0.9, {0, 45}, 0);
	taken.assign(v.size(), false);
	taken[1] = true;
	joinStates(v, again, 0.9 + o.maxLengthDiff, taken, o);
	EXPECT_EQ(again.leaves, (std::vector<size_t>{2}));
}

TEST(WallAsState, AStaticLeafActingAsTheWallIsAStateOfTheLongWallsDoor)
{
	const DoorOptions o;
	// a wall through the hinge (0, 0); the corners' "wall" was the 15 deg static leaf
	const std::vector<GridVector> v = {vec(0, -2, 0, 3, S), polarVec(0, 0, 0, 0.82, 15, S),
									   polarVec(0, 0, 0, 0.84, 52, D), polarVec(0, 0, 0, 0.87, 33, D)};
	Door d = doorAt(TPoint2D(0, 0), 0.855, {33, 52}, 1);
	d.leaves = {2, 3};
	std::vector<bool> taken = {false, false, true, true};
	wallAsState(v, d, 0.87 + o.maxLengthDiff, taken, o);
	EXPECT_EQ(d.wall, 0u);
	EXPECT_EQ(d.leaves, (std::vector<size_t>{2, 3, 1}));
	EXPECT_TRUE(taken[1]);
	ASSERT_EQ(d.angles.size(), 3u);
	EXPECT_NEAR(d.angles[0], rad(15), 1e-9);
	// no longer wall through the hinge: nothing changes
	const std::vector<GridVector> noWall = {vec(0, 1, 0, 3, S), v[1], v[2], v[3]};
	Door e = doorAt(TPoint2D(0, 0), 0.855, {33, 52}, 1);
	taken = {false, false, true, true};
	wallAsState(noWall, e, 0.87 + o.maxLengthDiff, taken, o);
	EXPECT_EQ(e.wall, 1u);
	EXPECT_TRUE(e.leaves.empty());
	EXPECT_EQ(e.angles.size(), 2u);
	// a "wall" longer than the leaves' reach is the wall
	Door f = doorAt(TPoint2D(0, 0), 0.855, {33, 52}, 1);
	taken = {false, false, true, true};
	wallAsState(v, f, 0.8, taken, o);
	EXPECT_EQ(f.wall, 1u);
}

TEST(ClosedInWall, AWallRunningOnPastTheHingeHoldsTheClosedLeaf)
{
	const DoorOptions o;
	const std::vector<GridVector> v = {vec(0, -2, 0, 3, S), vec(0, -2, 0, 0.5, S), vec(0, -2, 0, 1.2, S)};
	Door d = doorAt(TPoint2D(0, 0), 0.84, {15, 33, 52}, 0);
	closedInWall(v, d, o);
	EXPECT_TRUE(d.closedInWall);
	EXPECT_NEAR(d.closedAngle, M_PI / 2, 1e-12);
	EXPECT_EQ(d.angles.size(), 3u);  // no state seen
	// the wall ends 0.5 m past the hinge, less than a leaf (0.84 - 0.25): no closed leaf inside it
	Door shortPast = doorAt(TPoint2D(0, 0), 0.84, {15, 33, 52}, 1);
	closedInWall(v, shortPast, o);
	EXPECT_FALSE(shortPast.closedInWall);
	// a wall no longer than max_door_length (1.4) cannot hold it either
	const std::vector<GridVector> shortWall = {vec(0, -0.2, 0, 1.2, S)};
	Door s = doorAt(TPoint2D(0, 0), 0.84, {15, 33, 52}, 0);
	closedInWall(shortWall, s, o);
	EXPECT_FALSE(s.closedInWall);
	// the closed state seen (a state along the wall): it is a state, not inside the wall
	Door seen = doorAt(TPoint2D(0, 0), 0.84, {33, 52, 88}, 0);
	closedInWall(v, seen, o);
	EXPECT_FALSE(seen.closedInWall);
	// the hinge off the wall's line by more than kMaxWallOffset
	Door off = doorAt(TPoint2D(kMaxWallOffset + 0.02, 0), 0.84, {15, 33, 52}, 0);
	closedInWall(v, off, o);
	EXPECT_FALSE(off.closedInWall);
}

TEST(StateSpans, AStateAlongAVectorIsItsStretchThere)
{
	const DoorOptions o;
	const std::vector<Door> doors = {doorAt(TPoint2D(3, 0), 0.9, {0, 90}, 0)};
	const auto spans = stateSpans(doors, vec(0, 0, 6, 0, S), o);
	ASSERT_EQ(spans.size(), 1u);
	EXPECT_NEAR(spans[0].first, 3.0, 1e-12);
	EXPECT_NEAR(spans[0].second, 3.9, 1e-12);
	EXPECT_TRUE(stateSpans(doors, vec(0, kMaxWallOffset + 0.02, 6, kMaxWallOffset + 0.02, S), o).empty());
	EXPECT_TRUE(stateSpans(doors, vec(5, 0, 8, 0, S), o).empty());  // the same line, past the leaf
	// the 90 deg state along a vertical vector through the hinge, from its end
	const auto up = stateSpans(doors, vec(3, 2, 3, -1, S), o);
	ASSERT_EQ(up.size(), 1u);
	EXPECT_NEAR(up[0].first, 1.1, 1e-12);
	EXPECT_NEAR(up[0].second, 2.0, 1e-12);
	// a closed leaf inside the wall is a state there too
	Door inWall = doorAt(TPoint2D(3, 0), 0.9, {60}, 0);
	EXPECT_TRUE(stateSpans({inWall}, vec(0, 0, 6, 0, S), o).empty());
	inWall.closedInWall = true, inWall.closedAngle = 0;
	const auto closed = stateSpans({inWall}, vec(0, 0, 6, 0, S), o);
	ASSERT_EQ(closed.size(), 1u);
	EXPECT_NEAR(closed[0].first, 3.0, 1e-12);
	EXPECT_NEAR(closed[0].second, 3.9, 1e-12);
}
