// gv-bench-icp: MRPT's ICP (CICP, icpClassic) aligning a log's scans against a CGridVectorMap,
// next to MRPT's own COccupancyGridMap2D built from the same scans at the same poses: the time
// of one determineMatching2D call per scan and the error of the aligned pose from a guess
// --offset m / --offset-deg off (random direction, seeded); the time of one
// computeObservationLikelihood call (the scan at its reference pose and at the guess).
//
//   gv-bench-icp LOG TRAJ [--map MAP.gvmap] [--every N] [--offset M] [--offset-deg D] [--seed S]
//                [--grid-resolution R] [--config FILE.ini] [--repeat R]
//
// TRAJ: `t x y theta` per scan of LOG in the map's frame (gv-em-slam's trajectory.txt with its
// map.gvmap; gv-sim's truth_trajectory.txt). The scans tested are N/2, N/2 + N, ... Without
// --map the grid-vector map is built here by inserting every other scan at its TRAJ pose
// (sequential mode, no E-step; parameters: defaults, or --config), so the tested scans are held
// out of both maps; with --map every scan goes into the occupancy grid, and --config sets the
// map's [gridvector_matching] group only.
#include <mrpt/math/TPose2D.h>
#include "common/ArgParser.h"
#include "io/Counted.h"
#include <gridvector/io/LogReader.h>
#include "io/ObjectFile.h"
#include "io/Progress.h"
#include "io/TextParsing.h"
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/poses/CPosePDF.h>
#include <mrpt/slam/CICP.h>

#include <algorithm>
#include <ctime>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using mrpt::math::TPose2D;

