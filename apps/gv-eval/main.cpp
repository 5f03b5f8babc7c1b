// gv-eval: trajectory accuracy (as ../shared/bench/evaltraj.py) and map quality
// against gv-sim's truth.
#include "eval/FalseStatic.h"
#include "eval/MapEval.h"
#include "eval/TrajectoryEval.h"
#include "common/ArgParser.h"
#include "io/JsonFile.h"
#include "io/TextParsing.h"
#include <gridvector/io/LogReader.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <stdexcept>

using namespace gridvector;

namespace
{
/** traj --absolute: converged once every later error is below this [m]. */
constexpr double kConvergedDefault = 0.2;

bool isLog(std::string p)
{
	if (p.size() > 3 && p.compare(p.size() - 3, 3, ".gz") == 0) p.resize(p.size() - 3);
	for (const char* ext : {".log", ".clf", ".rawlog"})
	{
		const std::string e(ext);
		if (p.size() > e.size() && p.compare(p.size() - e.size(), e.size(), e) == 0) return true;
	}
	return false;
}

/** A trajectory file, or the odometry (--log-pose: the log's own poses) of a log. */
io::Trajectory loadTrajectory(const std::string& path, bool logPose)
{
	if (!isLog(path))
	{
		io::Trajectory t = io::readTrajectory(path);
		if (t.empty()) throw std::runtime_error(path + ": no poses");
		return t;
	}
	const io::Trajectory t = io::trajectoryOf(io::readLog(path), logPose);
	if (t.empty()) throw std::runtime_error(path + ": no " + (logPose ? "log poses" : "odometry") + " in this log");
	return t;
}

/** --max-dt, checked (traj and map --trajectory). */
double maxTimeDiff(const io::ArgParser& a)
{
	const double dt = a.getDouble("max-dt", eval::TrajectoryEvalOptions().maxTimeDiff);
	if (dt <= 0) a.fail("--max-dt must be > 0");
	return dt;
}

/** eval::matchPoses with the files named in its errors, and a note on stderr when it matched by order. */
eval::PoseMatch matchTrajectories(const io::Trajectory& est, const io::Trajectory& ref, double maxDt,
								  const std::string& files)
{
	eval::PoseMatch match;
	try
	{
		match = eval::matchPoses(est, ref, maxDt);  // by time as evaltraj.py; by order if times are ambiguous
	}
	catch (const std::runtime_error& e)
	{
		throw std::runtime_error(files + e.what());
	}
	if (match.byOrder)
		std::fprintf(stderr, "gv-eval: %s%s: matched by order (one pose per scan of the same log)\n", files.c_str(),
					 match.why.c_str());
	return match;
}

/** "too few matched poses (n)" from f(), naming the files and --max-dt. */
template <class F>
auto withTooFewNamed(F&& f, const std::string& files, double maxDt)
{
	try
	{
		return f();
	}
	catch (const std::runtime_error& e)
	{
		char dt[32];
		std::snprintf(dt, sizeof dt, "%g", maxDt);
		throw std::runtime_error(files + e.what() + " within --max-dt " + dt + " s");
	}
}

int trajectoryCommand(const io::ArgParser& a)
{
	a.requirePositional(3, 3);
	eval::TrajectoryEvalOptions o;
	o.maxTimeDiff = maxTimeDiff(a);
	const bool logPose = a.has("log-pose");
	const auto est = loadTrajectory(a.positional()[1], logPose);
	const auto ref = loadTrajectory(a.positional()[2], logPose);
	const std::string files = a.positional()[1] + " vs " + a.positional()[2] + ": ";
	const eval::PoseMatch match = matchTrajectories(est, ref, o.maxTimeDiff, files);
	if (a.has("absolute"))
	{
		const double threshold = a.getDouble("converged", kConvergedDefault);
		if (!(threshold > 0)) a.fail("--converged must be > 0");
		const auto m = withTooFewNamed([&] { return eval::evaluateLocalization(match.pairs, match.times, threshold); },
									   files, o.maxTimeDiff);
		std::cout << (a.has("json") ? io::jsonText(eval::toJson(m)) : eval::formatText(m) + "\n");
		return 0;
	}
	const auto m = withTooFewNamed([&] { return eval::evaluatePairs(match.pairs, o); }, files, o.maxTimeDiff);
	std::cout << (a.has("json") ? io::jsonText(eval::toJson(m)) : eval::formatText(m) + "\n");
	return 0;
}

int mapCommand(const io::ArgParser& a)
{
	a.requirePositional(3, 3);
	eval::MapEvalOptions o;
	o.wallTolerance = o.dynamicTolerance = a.getDouble("tolerance", o.wallTolerance);
	o.doorTolerance = a.getDouble("door-tolerance", o.doorTolerance);
	o.doorPassGap = a.getDouble("pass-gap", o.doorPassGap);
	o.doorMinRunBeams = int(a.getInt("door-min-beams", o.doorMinRunBeams, 1, 100000));
	if (o.wallTolerance <= 0 || o.doorTolerance <= 0) a.fail("tolerances must be > 0");
	if (!(o.doorPassGap > 0)) a.fail("--pass-gap must be > 0");
	auto vectors = eval::readVectors(a.positional()[1]);
	const auto truth = sim::readTruth(a.positional()[2]);
	std::vector<sim::DoorTruth> doors;
	if (a.has("doors")) doors = sim::readDoors(a.get("doors"));
	if (a.has("trajectory"))
	{
		// The map is in the estimate's frame: align it to the truth as the ATE does.
		const double maxDt = maxTimeDiff(a);
		const auto est = loadTrajectory(a.get("trajectory"), false);
		const std::string refFile = a.positional()[2] + "/" + sim::SimFiles::trajectory;
		const auto ref = io::readTrajectory(refFile);
		const std::string files = a.get("trajectory") + " vs " + refFile + ": ";
		const eval::PosePairs pairs = matchTrajectories(est, ref, maxDt, files).pairs;  // the same rule as traj
		const auto T = withTooFewNamed([&] { return eval::alignmentTransform(pairs); }, files, maxDt);
		vectors = eval::transformVectors(vectors, T);
		doors = eval::transformDoors(doors, T);
	}
	eval::MapMetrics m;
	eval::FalseStaticBreakdown b;
	try
	{
		m = eval::evaluateMap(vectors, truth, a.has("doors") ? &doors : nullptr, o);
		if (a.has("breakdown")) b = eval::falseStaticBreakdown(vectors, truth, o);
	}
	catch (const std::invalid_argument& e)  // sampleCount: a segment too long to sample; say which files
	{
		throw std::runtime_error(a.positional()[1] + " vs " + a.positional()[2] + ": " + e.what());
	}
	const std::string truePathFile = a.positional()[2] + "/" + sim::SimFiles::trajectory;
	if (a.has("breakdown") && std::filesystem::exists(truePathFile))  // times from its first pose, else absolute
	{
		const auto truePath = io::readTrajectory(truePathFile);
		if (!truePath.empty()) b.timeOrigin = truePath.front().first;
	}
	if (a.has("json"))
	{
		nlohmann::ordered_json j = eval::toJson(m);
		if (a.has("breakdown")) j["false_static"] = eval::toJson(b);
		std::cout << io::jsonText(j);
	}
	else
	{
		std::cout << a.positional()[1] << ": " << vectors.size() << " vectors\n" << eval::formatText(m);
		if (a.has("breakdown")) std::cout << eval::formatText(b);
	}
	return 0;
}
}  // namespace

