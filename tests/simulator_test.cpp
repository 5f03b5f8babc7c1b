// gv-sim: determinism, beam labels against the geometry, odometry noisy while
// the truth is not, output files readable by the project's own readers.
#include "eval/TrajectoryEval.h"
#include "io/AtomicFile.h"
#include <gridvector/io/LogReader.h>
#include "sim/BuiltinWorlds.h"
#include "sim/OdometryNoise.h"
#include "sim/People.h"
#include "sim/Simulator.h"
#include "sim/TruthFiles.h"

#include <gtest/gtest.h>

#include <filesystem>

using namespace gridvector;
using namespace gridvector::sim;
namespace fs = std::filesystem;

namespace
{
SimOptions small(const std::string& world, int scans = 300)
{
	SimOptions o;
	o.world = world;
	o.scans = scans;
	return o;
}

double nearestWall(const Vec2& p, const std::vector<Segment>& walls)
{
	double d = kNoHit;
	for (const auto& w : walls) d = std::min(d, distanceToSegment(p, w));
	return d;
}

io::Trajectory track(const SimResult& r, bool truth)
{
	io::Trajectory t;
	for (const auto& s : r.scans) t.emplace_back(s.t, truth ? s.truth : s.odometry);
	return t;
}
}  // namespace

TEST(Simulator, DeterministicPerSeed)
{
	const SimResult a = simulate(small("long-corridor")), b = simulate(small("long-corridor"));
	SimOptions o = small("long-corridor");
	o.seed = 2;
	const SimResult c = simulate(o);
	ASSERT_EQ(a.scans.size(), 300u);
	ASSERT_EQ(a.scans.size(), b.scans.size());
	size_t differ = 0;
	for (size_t k = 0; k < a.scans.size(); k++)
	{
		EXPECT_EQ(a.scans[k].ranges, b.scans[k].ranges);
		EXPECT_EQ(a.scans[k].labels, b.scans[k].labels);
		EXPECT_EQ(a.scans[k].odometry.x, b.scans[k].odometry.x);
		differ += a.scans[k].ranges != c.scans[k].ranges;
	}
	EXPECT_GT(differ, 250u);  // another seed: other noise, people and doors
	EXPECT_EQ(a.stats.dynamicHits, b.stats.dynamicHits);
	EXPECT_EQ(a.dynamicHits.size(), b.dynamicHits.size());
}

TEST(Simulator, BeamLabelsAgreeWithTheGeometry)
{
	for (const auto& name : builtinWorldNames())
	{
		SCOPED_TRACE(name);
		SimOptions o = small(name, 400);
		o.rangeSigma = 0;  // exact ranges: hit points lie on what they hit
		const SimResult r = simulate(o);
		const Laser laser(r.laser);
		std::vector<Segment> doorAreas, objectEdges;
		for (const auto& d : r.world.doors)
			for (int k = 0; k <= 90; k++)
				doorAreas.push_back(d.leaf(d.closedAngle + (d.openAngle - d.closedAngle) * k / 90.0));
		for (const auto& ob : r.world.objects)
			for (const auto* p : {&ob.first, &ob.second})
				for (size_t i = 0; i < p->size(); i++) objectEdges.emplace_back((*p)[i], (*p)[(i + 1) % p->size()]);
		size_t counts[5] = {0, 0, 0, 0, 0};
		for (size_t k = 0; k < r.scans.size(); k += 7)
		{
			const SimScan& s = r.scans[k];
			ASSERT_EQ(s.labels.size(), s.ranges.size());
			for (size_t i = 0; i < s.ranges.size(); i++)
			{
				const HitKind kind = labelKind(s.labels[i]);
				counts[int(kind)]++;
				const Vec2 p =
					Vec2(s.truth.x, s.truth.y) + Vec2::polar(s.ranges[i], s.truth.phi + laser.beamAngle(int(i)));
				switch (kind)
				{
					case HitKind::None:
						EXPECT_FLOAT_EQ(s.ranges[i], float(o.maxRange));
						break;
					case HitKind::Static:
						EXPECT_LT(nearestWall(p, r.world.walls), 1e-3);
						break;
					case HitKind::Door:
						EXPECT_LT(nearestWall(p, doorAreas), 0.02);
						break;
					case HitKind::Object:
						EXPECT_LT(nearestWall(p, objectEdges), 1e-3);
						break;
					case HitKind::Person:
						EXPECT_GT(nearestWall(p, r.world.walls), 0.05);
						break;
				}
				if (kind != HitKind::None)
				{
					EXPECT_LT(s.ranges[i], o.maxRange);
				}
			}
		}
		EXPECT_GT(counts[int(HitKind::Static)], 1000u);
		EXPECT_GT(counts[int(HitKind::Person)], 0u);
		EXPECT_GT(counts[int(HitKind::Door)], 0u);
		// the statistics count what the labels say
		size_t dyn = 0, all = 0;
		for (const auto& s : r.scans)
			for (char c : s.labels) dyn += isDynamic(labelKind(c)), all++;
		EXPECT_EQ(dyn, r.stats.dynamicHits);
		EXPECT_EQ(all, r.stats.beams);
	}
}

