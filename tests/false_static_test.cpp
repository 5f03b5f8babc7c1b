// The false-static breakdown (gv-eval map --breakdown) on a hand-made truth with known answers.
#include "eval/FalseStatic.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <stdexcept>

using namespace gridvector;

namespace
{
sim::HitRun hit(sim::HitKind kind, int id, double t, double x1, double y1, double x2, double y2)
{
	sim::HitRun h;
	h.kind = kind, h.id = id, h.t = t, h.seg = {x1, y1, x2, y2}, h.beams = 8;
	return h;
}

eval::MapVector vec(double x1, double y1, double x2, double y2, bool isStatic = true)
{
	return {{x1, y1, x2, y2}, isStatic ? 0.9 : 0.1, isStatic};
}

/** A wall along y = 0 from 0 to 50; door 0 hinged at (20, 0) seen closed at
 * t = 10-10.4 and open at t = 30; door 1 at (40, 0) seen closed at every pass;
 * a person at y = 1 near x = 5; the object moved from (10, 3) to (30, 3). */
sim::Truth truth()
{
	sim::Truth t;
	t.walls = {{0, 0, 50, 0}};
	t.seenWalls = t.walls;
	const sim::DoorTruth d{{20, 0}, 1, 0, M_PI / 2, 2};  // hinge, length, closed, open, swings
	t.doors = {d, d};
	t.doors[1].hinge = {40, 0};
	t.doorSwings = {{0, 20, 21, 0, M_PI / 2}, {1, 25, 26, 0, 1.0}, {1, 35, 36, 1.0, 0}};
	t.hits = {hit(sim::HitKind::Door, 0, 10, 20.1, 0.02, 20.9, 0.02),  // door 0 closed ...
			  hit(sim::HitKind::Door, 0, 10.4, 20.1, 0.02, 20.9, 0.02),
			  hit(sim::HitKind::Door, 0, 30, 20, 0.9, 20, 0.2),  // ... and open, at a second pass
			  hit(sim::HitKind::Door, 1, 12, 40.1, 0.02, 40.9, 0.02),  // door 1 closed at both passes
			  hit(sim::HitKind::Door, 1, 40, 40.1, 0.02, 40.9, 0.02),
			  hit(sim::HitKind::Person, 0, 5, 4.5, 1, 5.5, 1),
			  hit(sim::HitKind::Object, 0, 7, 30, 3, 31, 3)};
	t.objectEdges = {{"box", false, {10, 3, 11, 3}}, {"box", true, {30, 3, 31, 3}}};
	return t;
}
}  // namespace

TEST(FalseStatic, AttributesEachStretchToTheNearestDynamicTruth)
{
	const sim::Truth t = truth();
	const std::vector<eval::MapVector> v = {
		vec(0, 0, 50, 0),  // the wall, through both doorways: on the wall, not false static
		vec(20, 0.3, 20, 0.9),  // door 0's open leaf, static: 0.6 m, door seen in two states
		vec(40.2, 0.15, 40.8, 0.15),  // door 1's closed leaf 0.15 m off the wall: 0.6 m, one state
		vec(4.6, 1.02, 5.4, 1.02),  // the person's track: 0.8 m
		vec(10, 3, 10.5, 3),  // the object's first place: 0.5 m
		vec(5, 5, 5, 5.3),  // nowhere near anything dynamic: 0.3 m other
		vec(30, 3, 31, 3, false),  // dynamic vectors are not counted
	};
	const auto b = eval::falseStaticBreakdown(v, t);
	constexpr double tol = 2e-3;
	EXPECT_NEAR(b.twoStateDoors, 0.6, tol);
	EXPECT_NEAR(b.oneStateDoors, 0.6, tol);
	EXPECT_NEAR(b.people, 0.8, tol);
	EXPECT_NEAR(b.movedObject, 0.5, tol);
	EXPECT_NEAR(b.other, 0.3, tol);
	EXPECT_NEAR(b.total, 2.8, tol);
	ASSERT_EQ(b.doors.size(), 2u);
	EXPECT_NEAR(b.doors[0].falseStatic, 0.6, tol);
	EXPECT_NEAR(b.doors[1].falseStatic, 0.6, tol);
	// the categories but "other" are the ghost length, same places and tolerances
	const auto m = eval::evaluateMap(v, t, nullptr);
	EXPECT_NEAR(b.total - b.other, m.ghostLength, tol);
	EXPECT_NEAR(b.total - b.other - b.oneStateDoors, m.ghostLengthSeenSwinging, tol);
}

