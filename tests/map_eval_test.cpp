// Map metrics on synthetic cases with known answers, and the vectors-file reader.
#include "eval/MapEval.h"
#include "eval/SegmentIndex.h"
#include "io/AtomicFile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

using namespace gridvector;
using sim::Segment;
namespace fs = std::filesystem;

namespace
{
/** One 10 m wall along y = 0, of which x in [0, 8] was seen; a person seen at
 * y = 1, x in [5, 7]; a door hinged at (20, 0), 1 m long, swinging from 0 to 90 deg. */
sim::Truth truth()
{
	sim::Truth t;
	t.walls = {{0, 0, 10, 0}};
	t.seenWalls = {{0, 0, 8, 0}};
	sim::HitRun h;
	h.kind = sim::HitKind::Person;
	h.seg = {5, 1, 7, 1};
	h.beams = 10;
	t.hits = {h};
	sim::DoorTruth d;
	d.hinge = {20, 0};
	d.length = 1;
	d.closedAngle = 0;
	d.openAngle = M_PI / 2;
	d.swings = 2;
	sim::DoorTruth still = d;
	still.hinge = {30, 0};
	still.swings = 0;
	t.doors = {d, still};
	return t;
}

eval::MapVector vec(double x1, double y1, double x2, double y2, bool isStatic)
{
	return {{x1, y1, x2, y2}, isStatic ? 0.9 : 0.1, isStatic};
}

constexpr double kTol = 2e-3;  // the metrics are sampled every 1 cm
}  // namespace

TEST(MapEval, PerfectMapScoresOne)
{
	const auto m = eval::evaluateMap({vec(0, 0, 10, 0, true), vec(5, 1, 7, 1, false)}, truth(), nullptr);
	EXPECT_NEAR(m.staticPrecision, 1.0, 1e-9);
	EXPECT_NEAR(m.staticRecall, 1.0, 1e-9);
	EXPECT_NEAR(m.ghostLength, 0.0, 1e-9);
	EXPECT_NEAR(m.dynamicDetection, 1.0, 1e-9);
	EXPECT_NEAR(m.staticLength, 10.0, 1e-9);
	EXPECT_NEAR(m.dynamicLength, 2.0, 1e-9);
	EXPECT_FALSE(m.doorsEvaluated);
}

TEST(MapEval, KnownAnswers)
{
	const std::vector<eval::MapVector> v = {
		vec(0, 0.05, 4, 0.05, true),  // on the wall: 4 m
		vec(5, 1, 7, 1, true),  // a ghost on the person's track: 2 m
		vec(20.3, 0.2, 20.3, 0.8, true),  // a ghost in the door's swept area: 0.6 m
		vec(12, 3, 13, 3, true),  // off everything: 1 m, neither wall nor ghost
		vec(5, 1.05, 6, 1.05, false),  // dynamic, covers the person's hits from x = 4.9 to 6.087
		vec(8, 0, 9, 0, false),  // dynamic on a static wall: 1 m
	};
	const std::vector<sim::DoorTruth> detected = {{{20.2, 0.1}, 0.9, 0, 0, 0}, {{25, 0}, 0.9, 0, 0, 0}};
	const auto m = eval::evaluateMap(v, truth(), &detected);
	EXPECT_NEAR(m.staticLength, 7.6, 1e-9);
	EXPECT_NEAR(m.staticPrecision, 4.0 / 7.6, kTol);
	// seen wall [0, 8] covered where a static vector is within 0.1 m: x in [0, 4 + sqrt(0.01 - 0.0025)]
	EXPECT_NEAR(m.seenWallLength, 8.0, 1e-9);
	EXPECT_NEAR(m.staticRecall, (4.0 + std::sqrt(0.0075)) / 8.0, kTol);
	EXPECT_NEAR(m.ghostLength, 2.6, kTol);
	EXPECT_NEAR(m.ghostShare, 2.6 / 7.6, kTol);
	// the door's leaf was never hit, so it was not seen in two states: its sector is static there
	EXPECT_NEAR(m.ghostLengthSeenSwinging, 2.0, kTol);
	EXPECT_NEAR(m.dynamicHitLength, 2.0, 1e-9);
	EXPECT_NEAR(m.dynamicDetection, (1.0 + std::sqrt(0.0075)) / 2.0, kTol);
	EXPECT_NEAR(m.dynamicOnWalls, 1.0, kTol);
	// doors: only the door that swung counts; the detection at (20.2, 0.1) is 0.22 m from its hinge
	EXPECT_TRUE(m.doorsEvaluated);
	EXPECT_EQ(m.movingDoors, 1u);
	EXPECT_EQ(m.doorsFound, 1u);
	EXPECT_DOUBLE_EQ(m.doorRecall, 1.0);
	EXPECT_DOUBLE_EQ(m.doorPrecision, 0.5);
	EXPECT_EQ(eval::toJson(m)["door_recall"], 1.0);
	EXPECT_NE(eval::formatText(m).find("door recall:       1.0000 (1 of 1 swinging doors)"), std::string::npos);
	EXPECT_EQ(m.observedSwingingDoors, 0u);  // no door hits in the truth
}

