// gv-em-slam: EM-SLAM with grid vectors (Sec. 4 of Wang, Xiong, Chu) on a CARMEN
// log or an MRPT rawlog: static/dynamic vectors (E-step) and the robot path
// (M-step, pose graph) estimated alternately from raw odometry and scans.
//
//   gv-em-slam --input LOG --out DIR [--config FILE.ini] [--max-iterations N] [--online [--refine]] [--quiet]
//
// --online replays the log scan by scan through OnlineEmSlam (Sec. 6's sequential mode) and writes the same
// files from its final map and trajectory, plus trajectory_online.txt (each scan's pose when it came in) and
// vectors_live.txt (the live map a robot reads: OnlineEmSlam::vectors() after the last scan, before finish());
// --refine then runs the batch EM from the online trajectory (--init: from a given one); the odometry edges stay the
// log's odometry either way.
// Writes to DIR: trajectory.txt (t x y theta per scan, the input's timestamps),
// map.gvmap (serialized mrpt::maps::CGridVectorMap), vectors.txt
// (x1 y1 x2 y2 p_static static|dynamic), vectors.svg, occupancy.png/.pgm/.yaml,
// doors.txt, door_states.txt (every state, wall and leaves of each door) and report.json (per-iteration figures, memory
// as Table 1, timings, the self-check). Exit status 3: the self-check finds the run suspect (doc/io.md).
#include "EmOutputs.h"
#include "InitialTrajectory.h"
#include "OnlineReplay.h"

#include "doors/DoorDetector.h"
#include "em/EmSlam.h"
#include "map/MapExport.h"
#include "map/MemoryAccounting.h"
#include "map/OccupancyConversion.h"
#include "extraction/VectorExtractor.h"
#include "common/ArgParser.h"
#include "io/Counted.h"
#include "io/Progress.h"
#include "io/AtomicFile.h"
#include <gridvector/io/LogReader.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

using namespace gridvector;
using Clock = std::chrono::steady_clock;

/** Exit status of a run whose self-check says suspect (doc/io.md): 1 and 2 are bad input and bad usage. */
constexpr int kSuspectStatus = 3;

