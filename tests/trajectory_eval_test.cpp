// Trajectory metrics: known answers, timestamp matching, and agreement with
// ../shared/bench/evaltraj.py on a benchmark made from a real log.
#include "eval/TrajectoryEval.h"
#include <gridvector/io/LogReader.h>
#include "io/JsonFile.h"
#include "sim/BenchmarkLog.h"
#include "sim/Random.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

using namespace gridvector;
using mrpt::math::TPose2D;
namespace fs = std::filesystem;

namespace
{
/** A lawnmower path with a loop back over the start, 0.2 s apart. */
io::Trajectory path(size_t n)
{
	io::Trajectory t;
	for (size_t k = 0; k < n; k++)
	{
		const double a = 2 * M_PI * double(k) / double(n);
		t.emplace_back(100.0 + 0.2 * double(k), TPose2D(8 * std::cos(a), 5 * std::sin(2 * a), a + 0.3));
	}
	return t;
}

io::Trajectory transformed(const io::Trajectory& t, double dx, double dy, double th)
{
	io::Trajectory o;
	for (const auto& [s, p] : t)
		o.emplace_back(s, TPose2D(std::cos(th) * p.x - std::sin(th) * p.y + dx,
								  std::sin(th) * p.x + std::cos(th) * p.y + dy, p.phi + th));
	return o;
}

std::map<std::string, double> parseKeyValues(const std::string& line)
{
	std::map<std::string, double> m;
	std::istringstream in(line);
	std::string kv;
	while (in >> kv)
	{
		const auto eq = kv.find('=');
		if (eq != std::string::npos) m[kv.substr(0, eq)] = std::stod(kv.substr(eq + 1));
	}
	return m;
}

std::string run(const std::string& cmd)
{
	std::string out;
	FILE* p = popen(cmd.c_str(), "r");
	if (!p) return out;
	char buf[512];
	while (fgets(buf, sizeof buf, p)) out += buf;
	pclose(p);
	return out;
}
}  // namespace

TEST(TrajectoryEval, IdentityAndRigidMotionGiveZero)
{
	const auto ref = path(400);
	for (const auto& est : {ref, transformed(ref, 3.0, -7.5, 1.1)})
	{
		const auto m = eval::evaluateTrajectory(est, ref);
		EXPECT_EQ(m.matched, 400u);
		EXPECT_LT(m.ateRmse, 1e-9);
		EXPECT_LT(m.localT, 1e-9);
		EXPECT_LT(m.localRDeg, 1e-9);
		EXPECT_LT(m.loopT, 1e-9);
		EXPECT_EQ(m.localPairs, 399u);
		EXPECT_GT(m.loopPairs, 0u);
	}
}

TEST(TrajectoryEval, KnownErrors)
{
	const auto ref = path(300);
	// positions shifted, headings turned by 0.01 rad: ATE 0, local rotation error 0
	io::Trajectory shifted;
	for (const auto& [t, p] : ref) shifted.emplace_back(t, TPose2D(p.x + 0.1, p.y, p.phi + 0.01));
	const auto m = eval::evaluateTrajectory(shifted, ref);
	EXPECT_NEAR(m.ateRmse, 0.0, 1e-9);  // a pure translation is aligned away
	EXPECT_NEAR(m.localRDeg, 0.0, 1e-9);  // the constant heading offset cancels in relations
	// every pose displaced alternately by +-0.2 m in y: ATE 0.2, local relation error 0.4 m
	io::Trajectory zig;
	for (size_t k = 0; k < ref.size(); k++)
		zig.emplace_back(ref[k].first,
						 TPose2D(ref[k].second.x, ref[k].second.y + (k % 2 ? 0.2 : -0.2), ref[k].second.phi));
	const auto z = eval::evaluateTrajectory(zig, ref);
	EXPECT_NEAR(z.ateRmse, 0.2, 2e-3);
	EXPECT_NEAR(z.localT, 0.4, 1e-9);
}

