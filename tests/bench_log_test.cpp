// gv-bench-log: the same numbers as ../shared/bench/mkbench.py (Python's random
// module reproduced draw for draw), and the noise model itself.
#include "eval/TrajectoryEval.h"
#include "io/AtomicFile.h"
#include "io/FileBytes.h"
#include <gridvector/io/LogReader.h>
#include "sim/BenchmarkLog.h"
#include "sim/OdometryNoise.h"
#include "sim/Random.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

using namespace gridvector;
namespace fs = std::filesystem;

namespace
{
const std::string kIntel = std::string(GV_SHARED_DIR) + "/data/intel-corrected.log.gz";
std::string tmp(const std::string& n) { return (fs::temp_directory_path() / ("gv_bench_log_test_" + n)).string(); }
}  // namespace

TEST(Random, SameNumbersAsPythonsRandomModule)
{
	// python3 -c "import random; r=random.Random(1); print([r.random() for _ in range(3)])"
	sim::Random a(1);
	EXPECT_DOUBLE_EQ(a.uniform(), 0.13436424411240122);
	EXPECT_DOUBLE_EQ(a.uniform(), 0.8474337369372327);
	EXPECT_DOUBLE_EQ(a.uniform(), 0.763774618976614);
	// ... [r.gauss(0, 1) for _ in range(3)]
	sim::Random g(1);
	EXPECT_DOUBLE_EQ(g.gauss(0, 1), 1.2881847531554629);
	EXPECT_DOUBLE_EQ(g.gauss(0, 1), 1.449445608699771);
	EXPECT_DOUBLE_EQ(g.gauss(0, 1), 0.06633580893826191);
	// seeds wider than 32 bits: random.Random(2**40 + 5).random()
	EXPECT_DOUBLE_EQ(sim::Random((uint64_t(1) << 40) + 5).uniform(), 0.5043802970418443);
}

TEST(BenchmarkLog, ReferenceIsTheCorrectedPoseAndOdometryFollowsTheModel)
{
	const std::string out = tmp("intel");
	const auto sum = sim::makeBenchmarkLog(kIntel, out);
	EXPECT_EQ(sum.scans, 910u);
	const auto ref = io::readTrajectory(sum.refPath);
	const auto corrected = io::trajectoryOf(io::readLog(kIntel), true);
	ASSERT_EQ(ref.size(), corrected.size());
	for (size_t k = 0; k < ref.size(); k++)
	{
		EXPECT_NEAR(ref[k].first, 1100000000.0 + 0.2 * double(k + 1), 1e-3);  // t += dt, as mkbench.py
		EXPECT_NEAR(ref[k].second.x, corrected[k].second.x, 1e-6);
	}
	const io::LogData log = io::readLog(sum.logPath);
	ASSERT_EQ(log.scans.size(), 910u);
	EXPECT_NEAR(log.scans[0].scan->aperture, 179 * M_PI / 180, 1e-6);  // PARAM resolution 1 for 180 beams
	EXPECT_FLOAT_EQ(log.scans[0].scan->maxRange, 81.0f);
	EXPECT_EQ(log.scans[0].odometry.x, 0.0);
	const auto odo = io::trajectoryOf(log);
	const auto m = eval::evaluateTrajectory(odo, ref);
	EXPECT_GT(m.ateRmse, 1.0);  // 5 %, 0.02 rad per step and 0.8 deg/m drift leave a large error
	// noise off: odometry is the reference in another frame
	sim::BenchmarkOptions exact;
	exact.noise = {0, 0, 0};
	const auto s2 = sim::makeBenchmarkLog(kIntel, out, exact);
	EXPECT_LT(
		eval::evaluateTrajectory(io::trajectoryOf(io::readLog(s2.logPath)), io::readTrajectory(s2.refPath)).ateRmse,
		2e-5);
	fs::remove(sum.logPath);
	fs::remove(sum.refPath);
}

