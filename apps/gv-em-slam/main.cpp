// gv-em-slam: EM-SLAM with grid vectors (Sec. 4) on a CARMEN log or MRPT rawlog.
//
//   gv-em-slam --input LOG [--config FILE.ini] --out DIR [--max-iterations N] [--quiet]
#include <gridvector/EmSlam.h>
#include <gridvector/ErrorText.h>
#include <gridvector/VectorExtractor.h>
#include <gridvector/io/ArgParser.h>
#include <gridvector/io/AtomicFile.h>
#include <gridvector/io/LogReader.h>

#include <chrono>
#include <cstdlib>
#include <cstdio>
#include <iostream>
#include <string>
#include <unistd.h>
#include <vector>

using namespace gridvector;
using Clock = std::chrono::steady_clock;

namespace
{
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
}  // namespace

int main(int argc, char** argv)
{
	io::ArgParser args("gv-em-slam", "--input LOG --out DIR [--config FILE.ini] [--max-iterations N] [--quiet]");
	args.option("input", "LOG", "CARMEN log (.log/.clf[.gz]) or MRPT rawlog");
	args.option("out", "DIR", "output directory (created if missing)");
	args.option("config", "FILE.ini", "parameters (default: built-in)");
	args.option("max-iterations", "N", "EM iterations at most (overrides the config)");
	args.flag("quiet", "no progress output");
	try
	{
		if (!args.parse(argc, argv))
		{
			std::cout << args.usage();
			return 0;
		}
		if (!args.has("input") || !args.has("out")) args.fail("--input and --out are required");
	}
	catch (const io::UsageError& e)
	{
		std::cerr << e.what() << "\n";
		return 2;
	}
	const bool quiet = args.has("quiet");
	const bool tty = !quiet && isatty(2);
	try
	{
		const auto t0 = Clock::now();
		GridVectorConfig cfg = EmSlam::defaultConfig();
		if (args.has("config")) cfg.loadFromFile(args.get("config"));
		if (args.has("max-iterations")) cfg.mstep.maxIterations = int(args.getInt("max-iterations", 10, 1, 1000));
		const std::string out = args.get("out");
		io::ensureWritableDirectory(out);
		io::ReadOptions ro;
		ro.quiet = quiet;
		const io::LogData log = io::readLog(args.get("input"), ro);
		if (log.scans.empty()) throw std::runtime_error(args.get("input") + ": no laser scans");
		const double readSeconds = since(t0);
		// Sec. 3.1: local maps V_t
		const auto t1 = Clock::now();
		const VectorExtractor ex(cfg.extraction, cfg.grid);
		std::vector<LocalScan> scans;
		std::vector<mrpt::math::TPose2D> odo;
		scans.reserve(log.scans.size());
		for (size_t t = 0; t < log.scans.size(); ++t)
		{
			const auto& r = log.scans[t];
			scans.push_back(ex.extract(*r.scan));
			scans.back().scanIndex = int64_t(t);
			scans.back().timestamp = r.timestamp;
			odo.push_back(r.hasOdometry ? r.odometry : r.hasLogPose ? r.logPose : mrpt::math::TPose2D(0, 0, 0));
		}
		const double extractSeconds = since(t1);
		if (!quiet) std::fprintf(stderr, "%s\n", log.summary.c_str());
		EmSlam em(cfg);
		const char* dbg = std::getenv("GV_EM_DEBUG_DIR");
		const EmResult res = em.run(scans, odo, [&](const EmIteration& it, const std::vector<mrpt::math::TPose2D>& poses) {
			if (dbg)
			{
				io::Trajectory tr;
				for (size_t t = 0; t < poses.size(); ++t) tr.emplace_back(log.scans[t].timestamp, poses[t]);
				io::writeTrajectory(std::string(dbg) + "/traj_" + std::to_string(it.index) + ".txt", tr);
			}
			if (quiet) return;
			std::fprintf(stderr,
						 "iteration %d: %.1f%% constraints changed, %zu edges (%zu seq, %zu overlap, %zu loop), "
						 "%zu registrations (%zu failed), %zu static / %zu dynamic vectors, %zu changed; "
						 "M %.2fs (opt %.2fs, %d it, %zu rejected) E %.2fs\n",
						 it.index, 100 * it.changedShare, it.mstep.active, it.mstep.sequential, it.mstep.overlap,
						 it.mstep.loop, it.mstep.registrations, it.mstep.failedRegistrations, it.staticVectors,
						 it.dynamicVectors, it.changedVectors, it.mSeconds, it.mstep.optimisation.seconds,
						 it.mstep.optimisation.iterations, it.mstep.optimisation.rejected,
						 it.eSeconds);
		});
		io::Trajectory traj;
		for (size_t t = 0; t < res.poses.size(); ++t) traj.emplace_back(log.scans[t].timestamp, res.poses[t]);
		io::writeTrajectory(out + "/trajectory.txt", traj);
		if (!quiet)
			std::fprintf(stderr, "read %.2fs, extract %.2fs, total %.2fs, %s\n", readSeconds, extractSeconds,
						 since(t0), res.converged ? "converged" : "not converged");
		(void)tty;
	}
	catch (const std::exception& e)
	{
		std::cerr << oneLineError(e) << "\n";
		return 1;
	}
	return 0;
}