TEST(MapEval, DoorRecallOverDoorsSeenSwinging)
{
	sim::Truth t = truth();
	sim::DoorTruth third = t.doors[0];
	third.hinge = {40, 0};
	t.doors.push_back(third);  // door 2 swings too
	auto hit = [](int id, double x1, double y1, double x2, double y2) {
		sim::HitRun h;
		h.kind = sim::HitKind::Door, h.id = id, h.seg = {x1, y1, x2, y2}, h.beams = 8;
		return h;
	};
	t.hits.push_back(hit(0, 20.1, 0, 20.9, 0));  // door 0 closed ...
	t.hits.push_back(hit(0, 20, 0.9, 20, 0.2));  // ... and open: seen swinging
	t.hits.push_back(hit(2, 40.1, 0, 40.9, 0));  // door 2 closed ...
	t.hits.push_back(hit(2, 40.1, 0.03, 40.8, 0.04));  // ... closed again (3 deg): not seen swinging
	t.hits.push_back(hit(2, 40, 0.1, 40, 0.2));  // a 0.1 m run: too short to tell
	const std::vector<sim::DoorTruth> detected = {{{20.1, 0.1}, 0.9, 0, 0, 0}};
	const auto m = eval::evaluateMap({vec(0, 0, 10, 0, true)}, t, &detected);
	EXPECT_EQ(m.movingDoors, 2u);
	EXPECT_EQ(m.doorsFound, 1u);
	EXPECT_DOUBLE_EQ(m.doorRecall, 0.5);
	EXPECT_EQ(m.observedSwingingDoors, 1u);
	EXPECT_EQ(m.observedDoorsFound, 1u);
	EXPECT_DOUBLE_EQ(m.doorRecallObserved, 1.0);
	EXPECT_EQ(eval::toJson(m)["door_recall_observed"], 1.0);
}

// A 2-beam run (grazing incidence) fits any line: it shows no leaf state, however long it is.
TEST(MapEval, TwoBeamRunShowsNoLeafState)
{
	sim::Truth t = truth();
	auto hit = [](double x1, double y1, double x2, double y2, int beams) {
		sim::HitRun h;
		h.kind = sim::HitKind::Door, h.id = 0, h.seg = {x1, y1, x2, y2}, h.beams = beams;
		return h;
	};
	t.hits.push_back(hit(20, 0.9, 20, 0.2, 8));  // door 0 open, 8 beams
	t.hits.push_back(hit(20.1, 0, 20.7, 0, 2));  // closed, 2 beams 0.6 m apart
	EXPECT_FALSE(eval::showsLeafState(t.hits.back(), {}));
	EXPECT_FALSE(eval::doorsSeenSwinging(t)[0]);
	eval::MapEvalOptions lax;
	lax.doorMinRunBeams = 2;
	EXPECT_TRUE(eval::doorsSeenSwinging(t, lax)[0]);
	t.hits.back().beams = 3;
	EXPECT_TRUE(eval::doorsSeenSwinging(t)[0]);
}