namespace
{
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

void printIteration(const EmIteration& it)
{
	const auto& m = it.mstep;
	std::fprintf(stderr,
				 "iteration %d: %5.1f%% constraints changed; %zu edges (%zu sequential, %zu overlap, %zu loop), "
				 "%zu registrations, %zu rejected; %zu static / %zu dynamic vectors (%zu changed); "
				 "%zu doors (%zu vectors kept out, %zu cut); M %.2f s, E %.2f s\n",
				 it.index, 100 * it.changedShare, m.active, m.sequential, m.overlap, m.loop, m.registrations,
				 m.optimisation.rejected + m.unverified, it.staticVectors, it.dynamicVectors, it.changedVectors,
				 it.doors.doors, it.doors.excluded, it.doors.cut, it.mSeconds, it.eSeconds);
}

// Debugging aid: GV_EM_DEBUG_DIR=dir writes dir/traj_<iteration>.txt after each iteration, and traj_0.txt, the
// start (the raw odometry, or --init's trajectory), before the first: what the run is to improve on.
void dumpIteration(const io::LogData& log, const EmIteration& it, const std::vector<mrpt::math::TPose2D>& poses)
{
	const char* dir = std::getenv("GV_EM_DEBUG_DIR");
	if (!dir) return;
	io::Trajectory tr;
	for (size_t t = 0; t < poses.size(); ++t) tr.emplace_back(log.scans[t].timestamp, poses[t]);
	io::writeTrajectory(std::string(dir) + "/traj_" + std::to_string(it.index) + ".txt", tr);
}

// Debugging aid: GV_EM_DEBUG_DIR=dir also writes dir/edges_<iteration>.txt after each M-step, its
// registration edges (writeEdgeDump; --online writes online_edges_before_finish.txt and
// online_edges_final.txt, OnlineReplay.cpp); and dir/static_<iteration>.txt, per keyframe the
// static vectors that M-step registered: scan count length.
void dumpEdges(int iteration, const MStep& m, const std::vector<std::vector<MatchSegment>>& statics,
			   const std::vector<size_t>& key)
{
	const char* dir = std::getenv("GV_EM_DEBUG_DIR");
	if (!dir) return;
	if (!app::writeEdgeDump(std::string(dir) + "/edges_" + std::to_string(iteration) + ".txt", m.constraints(), key,
					   [&](const Constraint& c) { return m.graphInformation(c); }))
		return;
	std::FILE* f = std::fopen((std::string(dir) + "/static_" + std::to_string(iteration) + ".txt").c_str(), "w");
	if (!f) return;
	for (size_t k = 0; k < statics.size() && k < key.size(); ++k)
	{
		double len = 0;
		for (const auto& s : statics[k]) len += s.length;
		std::fprintf(f, "%zu %zu %.3f\n", key[k], statics[k].size(), len);
	}
	std::fclose(f);
}

// The self-check's map consistency: the keyframes' beams (the scans EM placed) at their final poses against the
// final static map.
BeamConsistency mapConsistency(const io::LogData& log, const std::vector<LocalScan>& scans,
							   const std::vector<mrpt::math::TPose2D>& odometry, const EmResult& res,
							   const VectorExtractor& ex, const GridVectorConfig& cfg)
{
	std::vector<GridVector> statics;
	for (const auto& v : res.finalVectors)
		if (v.state == VectorState::Static) statics.push_back(v);
	std::vector<ScanBeams> beams;
	for (size_t t : EmSlam::keyframes(odometry, cfg.mstep))
	{
		ScanBeams b;
		b.pose = res.poses[t];
		b.origin = scans[t].sensorOrigin;
		ex.scanToPoints(*log.scans[t].scan, b.ends, 1);
		beams.push_back(std::move(b));
	}
	return beamConsistency(statics, beams);
}

// The self-check's one or two lines: the evidence, then the verdict with its reasons.
void printSelfCheck(const SelfCheckEvidence& e, const SelfCheckVerdict& v)
{
	std::fprintf(stderr,
				 "self-check: EM %s (%s); %.1f%% of %zu registrations failed; %.1f%% of %zu edges rejected; "
				 "normalised chi2 %.2f; %.1f%% of %zu keyframes without a sequential edge; map %.1f%% dynamic; "
				 "%.2f%% of beams through occupied static cells\n",
				 e.converged ? "converged" : "did not converge", io::counted(e.iterations, "iteration").c_str(),
				 100 * e.failedShare(), e.registrations, 100 * e.rejectedShare(), e.edges, e.graph.normalisedChi2(),
				 100 * e.unlinkedShare(), e.keyframes, 100 * e.dynamicShare(), 100 * e.beams.share());
	std::fprintf(stderr, "%s\n", verdictLine(v).c_str());
}

int run(const io::ArgParser& args)
{
	const auto t0 = Clock::now();
	const bool quiet = args.has("quiet");
	GridVectorConfig cfg;
	if (args.has("config")) cfg.loadFromFile(args.get("config"));
	if (args.has("max-iterations")) cfg.mstep.maxIterations = int(args.getInt("max-iterations", 10, 1, 1000));
	const std::string input = args.get("input"), dir = args.get("out") + "/";
	io::OutputDirectory outDir(args.get("out"),
							   "report.json");  // checked now, created when there is something to write

	app::RunFigures fig;
	fig.input = input;
	fig.init = args.get("init");
	fig.configJson = cfg.toJson();
	io::ReadOptions ro;
	ro.quiet = quiet;
	const io::LogData log = io::readLog(input, ro);
	io::requireScans(log);
	fig.scans = log.scans.size();
	fig.readSeconds = since(t0);
	if (!quiet) std::fprintf(stderr, "%s\n", log.summary.c_str());

	// Sec. 3.1: the local maps V_t, and the dead reckoning u_t
	io::Progress progress(quiet);
	auto t1 = Clock::now();
	const VectorExtractor ex(cfg.extraction, cfg.grid);
	const bool online = args.has("online");
	std::vector<LocalScan> scans;
	std::vector<mrpt::math::TPose2D> odo;
	for (const auto& r : log.scans)
		odo.push_back(r.hasOdometry ? r.odometry : r.hasLogPose ? r.logPose : mrpt::math::TPose2D(0, 0, 0));
	if (!online)  // --online: extracted scan by scan in the replay, timed with it
	{
		// EM maps the keyframes (EmSlam::run): the other scans keep their sensor origin, not their vectors
		std::vector<bool> keyframe(log.scans.size(), false);
		for (size_t t : EmSlam::keyframes(odo, cfg.mstep)) keyframe[t] = true;
		scans.reserve(log.scans.size());
		for (size_t t = 0; t < log.scans.size(); ++t)
		{
			const auto& r = log.scans[t];
			progress.show("extracting vectors", t + 1, log.scans.size());
			scans.push_back(ex.extract(*r.scan));
			scans.back().scanIndex = int64_t(t);
			scans.back().timestamp = r.timestamp;
			fig.localVectors += scans.back().vectors.size();
			if (!keyframe[t]) std::vector<GridVector>().swap(scans.back().vectors);
		}
	}
	progress.done();
	fig.extractSeconds = since(t1);
	// --init: where EM starts; the odometry edges stay the log's odometry
	const std::vector<mrpt::math::TPose2D> init =
		args.has("init") ? app::initialTrajectory(log, odo, args.get("init")) : odo;

	// Sec. 6's sequential mode: the log scan by scan (--online), then (--refine) the batch EM from its trajectory
	EmIteration start;  // index 0
	dumpIteration(log, start, init);
	t1 = Clock::now();
	app::OnlineReplay replay;
	if (online)
	{
		replay = app::replayOnline(log, init, ex, cfg, progress, args.has("refine"));
		scans = std::move(replay.scans);
		if (!quiet)
		{
			const std::string j = app::onlineJson(replay, false);
			std::fprintf(stderr, "online: %s\n", j.c_str());
		}
	}
	if (online) fig.localVectors = replay.localVectors;
	const bool batch = !online || args.has("refine");
	EmResult res = online ? std::move(replay.result) : EmResult{};
	if (batch)
	{
		// Sec. 4: EM, from the raw odometry or (--refine) the online trajectory
		EmSlam em(cfg);
		if (std::getenv("GV_EM_DEBUG_DIR")) em.setMStepObserver(dumpEdges);
		// the keyframes' vectors move into the run; every scan keeps its sensor origin (the self-check's)
		res = em.run(
			std::move(scans), odo, online ? res.poses : init,
			[&](const EmIteration& it, const std::vector<mrpt::math::TPose2D>& poses) {
				progress.done();
				if (!quiet) printIteration(it);
				dumpIteration(log, it, poses);
			},
			[&](const char* stage, int iteration, double f) {
				progress.show("iteration " + std::to_string(iteration) + " of at most " +
								  std::to_string(cfg.mstep.maxIterations) + ": " + stage,
							  f);
			});
		progress.done();
	}
	fig.emSeconds = since(t1);
	if (online) fig.onlineJson = app::onlineJson(replay, batch);
	std::vector<MStepReport> msteps;
	for (const auto& it : res.iterations) msteps.push_back(it.mstep);
	if (res.iterations.empty()) msteps.push_back(replay.report);  // online alone: its registrations
	fig.selfCheck = selfCheckEvidence(res.converged, msteps, res.keyframes, res.finalGraph,
									  mapConsistency(log, scans, odo, res, ex, cfg), res.finalVectors);
	fig.verdict = judge(fig.selfCheck);

	// outputs: everything that can fail on the results (the occupancy grid's size) before the first file
	t1 = Clock::now();
	const auto grid = OccupancyConversion::toOccupancyGrid(res.finalVectors, cfg.occupancy, cfg.grid);
	outDir.create();
	io::Trajectory traj;
	for (size_t t = 0; t < res.poses.size(); ++t) traj.emplace_back(log.scans[t].timestamp, res.poses[t]);
	io::writeTrajectory(dir + "trajectory.txt", traj);
	if (online)
	{
		io::Trajectory causal;
		for (size_t t = 0; t < replay.causal.size(); ++t) causal.emplace_back(log.scans[t].timestamp, replay.causal[t]);
		io::writeTrajectory(dir + "trajectory_online.txt", causal);
		app::writeVectors(dir + "vectors_live.txt", replay.live);
	}
	const auto& doors = res.doors;
	fig.doors = doors.size();
	app::writeVectors(dir + "vectors.txt", res.finalVectors);
	app::writeSvg(dir + "vectors.svg", res.finalVectors, doors, res.poses);
	app::writeDoors(dir + "doors.txt", doors);
	app::writeDoorStates(dir + "door_states.txt", doors);
	app::writeGvmap(dir + "map.gvmap", cfg, res.finalVectors);
	MapExport::writePng(grid, dir + "occupancy.png");
	MapExport::writeRosMap(grid, dir + "occupancy.pgm", dir + "occupancy.yaml");
	MapExport::write3DScene(res.finalVectors, grid, dir + "map.3Dscene");
	fig.memory = MemoryAccounting::account(res.finalVectors, 0.1);
	MemoryAccounting::setFileBytes(fig.memory, size_t(std::filesystem::file_size(dir + "map.gvmap")));
	fig.outputSeconds = since(t1);
	fig.totalSeconds = since(t0);
	app::writeReport(outDir.markerPath(), fig, res);  // last: a directory with report.json is complete
	if (!quiet)
	{
		size_t nd = 0;
		for (const auto& v : res.finalVectors) nd += v.state == VectorState::Dynamic;
		std::fprintf(stderr,
					 "%s after %s: %zu static + %zu dynamic vectors, %s; %.2f s "
					 "(read %.2f, extract %.2f, EM %.2f, final map %.2f, outputs %.2f)\n",
					 res.converged ? "converged" : "stopped", io::counted(res.iterations.size(), "iteration").c_str(),
					 res.finalVectors.size() - nd, nd, io::counted(doors.size(), "door").c_str(), fig.totalSeconds,
					 fig.readSeconds, fig.extractSeconds, fig.emSeconds, res.finalMapSeconds, fig.outputSeconds);
		std::fprintf(stderr, "%s", MemoryAccounting::summary(fig.memory).c_str());
		std::fprintf(stderr,
					 "wrote %s{trajectory.txt, map.gvmap, vectors.txt, vectors.svg, occupancy.png, occupancy.pgm, "
					 "occupancy.yaml, map.3Dscene, doors.txt, door_states.txt, report.json%s}\n",
					 dir.c_str(), online ? ", trajectory_online.txt, vectors_live.txt" : "");
	}
	if (!quiet || !fig.verdict.ok) printSelfCheck(fig.selfCheck, fig.verdict);  // --quiet: only a suspect run
	return fig.verdict.ok ? 0 : kSuspectStatus;
}
}  // namespace