TEST(TrajectoryEval, MatchesByTimestampWithin50ms)
{
	const auto ref = path(200);
	io::Trajectory est;
	for (size_t k = 0; k < ref.size(); k++)
	{
		if (k % 4 == 0) continue;  // missing poses
		const double jitter = (k % 3 == 0) ? 0.03 : (k % 3 == 1 ? -0.049 : 0.07);  // the last is too far
		est.emplace_back(ref[k].first + jitter, ref[k].second);
	}
	std::reverse(est.begin(), est.end());  // order does not matter
	const auto pairs = eval::matchByTimestamp(est, ref, 0.05);
	size_t expect = 0;
	for (size_t k = 0; k < ref.size(); k++) expect += k % 4 != 0 && k % 3 != 2;
	EXPECT_EQ(pairs.size(), expect);
	EXPECT_THROW(eval::evaluateTrajectory(io::Trajectory(est.begin(), est.begin() + 2), ref), std::runtime_error);
	EXPECT_EQ(eval::formatText(eval::evaluateTrajectory(ref, ref)).rfind("n=200 ate_rmse_m=0.0000 ", 0), 0u);
}

TEST(TrajectoryEval, AgreesWithEvaltrajPy)
{
	const std::string py = std::string(GV_SHARED_DIR) + "/bench/evaltraj.py";
	if (run("command -v python3").empty() || !fs::exists(py)) GTEST_SKIP() << "python3 or evaltraj.py not available";
	const std::string dir = (fs::temp_directory_path() / "gv_trajectory_eval_test").string();
	fs::create_directories(dir);
	const auto bench =
		sim::makeBenchmarkLog(std::string(GV_SHARED_DIR) + "/data/intel-corrected.log.gz", dir + "/intel");
	const auto ref = io::readTrajectory(bench.refPath);
	const auto odo = io::trajectoryOf(io::readLog(bench.logPath));
	// estimates: raw odometry, and a thinned, jittered, noisy odometry
	io::Trajectory odd;
	sim::Random rng(7);
	for (size_t k = 0; k < odo.size(); k++)
		if (k % 5 != 0)
			odd.emplace_back(
				odo[k].first + rng.uniform(-0.06, 0.06),
				TPose2D(odo[k].second.x + rng.gauss(0, 0.3), odo[k].second.y, odo[k].second.phi + rng.gauss(0, 0.05)));
	for (const auto& est : {odo, odd, ref})
	{
		io::writeTrajectory(dir + "/est.txt", est);
		const auto theirs = parseKeyValues(run("python3 '" + py + "' '" + dir + "/est.txt' '" + bench.refPath + "'"));
		const auto m = eval::evaluateTrajectory(est, ref);
		const auto ours = parseKeyValues(eval::formatText(m));
		ASSERT_EQ(theirs.size(), 7u);
		for (const auto& [k, v] : theirs) EXPECT_NEAR(ours.at(k), v, 1e-3) << k;
		EXPECT_NEAR(m.ateRmse, theirs.at("ate_rmse_m"), 1e-3);
	}
	fs::remove_all(dir);
}

TEST(TrajectoryEval, AlignmentTransformRecoversTheFrameOffset)
{
	// Reference in the truth frame; the estimate is the same path seen from a frame
	// rotated by 0.7 rad and shifted by (1.2, 6.2), as a map built from odometry is.
	const mrpt::math::TPose2D T(1.2, 6.2, 0.7);
	gridvector::io::Trajectory ref, est;
	for (int i = 0; i < 50; ++i)
	{
		const double t = 100 + 0.2 * i, x = 0.1 * i, y = std::sin(0.2 * i);
		ref.push_back({t, mrpt::math::TPose2D(x, y, 0.1 * i)});
		const double c = std::cos(-T.phi), s = std::sin(-T.phi), dx = x - T.x, dy = y - T.y;
		est.push_back({t, mrpt::math::TPose2D(c * dx - s * dy, s * dx + c * dy, 0.1 * i - T.phi)});
	}
	const auto A = gridvector::eval::alignmentTransform(est, ref);
	EXPECT_NEAR(A.x, T.x, 1e-9);
	EXPECT_NEAR(A.y, T.y, 1e-9);
	EXPECT_NEAR(A.phi, T.phi, 1e-9);
}