TEST(MapEval, SecondGhostFigureLeavesOutDoorsSeenInOneState)
{
	sim::Truth t = truth();
	sim::DoorTruth third = t.doors[0];
	third.hinge = {40, 0};
	t.doors.push_back(third);  // door 2 swings too, but is seen closed only
	auto hit = [](sim::HitKind kind, int id, double x1, double y1, double x2, double y2) {
		sim::HitRun h;
		h.kind = kind, h.id = id, h.seg = {x1, y1, x2, y2}, h.beams = 8;
		return h;
	};
	t.hits.push_back(hit(sim::HitKind::Door, 0, 20.1, 0, 20.9, 0));  // door 0 closed ...
	t.hits.push_back(hit(sim::HitKind::Door, 0, 20, 0.9, 20, 0.2));  // ... and open: seen swinging
	t.hits.push_back(hit(sim::HitKind::Door, 2, 40.1, 0, 40.9, 0));  // door 2 closed, at every pass
	t.hits.push_back(hit(sim::HitKind::Person, 3, 40.5, 1, 41.5, 1));  // a person in front of door 2
	const std::vector<eval::MapVector> v = {
		vec(0, 0, 10, 0, true),  // the wall: 10 m
		vec(20.2, 0, 20.8, 0, true),  // door 0's closed leaf, static: 0.6 m ghost in both figures
		vec(40.2, 0, 40.8, 0, true),  // door 2's closed leaf: a ghost only in the first figure
		vec(41, 1, 41.4, 1, true),  // the person's track: 0.4 m ghost in both
	};
	const auto m = eval::evaluateMap(v, t, nullptr);
	EXPECT_NEAR(m.staticLength, 11.6, 1e-9);
	EXPECT_NEAR(m.ghostLength, 1.6, kTol);  // unchanged: every door that swung is a dynamic place
	EXPECT_NEAR(m.ghostLengthSeenSwinging, 1.0, kTol);
	EXPECT_NEAR(m.ghostShareSeenSwinging, 1.0 / 11.6, kTol);
	EXPECT_DOUBLE_EQ(eval::toJson(m)["ghost_length_seen_swinging_m"].get<double>(), m.ghostLengthSeenSwinging);
	EXPECT_NE(eval::formatText(m).find("ghost length (doors seen in one state are static): 1.00 m"), std::string::npos)
		<< eval::formatText(m);
	// the precision by the same reading: the wall and door 2's closed leaf are correct, 1.0 m is not
	EXPECT_NEAR(m.staticPrecision, 10.0 / 11.6, kTol);
	EXPECT_NEAR(m.staticPrecisionSeenSwinging, 10.6 / 11.6, kTol);
	EXPECT_NE(eval::formatText(m).find("static precision (doors seen in one state are static): 0.9138"),
			  std::string::npos)
		<< eval::formatText(m);
}

// Lengths are integrated at sample points; a huge (finite) vector must be an error, not int overflow
// (one sample for 1e300 m) or hours of sampling.
TEST(MapEval, SampleCountIsBounded)
{
	EXPECT_EQ(eval::sampleCount(0.5, 0.01), 50);
	EXPECT_EQ(eval::sampleCount(1e-6, 0.01), 1);
	EXPECT_EQ(eval::sampleCount(1e6, 0.01), 100000000);  // 1,000 km: the bound
	EXPECT_THROW(eval::sampleCount(1.0001e6, 0.01), std::invalid_argument);
	EXPECT_THROW(eval::sampleCount(1e300, 0.01), std::invalid_argument);
	EXPECT_THROW(eval::sampleCount(std::numeric_limits<double>::infinity(), 0.01), std::invalid_argument);
	EXPECT_THROW(eval::sampleCount(std::nan(""), 0.01), std::invalid_argument);
	EXPECT_THROW(eval::sampleCount(1, 0), std::invalid_argument);
	EXPECT_THROW(eval::evaluateMap({vec(0, 5, 1e300, 5, true)}, truth(), nullptr), std::invalid_argument);
	EXPECT_THROW(eval::evaluateMap({vec(0, 0, 10, 0, true)}, truth(), nullptr,
								   [] {
									   eval::MapEvalOptions o;
									   o.sampleStep = 0;
									   return o;
								   }()),
				 std::invalid_argument);
}