int main(int argc, char** argv)
{
	io::ArgParser args("gv-em-slam",
					   "--input LOG --out DIR [--config FILE.ini] [--init TRAJ] [--max-iterations N] [--online [--refine]] "
					   "[--quiet]");
	args.option("input", "LOG", "CARMEN log (.log/.clf[.gz]) or MRPT rawlog", io::ArgParser::kRequired);
	args.option("out", "DIR", "output directory (created if missing)", io::ArgParser::kRequired);
	args.option("config", "FILE.ini", "gridvector parameters ([gridvector_*] sections)",
				"the library's defaults (gv-config --ini)");
	args.option("init", "TRAJ",
				"start from this 't x y theta' trajectory (e.g. gv-graphslam's) instead of raw odometry (the odometry "
				"edges stay the log's)",
				"none: raw odometry");
	args.option("max-iterations", "N", "EM iterations at most (overrides [gridvector_mstep] max_iterations)",
				std::to_string(GridVectorConfig().mstep.maxIterations));
	args.flag("online",
			  "replay the log scan by scan through the online EM-SLAM (OnlineEmSlam); also writes "
			  "trajectory_online.txt (each scan's pose when it came in) and the per-scan latency in report.json");
	args.flag("refine",
			  "with --online: run the batch EM afterwards, from the online trajectory (for loops long against the "
			  "odometry's drift)");
	args.flag("quiet", "no progress or summary output");
	return io::runTool(args, argc, argv, [&] {
		if (!args.has("input") || !args.has("out")) args.fail("--input and --out are required");
		if (args.has("refine") && !args.has("online")) args.fail("--refine needs --online");
		args.requirePositional(0, 0);
		return run(args);  // a bad option value found there (--max-iterations 0) is bad usage: status 2
	});
}