namespace
{
/** The options' defaults (--help prints them). */
struct Defaults
{
	static constexpr long every = 10;
	static constexpr double offset = 0.3, offsetDeg = 5.0, gridResolution = 0.05;
	static constexpr long seed = 1, repeat = 1;
};
struct Errors
{
	std::vector<double> trans, rot;  //!< [m], [deg]
	double matchSeconds = 0, icpSeconds = 0, likelihoodSeconds = 0;
	size_t matchCalls = 0, points = 0, pairs = 0, likelihoodCalls = 0;
};

double percentile(std::vector<double> v, double q)
{
	if (v.empty()) return 0;
	std::sort(v.begin(), v.end());
	return v[std::min(v.size() - 1, size_t(q * double(v.size() - 1) + 0.5))];
}

void report(const char* name, const Errors& e)
{
	size_t good = 0;
	for (size_t k = 0; k < e.trans.size(); ++k) good += e.trans[k] < 0.05 && e.rot[k] < 1.0;
	std::printf(
		"%s: determineMatching2D %.1f us CPU per call (%zu calls, %.0f points and %.0f pairs per call); "
		"ICP %.2f ms CPU per alignment\n",
		name, 1e6 * e.matchSeconds / double(e.matchCalls), e.matchCalls, double(e.points) / double(e.matchCalls),
		double(e.pairs) / double(e.matchCalls), 1e3 * e.icpSeconds / double(e.trans.size()));
	std::printf("%s: computeObservationLikelihood %.1f us CPU per call (%zu calls)\n", name,
				1e6 * e.likelihoodSeconds / double(e.likelihoodCalls), e.likelihoodCalls);
	std::printf(
		"%s: error translation median %.4f p90 %.4f max %.4f m; rotation median %.3f p90 %.3f max %.3f deg; "
		"within 5 cm and 1 deg: %zu of %zu\n",
		name, percentile(e.trans, 0.5), percentile(e.trans, 0.9), percentile(e.trans, 1.0), percentile(e.rot, 0.5),
		percentile(e.rot, 0.9), percentile(e.rot, 1.0), good, e.trans.size());
}

/** Process CPU time [s]: other jobs on the core do not count. */
double cpuSeconds() { return double(std::clock()) / CLOCKS_PER_SEC; }

/** The scan's likelihood at the reference pose and at the guess, each `repeat` times, timed. */
void likelihoodOne(const mrpt::maps::CMetricMap& map, const mrpt::obs::CObservation& scan, const TPose2D& ref,
				   const TPose2D& guess, long repeat, Errors& e)
{
	const double t0 = cpuSeconds();
	double sum = 0;
	for (long r = 0; r < repeat; ++r)
		for (const TPose2D& x : {ref, guess})
			sum += map.computeObservationLikelihood(scan, mrpt::poses::CPose3D(mrpt::poses::CPose2D(x)));
	e.likelihoodSeconds += cpuSeconds() - t0;
	e.likelihoodCalls += size_t(2 * repeat);
	if (!std::isfinite(sum)) throw std::runtime_error("computeObservationLikelihood gave " + std::to_string(sum));
}

/** One scan against one map: a timed determineMatching2D at the reference pose (all points,
 * CICP's first gate; `repeat` times), then CICP from the guess. */
void alignOne(const mrpt::maps::CMetricMap& map, const mrpt::maps::CSimplePointsMap& pts, const TPose2D& ref,
			  const TPose2D& guess, long repeat, Errors& e)
{
	mrpt::slam::CICP icp;  // MRPT's defaults: thresholdDist 0.75, thresholdAng 0.15 deg, ALFA 0.5, decimation 5
	icp.options.ICP_algorithm = mrpt::slam::icpClassic;
	mrpt::maps::TMatchingParams mp;
	mp.maxDistForCorrespondence = icp.options.thresholdDist;
	mp.maxAngularDistForCorrespondence = icp.options.thresholdAng;
	mp.angularDistPivotPoint = {ref.x, ref.y, 0};
	mrpt::tfest::TMatchingPairList pairs;
	mrpt::maps::TMatchingExtraResults extra;
	const double t0 = cpuSeconds();
	for (long r = 0; r < repeat; ++r) map.determineMatching2D(&pts, mrpt::poses::CPose2D(ref), pairs, mp, extra);
	const double t1 = cpuSeconds();
	mrpt::slam::CICP::TReturnInfo info;
	const TPose2D est = icp.Align(&map, &pts, mrpt::poses::CPose2D(guess), info)->getMeanVal().asTPose();
	const double t2 = cpuSeconds();
	e.matchSeconds += t1 - t0;
	e.icpSeconds += t2 - t1;
	e.matchCalls += size_t(repeat), e.points += size_t(repeat) * pts.size(), e.pairs += size_t(repeat) * pairs.size();
	e.trans.push_back(std::hypot(est.x - ref.x, est.y - ref.y));
	e.rot.push_back(std::abs(std::remainder(est.phi - ref.phi, 2 * M_PI)) * 180 / M_PI);
}

int run(const gridvector::io::ArgParser& args)
{
	args.requirePositional(2, 2);
	const std::string logPath = args.positional()[0], trajPath = args.positional()[1];
	const long every = args.getInt("every", Defaults::every, 2, 1000000);
	const double offset = args.getDouble("offset", Defaults::offset),
				 offsetDeg = args.getDouble("offset-deg", Defaults::offsetDeg);
	const double gridRes = args.getDouble("grid-resolution", Defaults::gridResolution);
	const long repeat = args.getInt("repeat", Defaults::repeat, 1, 1000000);
	const bool quiet = args.has("quiet");
	if (!(offset >= 0) || !(offsetDeg >= 0) || !(gridRes > 0))
		args.fail("--offset, --offset-deg must be >= 0, --grid-resolution > 0");
	gridvector::io::ReadOptions ro;
	ro.quiet = quiet;
	const gridvector::io::LogData data = gridvector::io::readLog(logPath, ro);
	gridvector::io::requireScans(data);
	const gridvector::io::Trajectory traj = gridvector::io::readTrajectory(trajPath);
	if (traj.size() != data.scans.size())
		throw std::runtime_error(trajPath + ": " + gridvector::io::counted(traj.size(), "pose") + " for " +
								 gridvector::io::counted(data.scans.size(), "scan") + " of " + logPath);
	mrpt::maps::CGridVectorMap gv;
	if (args.has("map"))
	{
		gridvector::io::readObjectFile(args.get("map"), gv);
		if (args.has("config"))  // the stored map keeps its own parameters but the matching group
		{
			gridvector::GridVectorConfig file, cfg = gv.config();
			file.loadFromFile(args.get("config"));
			cfg.matching = file.matching;
			gv.setConfig(cfg);
		}
	}
	else if (args.has("config"))
	{
		gridvector::GridVectorConfig cfg;
		cfg.loadFromFile(args.get("config"));
		gv.setConfig(cfg);
	}
	mrpt::maps::COccupancyGridMap2D grid(-10, 10, -10, 10, float(gridRes));
	const size_t first = size_t(every / 2);
	auto tested = [&](size_t i) { return i >= first && (i - first) % size_t(every) == 0; };
	for (size_t i = 0; i < data.scans.size(); ++i)
	{
		const mrpt::poses::CPose3D pose(mrpt::poses::CPose2D(traj[i].second));
		const bool mapIt = args.has("map") || (i % 2 == 0 && !tested(i));
		if (mapIt) grid.insertObservation(*data.scans[i].scan, pose);
		if (mapIt && !args.has("map")) gv.insertObservation(*data.scans[i].scan, pose);
	}
	std::printf("log: %s, %zu scans; map: %s; every %ld-th scan tested from a guess %.3f m / %.2f deg off\n",
				logPath.c_str(), data.scans.size(), gv.asString().c_str(), every, offset, offsetDeg);
	std::mt19937 rng(uint32_t(args.getInt("seed", Defaults::seed, 0, 4294967295L)));
	std::uniform_real_distribution<double> dir(-M_PI, M_PI);
	Errors eGv, eGrid;
	gridvector::io::Progress progress(quiet);  // between the timed calls
	for (size_t i = first; i < data.scans.size(); i += size_t(every))
	{
		progress.show("aligning scans", i, data.scans.size());
		mrpt::maps::CSimplePointsMap pts;
		pts.insertionOptions.minDistBetweenLaserPoints = 0;
		pts.loadFromRangeScan(*data.scans[i].scan);
		if (pts.size() == 0) continue;
		const double a = dir(rng), sign = rng() % 2 ? 1.0 : -1.0;
		const TPose2D ref = traj[i].second;
		const TPose2D guess = ref + TPose2D(offset * std::cos(a), offset * std::sin(a), sign * offsetDeg * M_PI / 180);
		alignOne(gv, pts, ref, guess, repeat, eGv);
		alignOne(grid, pts, ref, guess, repeat, eGrid);
		likelihoodOne(gv, *data.scans[i].scan, ref, guess, repeat, eGv);
		likelihoodOne(grid, *data.scans[i].scan, ref, guess, repeat, eGrid);
	}
	progress.done();
	if (eGv.trans.empty()) throw std::runtime_error(logPath + ": no tested scan has a valid reading");
	report("CGridVectorMap", eGv);
	report("COccupancyGridMap2D", eGrid);
	return 0;
}
}  // namespace