TEST(Simulator, OdometryIsNoisyAndTheTruthIsNot)
{
	const SimResult r = simulate(small("corridor-loop", 1200));
	// the true path lies on the corridor centre lines the route follows
	for (const auto& s : r.scans)
	{
		const bool onLine = std::abs(s.truth.y - 6.2) < 1e-6 || std::abs(s.truth.y - 13.8) < 1e-6 ||
							std::abs(s.truth.x - 1.2) < 1e-6 || std::abs(s.truth.x - 36.8) < 1e-6;
		EXPECT_TRUE(onLine) << s.truth.x << " " << s.truth.y;
	}
	EXPECT_NEAR(r.stats.pathLength, 0.5 * 0.2 * 1199, 15.0);  // ~0.1 m per scan, less the turns
	const auto m = eval::evaluateTrajectory(track(r, false), track(r, true));
	EXPECT_GT(m.ateRmse, 0.5);
	EXPECT_GT(m.localRDeg, 0.05);
	EXPECT_EQ(r.scans[0].odometry.x, 0.0);  // dead reckoning starts at the origin
	// without noise and drift, odometry is the truth in another frame
	SimOptions o = small("corridor-loop", 1200);
	o.sigmaT = o.sigmaR = o.driftDegPerM = 0;
	const SimResult exact = simulate(o);
	EXPECT_LT(eval::evaluateTrajectory(track(exact, false), track(exact, true)).ateRmse, 1e-6);
	// drift alone bends odometry by 0.8 deg per metre travelled
	o.driftDegPerM = 0.8;
	const SimResult drift = simulate(o);
	const double dTheta = wrapAngle(drift.scans.back().odometry.phi - drift.scans.back().truth.phi);
	EXPECT_NEAR(std::abs(dTheta), wrapAngle(0.8 * M_PI / 180 * drift.stats.pathLength), 1e-6);
}

TEST(Simulator, DynamicContentIsConfigurable)
{
	SimOptions o = small("long-corridor", 400);
	o.people = 0;
	o.doors = false;
	o.movedObject = false;
	const SimResult still = simulate(o);
	EXPECT_EQ(still.stats.dynamicHits, 0u);
	EXPECT_TRUE(still.dynamicHits.empty());
	EXPECT_TRUE(still.world.doors.empty());
	o.people = 15;
	o.doors = o.movedObject = true;
	const SimResult busy = simulate(o);
	EXPECT_EQ(busy.stats.people, 15u);
	EXPECT_GT(busy.stats.personHits, simulate(small("long-corridor", 400)).stats.personHits);
	EXPECT_GT(busy.stats.doorSwings, 0u);
	// the moved object is seen at its first place before the move and at its second after
	const SimResult full = simulate(small("long-corridor", 0));
	const auto& ob = full.world.objects.at(0);
	std::vector<Segment> first, second;
	for (size_t i = 0; i < ob.first.size(); i++) first.emplace_back(ob.first[i], ob.first[(i + 1) % ob.first.size()]);
	for (size_t i = 0; i < ob.second.size(); i++)
		second.emplace_back(ob.second[i], ob.second[(i + 1) % ob.second.size()]);
	size_t before = 0, after = 0;
	for (const auto& h : full.dynamicHits)
		if (h.kind == HitKind::Object)
		{
			const bool early = h.t - full.options.startTime < full.objectMoveTime;
			EXPECT_LT(nearestWall(h.seg.a, early ? first : second), 0.06);
			(early ? before : after)++;
		}
	EXPECT_GT(before, 0u);
	EXPECT_GT(after, 0u);
	EXPECT_THROW(simulate(small("no-such-world")), std::invalid_argument);
	// the refused key as visit() names it, and the problem apart (gv-sim words flags and .ini keys from them)
	using Refusal = std::pair<std::string, std::string>;  // key, problem
	auto refusal = [](const SimOptions& o) -> Refusal {
		try
		{
			o.validate();
		}
		catch (const SimOptionError& e)
		{
			return {e.key, e.problem};
		}
		return {};
	};
	EXPECT_EQ(refusal(small("no_such_world")), Refusal("world", "must be one of corridor-loop, office, long-corridor"));
	SimOptions turn = small("office");
	turn.turnRateDeg = 400;
	EXPECT_EQ(refusal(turn), Refusal("turn_rate_deg", "must be in (0, 360]"));
	SimOptions bad = small("office");
	bad.beams = 1;
	EXPECT_THROW(simulate(bad), std::invalid_argument);
}

