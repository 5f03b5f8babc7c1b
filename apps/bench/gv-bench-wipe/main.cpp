// gv-bench-wipe: the E-step's map of a trajectory (GlobalMap::buildPerScan: Eq. 4 unmerged and
// the full product of Eq. 8, computed by WipeProduct vector by vector) on a log at the poses of a
// trajectory, against the same product run scan by scan through ScanWipe (the sequential mode's
// update) in the same run: CPU time of each, the work (triangle/vector pairs, cells updated),
// and whether the two maps are the same bit for bit.
//
//   gv-bench-wipe LOG TRAJ [--repeat N] [--config FILE.ini]
//
// TRAJ: `t x y theta` per scan (gv-em-slam's trajectory.txt). The scans are gv-em-slam's
// keyframes (mstep.keyframe_distance / keyframe_rotation_deg on the log's odometry) and the
// parameters the library defaults gv-em-slam runs with, so the product is the one
// gv-em-slam's E-step computes at that trajectory.
#include "em/EmSlam.h"
#include "map/GlobalMap.h"
#include "extraction/VectorExtractor.h"
#include "common/ArgParser.h"
#include "io/Counted.h"
#include "io/Progress.h"
#include <gridvector/io/LogReader.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <stdexcept>
#include <string>
#include <vector>

using namespace gridvector;
using mrpt::math::TPose2D;

namespace
{
const int kRepeat = 3;  //!< --repeat
double cpuSeconds(std::clock_t a, std::clock_t b) { return double(b - a) / CLOCKS_PER_SEC; }

// The reference: ScanWipe::apply scan by scan over the per-scan vectors, each scan's own left out.
std::vector<GridVector> scanByScan(const std::vector<TPose2D>& poses, const std::vector<LocalScan>& scans,
								   const GridVectorConfig& cfg, ScanWipe::Stats& total)
{
	std::vector<GridVector> all;
	std::vector<size_t> first;
	for (size_t t = 0; t < scans.size(); ++t)
	{
		first.push_back(all.size());
		for (const auto& v : scans[t].vectors) all.push_back(v.compose(poses[t]));
	}
	first.push_back(all.size());
	VectorIndex index(VectorIndex::kCellSize);
	for (size_t i = 0; i < all.size(); ++i) index.insert(uint32_t(i), Box2D::of(all[i]));
	ScanWipe wiper(cfg.map.hitBand, GlobalMap::kBatchWipeCountsBeams);  // the unit of the product it is timed against
	std::vector<ScanWipe::Segment> segs;
	total = {};
	for (size_t t = 0; t < scans.size(); ++t)
	{
		segs.clear();
		for (size_t i = first[t]; i < first[t + 1]; ++i) segs.push_back(ScanWipe::segmentOf(all[i]));
		const auto st = wiper.apply(
			GlobalMap::sensorPosition(poses[t], scans[t]), segs, all, index,
			[&](size_t, uint32_t s) { return s >= first[t] && s < first[t + 1] ? WipePart::Outside : WipePart::Hit; });
		total.triangles += st.triangles, total.candidates += st.candidates;
		total.vectorsTouched += st.vectorsTouched, total.cellsHit += st.cellsHit, total.cellsVisited += st.cellsVisited;
	}
	return all;
}

size_t differingCells(const std::vector<GridVector>& a, const std::vector<GridVector>& b)
{
	if (a.size() != b.size()) return SIZE_MAX;
	size_t n = 0;
	for (size_t i = 0; i < a.size(); ++i)
	{
		if (a[i].cells().size() != b[i].cells().size()) return SIZE_MAX;
		for (size_t c = 0; c < a[i].cells().size(); ++c)
			n += std::memcmp(&a[i].cells()[c], &b[i].cells()[c], sizeof(GridCell)) != 0;
	}
	return n;
}
}  // namespace

int run(const io::ArgParser& args)
{
	args.requirePositional(2, 2);
	const std::string log = args.positional()[0], trajPath = args.positional()[1];
	const int repeat = int(args.getInt("repeat", kRepeat, 1, 1000));
	GridVectorConfig cfg;
	if (args.has("config")) cfg.loadFromFile(args.get("config"));
	const bool quiet = args.has("quiet");
	io::ReadOptions ro;
	ro.quiet = quiet;
	const io::LogData data = io::readLog(log, ro);
	const io::Trajectory traj = io::readTrajectory(trajPath);
	io::requireScans(data);
	if (traj.size() != data.scans.size())
		throw std::runtime_error(trajPath + ": " + io::counted(traj.size(), "pose") + " for " +
								 io::counted(data.scans.size(), "scan"));
	std::vector<TPose2D> odo;
	for (const auto& r : data.scans) odo.push_back(r.hasOdometry ? r.odometry : r.hasLogPose ? r.logPose : TPose2D());
	const auto key = EmSlam::keyframes(odo, cfg.mstep);
	const VectorExtractor ex(cfg.extraction, cfg.grid);
	std::vector<LocalScan> scans;
	std::vector<TPose2D> poses;
	size_t cells = 0;
	for (size_t k = 0; k < key.size(); ++k)
	{
		scans.push_back(ex.extract(*data.scans[key[k]].scan));
		scans.back().scanIndex = int64_t(k);
		poses.push_back(traj[key[k]].second);
		for (const auto& v : scans.back().vectors) cells += v.cells().size();
	}

	double product = 1e300, reference = 1e300;
	std::vector<GridVector> a, b;
	ScanWipe::Stats st;
	io::Progress progress(quiet);  // between the timed calls
	for (int r = 0; r < repeat; ++r)  // alternated, so that both see the same machine
	{
		progress.show("timing passes", size_t(r), size_t(repeat));
		auto c0 = std::clock();
		a = GlobalMap::buildPerScan(poses, scans, cfg);
		auto c1 = std::clock();
		b = scanByScan(poses, scans, cfg, st);
		auto c2 = std::clock();
		product = std::min(product, cpuSeconds(c0, c1));
		reference = std::min(reference, cpuSeconds(c1, c2));
	}
	progress.done();
	const size_t differ = differingCells(a, b);
	std::printf("log: %s\nkeyframes: %zu of %zu scans, %zu vectors, %zu cells\n", log.c_str(), key.size(),
				data.scans.size(), a.size(), cells);
	std::printf(
		"work: %zu triangle/vector pairs from the index, %zu (scan, vector) pairs updated, %zu cells hit, "
		"%zu cells passed\n",
		st.candidates, st.vectorsTouched, st.cellsHit, st.cellsVisited);
	std::printf(
		"buildPerScan (WipeProduct): %.3f s CPU; scan by scan (ScanWipe): %.3f s CPU; ratio %.2f "
		"(best of %d each)\n",
		product, reference, reference / product, repeat);
	std::printf("cells differing: %zu (%s)\n", differ, differ == 0 ? "identical" : "NOT identical");
	return differ == 0 ? 0 : 1;
}

int main(int argc, char** argv)
{
	io::ArgParser args("gv-bench-wipe", "LOG TRAJ [--repeat N] [--config FILE.ini]");
	args.option("repeat", "N", "timings of each path, alternated; the best is reported", std::to_string(kRepeat));
	args.flag("quiet", "no progress (the figures on stdout are the output)");
	args.option("config", "FILE.ini", "parameters over gv-em-slam's defaults", "none: gv-em-slam's defaults");
	return io::runTool(args, argc, argv, [&] { return run(args); });
}