int main(int argc, char** argv)
{
	gridvector::io::ArgParser args("gv-bench-icp",
								   "LOG TRAJ [--map MAP.gvmap] [--every N] [--offset M] [--offset-deg D] [--seed S] "
								   "[--grid-resolution R] [--config FILE.ini] [--repeat R]");
	using gridvector::io::shortestText;
	args.option("map", "MAP.gvmap", "the grid-vector map", "built from every other scan at its TRAJ pose");
	args.option("every", "N", "test scans N/2, N/2 + N, ...", std::to_string(Defaults::every));
	args.option("offset", "M", "guess this far from the TRAJ pose, in a random direction [m]",
				shortestText(Defaults::offset));
	args.option("offset-deg", "D", "... and turned by +-D [deg]", shortestText(Defaults::offsetDeg));
	args.option("seed", "S", "seed of the guesses' directions", std::to_string(Defaults::seed));
	args.option("grid-resolution", "R", "MRPT occupancy grid's cell size [m]", shortestText(Defaults::gridResolution));
	args.option("config", "FILE.ini",
				"gridvector parameters for the map built here; with --map its [gridvector_matching] only",
				"the library's defaults (gv-config --ini)");
	args.option("repeat", "R", "time each determineMatching2D / likelihood call R times (steadier figures)",
				std::to_string(Defaults::repeat));
	args.flag("quiet", "no progress (the figures on stdout are the output)");
	return gridvector::io::runTool(args, argc, argv, [&] { return run(args); });
}