TEST(Simulator, WritesALogTheReadersAcceptAndTruthFiles)
{
	const SimResult r = simulate(small("office", 250));
	const std::string dir = (fs::temp_directory_path() / "gv_simulator_test").string();
	fs::remove_all(dir);
	writeSimulation(r, dir);
	const io::LogData log = io::readLog(dir + "/" + SimFiles::log);
	ASSERT_EQ(log.scans.size(), r.scans.size());
	for (size_t k = 0; k < r.scans.size(); k += 11)
	{
		const auto& s = log.scans[k];
		EXPECT_NEAR(s.timestamp, r.scans[k].t, 1e-6);
		EXPECT_NEAR(s.odometry.x, r.scans[k].odometry.x, 1e-6);  // the log shows odometry, never the truth
		EXPECT_NEAR(s.logPose.phi, r.scans[k].odometry.phi, 1e-6);
		EXPECT_NEAR(s.scan->aperture, M_PI, 1e-6);
		EXPECT_FLOAT_EQ(s.scan->maxRange, float(r.options.maxRange));
		for (size_t i = 0; i < s.scan->getScanSize(); i++)
		{
			EXPECT_NEAR(s.scan->getScanRange(i), r.scans[k].ranges[i], 6e-4);
			EXPECT_EQ(s.scan->getScanRangeValidity(i), r.scans[k].labels[i] != '-');
		}
	}
	const auto truth = io::readTrajectory(dir + "/" + SimFiles::trajectory);
	ASSERT_EQ(truth.size(), r.scans.size());
	EXPECT_NEAR(truth[100].second.x, r.scans[100].truth.x, 1e-6);
	const Truth t = readTruth(dir);
	EXPECT_EQ(t.walls.size(), r.world.walls.size());
	EXPECT_EQ(t.doors.size(), r.world.doors.size());
	EXPECT_EQ(t.hits.size(), r.dynamicHits.size());
	EXPECT_EQ(t.seenWalls.size(), r.seenWalls.size());
	EXPECT_EQ(t.objectEdges.size(), 8u);
	EXPECT_NEAR(t.objectMoveTime, r.options.startTime + r.objectMoveTime, 1e-6);
	size_t swings = 0;
	for (const auto& d : t.doors) swings += size_t(d.swings);
	EXPECT_EQ(swings, t.doorSwings.size());
	fs::remove_all(dir);
}

// truth_dynamic.txt may only name doors of truth_doors.txt: an unknown door's hit would be a dynamic
// place to the ghost figures but no door to the breakdown and the recalls (they would not add up).
TEST(Simulator, TruthRejectsDoorsNotInTheDoorsFile)
{
	const std::string dir = (fs::temp_directory_path() / "gv_simulator_truth_doors").string();
	fs::remove_all(dir);
	fs::create_directories(dir);
	const auto write = [&](const char* name, const std::string& text) {
		io::writeFileAtomically(dir + "/" + name, [&](std::ostream& os) { os << text; });
	};
	write(SimFiles::walls, "0 0 10 0\n");
	write(SimFiles::seenWalls, "0 0 10 0\n");
	write(SimFiles::doors, "5 0 0.9 0 1.5 1\n");
	const auto errorOf = [&](const std::string& dynamic) {
		write(SimFiles::dynamic, dynamic);
		try
		{
			const Truth t = readTruth(dir);
			return "read " + std::to_string(t.hits.size()) + " hits, " + std::to_string(t.doorSwings.size()) +
				   " swings";
		}
		catch (const std::runtime_error& e)
		{
			return std::string(e.what());
		}
	};
	const std::string file = dir + "/" + SimFiles::dynamic;
	EXPECT_EQ(errorOf("hit door 0 1 5 0.1 5 0.8 4\ndoor_swing 0 2 3 0 1.5\nhit person 7 1 3 1 4 1 5\n"),
			  "read 2 hits, 1 swings");
	EXPECT_EQ(errorOf("hit person 0 1 3 1 4 1 5\nhit door 1 1 5 0.1 5 0.8 4\n"),
			  file + ":2: door 1 is not in truth_doors.txt (1 door)");
	EXPECT_EQ(errorOf("door_swing 3 2 3 0 1.5\n"),
			  file + ":1: door 3 is not in truth_doors.txt (1 door)");  // not "1 doors"
	write(SimFiles::doors, "");
	EXPECT_EQ(errorOf("hit door 0 1 5 0.1 5 0.8 4\n"), file + ":1: door 0 is not in truth_doors.txt (0 doors)");
	fs::remove_all(dir);
}