namespace
{
/** path(n) with its first `tied` poses at one time, as csail-corrected's six-digit timestamps. */
io::Trajectory tiedPath(size_t n, size_t tied)
{
	io::Trajectory t = path(n);
	for (size_t k = 0; k < tied; k++) t[k].first = 100.0;
	return t;
}
}  // namespace

TEST(TrajectoryEval, TimesSharedByDifferentPosesAreMatchedByOrderWhenBothArePerScan)
{
	const auto ref = tiedPath(200, 120);
	const auto est = transformed(ref, 3.0, -7.5, 1.1);  // the same path in another frame: every error 0
	const auto m = eval::matchPoses(est, ref, 0.05);
	EXPECT_TRUE(m.byOrder);
	EXPECT_EQ(m.why, "120 estimate poses share t = 100.000000 and differ");
	ASSERT_EQ(m.pairs.size(), 200u);
	const auto byOrder = eval::evaluatePairs(m.pairs);
	EXPECT_LT(byOrder.ateRmse, 1e-9);
	EXPECT_LT(byOrder.loopT, 1e-9);
	// by time (evaltraj.py) all 120 go to one estimate pose
	EXPECT_GT(eval::evaluateTrajectory(est, ref).ateRmse, 1.0);
}

TEST(TrajectoryEval, AlignmentTransformMatchesAsGvEvalTraj)
{
	// gv-eval map --trajectory aligns the map by the trajectory's SE(2) alignment: where times are
	// shared by different poses, pairing by time sent all 120 tied reference poses to one estimate pose
	const auto ref = tiedPath(200, 120);
	const auto est = transformed(ref, 3.0, -7.5, 1.1);  // the same path in another frame
	const auto A = eval::alignmentTransform(est, ref, 0.05);
	EXPECT_TRUE(A == eval::alignmentTransform(eval::matchPoses(est, ref, 0.05).pairs));
	auto worst = [&](const TPose2D& T) {  // largest distance of an aligned estimate position from its reference
		double w = 0;
		for (size_t k = 0; k < ref.size(); k++)
		{
			const auto& e = est[k].second;
			const double x = std::cos(T.phi) * e.x - std::sin(T.phi) * e.y + T.x,
						 y = std::sin(T.phi) * e.x + std::cos(T.phi) * e.y + T.y;
			w = std::max(w, std::hypot(x - ref[k].second.x, y - ref[k].second.y));
		}
		return w;
	};
	EXPECT_LT(worst(A), 1e-6);
	EXPECT_GT(worst(eval::alignmentTransform(eval::matchByTimestamp(est, ref, 0.05))),
			  1.0);  // what pairing by time gave
	auto fewer = est;
	fewer.pop_back();
	EXPECT_THROW(eval::alignmentTransform(fewer, ref, 0.05), std::runtime_error);  // refused as gv-eval traj refuses it
}

TEST(TrajectoryEval, TimesSharedByDifferentPosesWithoutOnePosePerScanAreAnError)
{
	const auto ref = tiedPath(200, 120);
	auto fewer = ref;
	fewer.pop_back();
	auto shifted = ref;
	shifted[150].first += 1.0;
	for (const auto& [est, what] :
		 {std::pair(fewer, std::string("199 estimate and 200 reference poses)")),
		  std::pair(shifted, std::string("200 estimate and 200 reference poses, pose 151 at other times)"))})
		try
		{
			eval::matchPoses(est, ref, 0.05);
			ADD_FAILURE() << what;
		}
		catch (const std::runtime_error& e)
		{
			const std::string msg = e.what();
			EXPECT_EQ(msg.rfind("120 estimate poses share t = 100.000000 and differ: ", 0), 0u) << msg;
			EXPECT_NE(msg.find(what), std::string::npos) << msg;
		}
}

TEST(TrajectoryEval, UnambiguousTimesAreMatchedByTimeAsEvaltrajPy)
{
	// distinct times (a thinned, jittered estimate), and times shared by equal poses (a repeated line)
	const auto ref = path(200);
	io::Trajectory thinned;
	for (size_t k = 0; k < ref.size(); k += 2) thinned.emplace_back(ref[k].first + 0.01, ref[k].second);
	auto repeated = ref;
	repeated.insert(repeated.begin() + 50, ref[50]);
	for (const auto& est : {thinned, repeated})
	{
		const auto m = eval::matchPoses(est, ref, 0.05);
		EXPECT_FALSE(m.byOrder);
		EXPECT_TRUE(m.why.empty());
		const auto t = eval::matchByTimestamp(est, ref, 0.05);
		ASSERT_EQ(m.pairs.size(), t.size());
		for (size_t i = 0; i < t.size(); i++) EXPECT_TRUE(m.pairs[i] == t[i]) << i;
	}
}