TEST(MapEval, ReadsVectorsFilesStrictly)
{
	const std::string p = (fs::temp_directory_path() / "gv_map_eval_vectors.txt").string();
	io::writeFileAtomically(p, [](std::ostream& os) {
		os << "# x1 y1 x2 y2 p_static label\n0 0 1 0 0.7\n0 1 1 1 0.2\n0 2 1 2 0.9 dynamic\n0 3 1 3 0.1 static\n";
	});
	const auto v = eval::readVectors(p);
	ASSERT_EQ(v.size(), 4u);
	EXPECT_TRUE(v[0].isStatic);
	EXPECT_FALSE(v[1].isStatic);
	EXPECT_FALSE(v[2].isStatic);  // the label wins over p_static
	EXPECT_TRUE(v[3].isStatic);
	const auto errorOf = [&](const std::string& text) {
		io::writeFileAtomically(p, [&](std::ostream& os) { os << text; });
		try
		{
			eval::readVectors(p);
		}
		catch (const std::runtime_error& e)
		{
			return std::string(e.what());
		}
		return std::string("no error");
	};
	EXPECT_EQ(errorOf("0 0 1 0\n"), p + ":1: expected 'x1 y1 x2 y2 p_static [static|dynamic]', found 4 fields");
	EXPECT_EQ(errorOf("\n0 0 1 0 1.5\n"), p + ":2: p_static is 1.5 (must be in [0, 1])");
	EXPECT_EQ(errorOf("0 0 1 nan 0.5\n"), p + ":1: y2 is 'nan' (not a finite number)");
	EXPECT_EQ(errorOf("0 0 1 0 0.5 maybe\n"), p + ":1: label is 'maybe' (expected static or dynamic)");
	fs::remove(p);
}

TEST(SegmentIndex, FindsTheNearestSegmentWithinRange)
{
	std::vector<Segment> segs;
	for (int i = 0; i < 50; i++) segs.emplace_back(i * 0.7, std::sin(i), i * 0.7 + 3.3, std::cos(i) * 4);
	const eval::SegmentIndex idx(segs, 0.5);
	for (double x = -2; x < 40; x += 0.37)
		for (double y = -6; y < 6; y += 0.41)
		{
			double brute = sim::kNoHit;
			for (const auto& s : segs) brute = std::min(brute, sim::distanceToSegment({x, y}, s));
			const double got = idx.nearest({x, y}, 0.8);
			if (brute <= 0.8)
				EXPECT_DOUBLE_EQ(got, brute);
			else
				EXPECT_EQ(got, sim::kNoHit);
		}
}

TEST(MapEval, TransformMovesVectorsAndDoorsRigidly)
{
	eval::MapVector v;
	v.seg = sim::Segment(1, 0, 2, 0);
	const auto out = eval::transformVectors({v}, mrpt::math::TPose2D(10, 5, M_PI / 2));
	ASSERT_EQ(out.size(), 1u);
	EXPECT_NEAR(out[0].seg.a.x, 10, 1e-12);
	EXPECT_NEAR(out[0].seg.a.y, 6, 1e-12);
	EXPECT_NEAR(out[0].seg.b.y, 7, 1e-12);
	sim::DoorTruth d;
	d.hinge = sim::Vec2(1, 0);
	d.closedAngle = 0.2;
	const auto dd = eval::transformDoors({d}, mrpt::math::TPose2D(0, 0, M_PI));
	EXPECT_NEAR(dd[0].hinge.x, -1, 1e-12);
	EXPECT_NEAR(dd[0].closedAngle, 0.2 + M_PI, 1e-12);
}
