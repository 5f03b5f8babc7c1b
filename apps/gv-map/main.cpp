// gv-map: build the global grid vector map (Sec. 3.2) of a laser log with given poses.
//
//   gv-map --input LOG --poses {log|FILE} --out DIR [--config FILE.ini] [--simplemap] [--quiet]
//
// LOG: CARMEN (.log/.clf, optionally .gz) or MRPT rawlog. --poses log uses the
// poses stored with each scan (CARMEN FLASER: the corrected pose), falling back
// to odometry; FILE is a "t x y theta" trajectory matched to scans by time.
// Writes to DIR: map.gvmap (serialized mrpt::maps::CGridVectorMap), vectors.txt,
// vectors.svg, occupancy.png, occupancy.pgm + occupancy.yaml (ROS map_server),
// map.3Dscene (MRPT viewers) and memory.json (Table 1); with --simplemap also
// map.simplemap (the scans at their poses: MRPT's pf-localization builds its maps from it).
#include "map/MapExport.h"
#include "map/MemoryAccounting.h"
#include "map/OccupancyConversion.h"
#include "common/ArgParser.h"
#include "io/Counted.h"
#include "io/AtomicFile.h"
#include "io/Progress.h"
#include <gridvector/io/LogReader.h>
#include "io/RawlogWriter.h"

#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>

using namespace gridvector;
using Clock = std::chrono::steady_clock;

namespace
{
/** The pose of each scan: the log's, or the trajectory's (io::posesAtScans: by position or by time within 50 ms). */
std::vector<std::optional<mrpt::math::TPose2D>> posesFor(const io::LogData& log, const std::string& source)
{
	std::vector<std::optional<mrpt::math::TPose2D>> out(log.scans.size());
	if (source == "log")
	{
		for (size_t i = 0; i < log.scans.size(); ++i)
		{
			const auto& r = log.scans[i];
			if (r.hasLogPose)
				out[i] = r.logPose;
			else if (r.hasOdometry)
				out[i] = r.odometry;
		}
		return out;
	}
	const io::Trajectory traj = io::readTrajectory(source);
	if (traj.empty()) throw std::runtime_error(source + ": no poses");
	return io::posesAtScans(log, traj, source);
}

int run(const io::ArgParser& args)
{
	const std::string input = args.get("input"), poseSource = args.get("poses"), out = args.get("out");
	const bool quiet = args.has("quiet");
	GridVectorConfig cfg;
	if (args.has("config")) cfg.loadFromFile(args.get("config"));
	io::OutputDirectory outDir(out, "memory.json");  // checked now, created when the map is ready

	io::ReadOptions ro;
	ro.quiet = quiet;
	const io::LogData log = io::readLog(input, ro);
	io::requireScans(log);
	const auto poses = posesFor(log, poseSource);

	mrpt::maps::CGridVectorMap map(cfg);
	io::Progress progress(quiet);
	size_t used = 0;
	const auto t0 = Clock::now();
	for (size_t i = 0; i < log.scans.size(); ++i)
	{
		progress.show("gv-map: scans", i, log.scans.size());
		if (!poses[i]) continue;
		const auto& p = *poses[i];
		map.insertObservation(*log.scans[i].scan, mrpt::poses::CPose3D(p.x, p.y, 0, p.phi, 0, 0));
		++used;
	}
	progress.show("gv-map: scans", log.scans.size(), log.scans.size());
	progress.done();
	const double secs = std::chrono::duration<double>(Clock::now() - t0).count();
	if (used == 0) throw std::runtime_error((poseSource == "log" ? input : poseSource) + ": no scan has a pose");

	const auto& vectors = map.vectors();
	const auto grid = OccupancyConversion::toOccupancyGrid(vectors, cfg.occupancy, cfg.grid);
	const std::string dir = outDir.create() + "/";
	map.saveToFile(dir + "map.gvmap");
	MapExport::writeVectorsText(vectors, dir + "vectors.txt");
	MapExport::writeSvg(vectors, dir + "vectors.svg");
	MapExport::writePng(grid, dir + "occupancy.png");
	MapExport::writeRosMap(grid, dir + "occupancy.pgm", dir + "occupancy.yaml");
	MapExport::write3DScene(vectors, grid, dir + "map.3Dscene");
	const MemoryReport mem = MemoryAccounting::account(vectors, 0.1);
	const bool simplemap = args.has("simplemap");
	if (simplemap) io::writeSimplemap(dir + "map.simplemap", log, poses);
	MemoryAccounting::writeJson(mem, outDir.markerPath());  // last: a directory with memory.json is complete
	if (!quiet)
	{
		std::printf("%s: %zu of %s mapped in %.2f s (%.0f scans/s), %s\n", input.c_str(), used,
					io::counted(log.scans.size(), "scan").c_str(), secs, used / std::max(secs, 1e-9),
					io::counted(vectors.size(), "grid vector").c_str());
		std::printf("%s", MemoryAccounting::summary(mem).c_str());
		std::printf(
			"wrote %s{map.gvmap, vectors.txt, vectors.svg, occupancy.png, occupancy.pgm, occupancy.yaml, map.3Dscene, "
			"memory.json%s}\n",
			dir.c_str(), simplemap ? ", map.simplemap" : "");
	}
	return 0;
}
}  // namespace

int main(int argc, char** argv)
{
	io::ArgParser args("gv-map",
					   "--input LOG --poses {log|FILE} --out DIR [--config FILE.ini] [--simplemap] [--quiet]");
	args.option("input", "LOG", "CARMEN log (.log/.clf, optionally .gz) or MRPT rawlog", io::ArgParser::kRequired);
	args.option("poses", "log|FILE", "poses stored in the log, or a 't x y theta' trajectory file",
				io::ArgParser::kRequired);
	args.option("out", "DIR", "output directory (created if missing)", io::ArgParser::kRequired);
	args.option("config", "FILE.ini", "gridvector parameters ([gridvector_*] sections)",
				"the library's defaults (gv-config --ini)");
	args.flag("simplemap", "also write map.simplemap: the mapped scans at their poses (for MRPT's pf-localization)");
	args.flag("quiet", "no progress and no summary");
	return io::runTool(args, argc, argv, [&] {
		args.requirePositional(0, 0);
		for (const char* req : {"input", "poses", "out"})
			if (!args.has(req)) args.fail(std::string("missing --") + req);
		return run(args);
	});
}