TEST(BenchmarkLog, ByteIdenticalToMkbenchPy)
{
	const std::string py = std::string(GV_SHARED_DIR) + "/bench/mkbench.py";
	if (std::system("command -v python3 >/dev/null 2>&1") != 0 || !fs::exists(py))
		GTEST_SKIP() << "python3 or mkbench.py missing";
	for (int seed : {1, 3})
	{
		sim::BenchmarkOptions o;
		o.seed = seed;
		const auto ours = sim::makeBenchmarkLog(kIntel, tmp("ours"), o);
		const std::string theirs = tmp("theirs");
		ASSERT_EQ(
			std::system(
				("python3 '" + py + "' '" + kIntel + "' '" + theirs + "' --seed " + std::to_string(seed)).c_str()),
			0);
		EXPECT_TRUE(io::readFileBytes(ours.logPath) == io::readFileBytes(theirs + ".log")) << "seed " << seed;
		EXPECT_TRUE(io::readFileBytes(ours.refPath) == io::readFileBytes(theirs + ".ref.txt")) << "seed " << seed;
		for (const auto& p : {ours.logPath, ours.refPath, theirs + ".log", theirs + ".ref.txt"}) fs::remove(p);
	}
}

TEST(BenchmarkLog, MalformedInputIsAnError)
{
	const std::string in = tmp("bad.log");
	io::writeFileAtomically(in, [](std::ostream& os) {
		os << "PARAM x 1\nFLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 1 h 1\nFLASER 3 1.0 -2.0 3.0 0 0 0 0 0 0 1 h 1\nFLASER 3 1 "
			  "1\n";
	});
	try
	{
		sim::makeBenchmarkLog(in, tmp("bad_out"));
		ADD_FAILURE();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()), in + ":3: FLASER range 1 is -2.0 (negative)");
	}
	EXPECT_FALSE(fs::exists(tmp("bad_out") + ".log"));  // nothing half-written
	io::writeFileAtomically(in, [](std::ostream& os) { os << "ODOM 0 0 0 0 0 0 1 h 1\n"; });
	EXPECT_THROW(sim::makeBenchmarkLog(in, tmp("bad_out")), std::runtime_error);
	fs::remove(in);
}

TEST(BenchmarkLog, WrongBeamCountIsAnErrorNotAShiftedPose)
{
	// "FLASER 2" over 3 ranges: mkbench.py would take the third range as x, x as y, y as theta
	const std::string in = tmp("beams.log");
	io::writeFileAtomically(in, [](std::ostream& os) {
		os << "FLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 1 h 1\nFLASER 2 1.0 2.0 3.0 0.5 0.25 0 0.5 0.25 0 1.2 h 1.2\n";
	});
	try
	{
		sim::makeBenchmarkLog(in, tmp("beams_out"));
		ADD_FAILURE() << "accepted";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()), in + ":2: FLASER: 2 beams announced: expected 13 fields, found 14");
	}
	EXPECT_FALSE(fs::exists(tmp("beams_out") + ".log"));
	EXPECT_FALSE(fs::exists(tmp("beams_out") + ".ref.txt"));
	// the single-timestamp layout the log readers accept is accepted here too
	io::writeFileAtomically(in, [](std::ostream& os) { os << "FLASER 3 1.0 2.0 3.0 0 0 0 0 0 0 1\n"; });
	EXPECT_EQ(sim::makeBenchmarkLog(in, tmp("beams_out")).scans, 1u);
	for (const char* f : {".log", ".ref.txt"}) fs::remove(tmp("beams_out") + f);
	fs::remove(in);
}

TEST(OdometryNoise, DriftAloneTurnsByTheDistanceTravelled)
{
	sim::Random rng(1);
	sim::NoisyOdometry odo({0, 0, 0.8}, rng);
	mrpt::math::TPose2D last;
	for (int k = 0; k <= 100; k++) last = odo.step({0.1 * k, 0, 0});  // 10 m straight
	EXPECT_NEAR(last.phi, 8.0 * M_PI / 180, 1e-12);
}