TEST(TrajectoryEval, GvEvalScoresCsailsRawLogByOrder)
{
	// csail-corrected: 365 of 406 scans at t = 1.13486e+09; its own poses against themselves score 0
	const std::string csail = std::string(GV_SHARED_DIR) + "/data/csail-corrected.log.gz";
	const std::string bin = std::string(GV_BIN_DIR) + "/gv-eval";
	if (!fs::exists(bin) || !fs::exists(csail)) GTEST_SKIP() << "gv-eval or csail-corrected not available";
	const std::string out = run("'" + bin + "' traj '" + csail + "' '" + csail + "' --log-pose 2>&1");
	EXPECT_NE(out.find("365 estimate poses share t = 1134860000.000000 and differ: matched by order"),
			  std::string::npos)
		<< out;
	const auto m = parseKeyValues(out.substr(out.find("n=")));
	EXPECT_EQ(m.at("n"), 406);
	EXPECT_EQ(m.at("ate_rmse_m"), 0);
	EXPECT_EQ(m.at("rel_loop_t_m"), 0);
}

// Localisation on a map (gv-eval traj --absolute): nothing is aligned, so a constant offset that the
// ATE would remove is an error; convergence is the first pose from which every error stays below the bound.
TEST(TrajectoryEval, LocalizationErrorsAreUnalignedWithConvergenceTime)
{
	const io::Trajectory ref = path(100);
	io::Trajectory est = ref;
	for (size_t k = 0; k < est.size(); ++k)
	{
		// 1.0 m off for the first 10 poses, 0.3 m at pose 20 (a relapse), then 0.05 m in x throughout
		const double off = k < 10 ? 1.0 : k == 20 ? 0.3 : 0.05;
		est[k].second.x += off;
	}
	est.back().second.phi += 2 * M_PI / 180;
	const eval::PoseMatch match = eval::matchPoses(est, ref, 0.05);
	ASSERT_EQ(match.times.size(), 100u);
	const auto m = eval::evaluateLocalization(match.pairs, match.times, 0.2);
	EXPECT_EQ(m.matched, 100u);
	EXPECT_NEAR(m.rmse, std::sqrt((10 * 1.0 + 0.09 + 89 * 0.0025) / 100), 1e-9);
	EXPECT_NEAR(m.finalT, 0.05, 1e-9);
	EXPECT_NEAR(m.finalRDeg, 2.0, 1e-9);
	EXPECT_TRUE(m.converged);
	EXPECT_NEAR(m.firstBelow, 10 * 0.2, 1e-9);
	EXPECT_NEAR(m.convergedAfter, 21 * 0.2, 1e-9);  // pose 21, not pose 10: pose 20 is off by 0.3 m
	EXPECT_NEAR(m.rmseAfter, 0.05, 1e-9);
	EXPECT_NEAR(m.maxAfter, 0.05, 1e-9);
	// The ATE aligns the constant offset away; the localisation error keeps it.
	EXPECT_LT(eval::evaluatePairs(match.pairs).ateRmse, m.rmse);

	est.back().second.x += 1.0;  // diverged at the end
	const eval::PoseMatch lost = eval::matchPoses(est, ref, 0.05);
	const auto d = eval::evaluateLocalization(lost.pairs, lost.times, 0.2);
	EXPECT_FALSE(d.converged);
	EXPECT_TRUE(std::isnan(d.convergedAfter));
	EXPECT_NE(eval::formatText(d).find("converged=no"), std::string::npos);
	EXPECT_NEAR(eval::toJson(m)["converged_after_s"].get<double>(), 4.2, 1e-9) << eval::toJson(m);
	EXPECT_NE(io::jsonText(eval::toJson(d)).find("\"converged_after_s\": null"), std::string::npos) << "NaN: null";
}