// A stretch within reach of a one-state door and of another dynamic place goes to the nearer (the door
// here), while the second ghost figure, which drops only one-state doors' places, still counts it.
TEST(FalseStatic, OneStateDoorOverlappingAPersonIsStillAGhostOfTheSecondFigure)
{
	sim::Truth t = truth();
	t.hits.push_back(hit(sim::HitKind::Person, 1, 50, 40.2, 0.22, 40.8, 0.22));  // 7 cm from the leaf below
	const std::vector<eval::MapVector> v = {vec(40.2, 0.15, 40.8, 0.15)};  // in door 1's swept sector
	const auto b = eval::falseStaticBreakdown(v, t);
	constexpr double tol = 2e-3;
	EXPECT_NEAR(b.oneStateDoors, 0.6, tol);
	EXPECT_NEAR(b.people, 0.0, tol);
	const auto m = eval::evaluateMap(v, t, nullptr);
	EXPECT_NEAR(b.total - b.other, m.ghostLength, tol);  // the first identity holds
	EXPECT_NEAR(m.ghostLengthSeenSwinging, 0.6, tol);  // the second figure: the person is a dynamic place
	EXPECT_NEAR(b.total - b.other - b.oneStateDoors, 0.0, tol);
}

TEST(FalseStatic, DoorPassesAndLeafAngles)
{
	const auto obs = eval::doorObservations(truth(), {});
	ASSERT_EQ(obs.size(), 2u);
	EXPECT_TRUE(obs[0].seenSwinging);
	EXPECT_FALSE(obs[1].seenSwinging);
	EXPECT_NEAR(obs[0].openDeg, 90, 1e-9);
	ASSERT_EQ(obs[0].passes.size(), 2u);  // 10 and 10.4 s are one pass, 30 s another
	EXPECT_EQ(obs[0].passes[0].runs, 2u);
	EXPECT_NEAR(obs[0].passes[0].t0, 10, 1e-9);
	EXPECT_NEAR(obs[0].passes[0].t1, 10.4, 1e-9);
	EXPECT_NEAR(obs[0].passes[0].maxDeg, std::atan2(0.02, 0.9) * 180 / M_PI, 1e-9);  // the far end 0.02 m off the line
	EXPECT_NEAR(obs[0].passes[1].minDeg, 90, 1e-6);
	ASSERT_EQ(obs[1].passes.size(), 2u);
	EXPECT_LT(obs[1].passes[1].maxDeg, 2);
	ASSERT_EQ(obs[1].swingTimes.size(), 2u);  // swung while the robot was elsewhere
	EXPECT_EQ(obs[0].swingTimes.size(), 1u);
	// MapEvalOptions::doorPassGap (default 2 s): 10.4 -> 30 s is one pass with a 20 s gap allowed
	eval::MapEvalOptions wide;
	EXPECT_EQ(eval::MapEvalOptions().doorPassGap, 2.0);
	wide.doorPassGap = 20;
	EXPECT_EQ(eval::doorObservations(truth(), wide)[0].passes.size(), 1u);
}

TEST(FalseStatic, TextAndJsonNameEveryCategory)
{
	auto b = eval::falseStaticBreakdown({vec(20, 0.3, 20, 0.9)}, truth());
	b.timeOrigin = 10;
	const std::string text = eval::formatText(b);
	EXPECT_NE(text.find("doors seen in two states 0.60"), std::string::npos) << text;
	EXPECT_NE(
		text.find(
			"door 1: 2 swings (open 90 deg), seen in one state, false static 0.00 m, 2 passes: [2-2 s, 1 scan, 1 deg]"),
		std::string::npos)
		<< text;
	EXPECT_NE(text.find("swings at 15-16 s (0->57) 25-26 s (57->0)"), std::string::npos) << text;
	const nlohmann::ordered_json json = eval::toJson(b);
	EXPECT_DOUBLE_EQ(json["two_state_doors_m"].get<double>(), b.twoStateDoors);
	EXPECT_EQ(json["doors"].size(), b.doors.size());
	EXPECT_EQ(json["doors"][0]["seen_swinging"], b.doors[0].seenSwinging) << json;
	EXPECT_EQ(json["doors"][0]["passes"].size(), b.doors[0].passes.size()) << json;
}

TEST(FalseStatic, HugeVectorIsAnError)
{
	EXPECT_THROW(eval::falseStaticBreakdown({vec(0, 5, 1e300, 5)}, truth()), std::invalid_argument);
	const auto b = eval::falseStaticBreakdown({}, truth());  // an empty map: nothing false static, every door listed
	EXPECT_EQ(b.total, 0.0);
	EXPECT_EQ(b.doors.size(), 2u);
}