TEST(Simulator, DoorTimelineSwingsSmoothly)
{
	DoorTimeline tl;
	tl.initial = 0;
	tl.swings = {{10, 12, 0, 1.5}, {20, 21, 1.5, 0}};
	EXPECT_DOUBLE_EQ(tl.angleAt(5), 0);
	EXPECT_NEAR(tl.angleAt(11), 0.75, 1e-12);
	EXPECT_DOUBLE_EQ(tl.angleAt(15), 1.5);
	EXPECT_DOUBLE_EQ(tl.angleAt(30), 0);
}

TEST(Scene, FanCastingEqualsOneRayAtATime)
{
	const World w = makeWorld("office");
	Scene scene(w.walls);
	Random rng(5);
	for (int k = 0; k < 6; k++) scene.addCircle({{rng.uniform(1, 19), rng.uniform(1, 7)}, 0.25}, k);
	scene.addSegment({{3, 3}, {5, 6}}, HitKind::Door, 0);
	for (int trial = 0; trial < 300; trial++)
	{
		const Vec2 o(rng.uniform(0.5, 19.5), rng.uniform(0.5, 7.5));
		const int n = trial % 3 == 0 ? 720 : trial % 3 == 1 ? 361 : 180;  // 360 deg fans wrap around
		const double res = (trial % 3 == 0 ? 2 * M_PI : M_PI) / (n % 2 ? n - 1 : n);
		const double start = rng.uniform(-4, 4);
		const auto fan = scene.castFan(o, start, res, n, 25.0);
		for (int i = 0; i < n; i++)
		{
			const Hit h = scene.cast(o, Vec2::polar(1.0, start + i * res), 25.0);
			ASSERT_EQ(fan[size_t(i)].kind, h.kind) << trial << " beam " << i;
			ASSERT_EQ(fan[size_t(i)].id, h.id);
			if (h.kind != HitKind::None)
			{
				ASSERT_DOUBLE_EQ(fan[size_t(i)].range, h.range);
			}
		}
	}
}

// --door-swing-period: a door used all day swings again every P..2P s, many times a run;
// 0 keeps the 2-4 swings of a run (and the same random draws: the default logs do not change)
TEST(Simulator, DoorsSwingEveryPeriodWhenAsked)
{
	SimOptions o = small("corridor-loop", 1500);  // 300 s
	const SimResult few = simulate(o);
	for (const auto& tl : few.doors) EXPECT_LE(tl.swings.size(), 4u);
	o.doorSwingPeriod = 30;
	const SimResult many = simulate(o);
	ASSERT_EQ(many.doors.size(), few.doors.size());
	for (const auto& tl : many.doors)
	{
		EXPECT_GE(tl.swings.size(), 4u);  // 300 s at one swing per 30-60 s (+ the swing's own 1-2.5 s)
		EXPECT_LE(tl.swings.size(), 10u);
		for (size_t k = 1; k < tl.swings.size(); ++k)
		{
			EXPECT_GE(tl.swings[k].t0 - tl.swings[k - 1].t0, 30 - 1e-9);
			EXPECT_LE(tl.swings[k].t0 - tl.swings[k - 1].t0, 60 + 1e-9);
			EXPECT_NE(tl.swings[k].from, tl.swings[k].to);  // open <-> closed each time
		}
	}
	o.doorSwingPeriod = 2;
	EXPECT_THROW(o.validate(), SimOptionError);
	o.doorSwingPeriod = 0;
	o.pauseS = -1;
	EXPECT_THROW(o.validate(), SimOptionError);
}

// --pause-s: a pauser (every third person, the second) stands still pause_s..2 pause_s s
TEST(Simulator, PausersStandStillForMinutesWhenAsked)
{
	const World w = makeWorld("corridor-loop");
	const WalkGraph graph(w, 0.35);
	const auto stillFor = [&](double pauseS) {
		Random rng(7);
		Crowd crowd(graph, w.walls, 3, {w.start.x, w.start.y}, rng, pauseS);
		const Vec2 start = crowd.people().at(1).pos, far(-100, -100);  // the robot far away
		double t = 0;
		while (t < 400 && (crowd.people().at(1).pos - start).norm() < 1e-9) crowd.step(0.2, far), t += 0.2;
		return t;
	};
	EXPECT_LE(stillFor(0), 10.2);  // the first pause: 0-10 s
	const double minutes = stillFor(120);
	EXPECT_GE(minutes, 120 - 0.2);
	EXPECT_LE(minutes, 240 + 0.2);
}