int main(int argc, char** argv)
{
	io::ArgParser args("gv-eval",
					   "traj EST REF [options]      (EST, REF: 't x y theta' files or logs: their odometry)\n"
					   "       gv-eval map VECTORS.txt TRUTHDIR [options]  (TRUTHDIR: a gv-sim output directory)");
	args.flag("json", "print JSON instead of text");
	args.option("max-dt", "S",
				"traj, map --trajectory: match poses within this time difference (s); where times are "
				"shared by different poses, one pose per scan of the same log is matched by order",
				io::shortestText(eval::TrajectoryEvalOptions().maxTimeDiff));
	args.flag("log-pose", "traj: for logs, use the poses the log attaches to scans instead of odometry");
	args.flag("absolute",
			  "traj: localisation error in the reference's frame, nothing aligned (final error, convergence)");
	args.option("converged", "M", "traj --absolute: converged once every later error is below M (m)",
				io::shortestText(kConvergedDefault));
	args.option("trajectory", "EST",
				"map: the trajectory the map was built with; aligns the map to the truth like the ATE",
				"none: the map is in the truth's frame");
	args.option("doors", "FILE", "map: detected doors 'hinge_x hinge_y length ...' to score door recall",
				"none: no door recall");
	args.flag("breakdown",
			  "map: the static length off every true wall by its nearest dynamic truth, and each door's passes");
	const eval::MapEvalOptions mapDefaults;
	args.option("tolerance", "M", "map: distance for 'on a wall' / 'on a dynamic object' (m)",
				io::shortestText(mapDefaults.wallTolerance));
	args.option("door-tolerance", "M", "map: hinge match distance (m)", io::shortestText(mapDefaults.doorTolerance));
	args.option("door-min-beams", "N",
				"map: a truth hit run shows a door leaf's state with at least N beams (3: two points fit any line)",
				std::to_string(mapDefaults.doorMinRunBeams));
	args.option("pass-gap", "S", "map --breakdown: a door's leaf hits further apart in time are two passes (s)",
				io::shortestText(mapDefaults.doorPassGap));
	return io::runTool(args, argc, argv, [&]() -> int {
		if (args.positional().empty()) args.fail("missing command (traj or map)");
		const std::string cmd = args.positional()[0];
		if (cmd == "traj") return trajectoryCommand(args);
		if (cmd == "map") return mapCommand(args);
		args.fail("unknown command '" + cmd + "' (expected traj or map)");
	});
}
