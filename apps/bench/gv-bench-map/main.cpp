// gv-bench-map: the global grid vector map (Sec. 3.2) on real logs with their
// corrected poses, against MRPT's COccupancyGridMap2D built from the same scans
// and poses in the same run:
//  - vectors, total length, Table 1 memory figures (n_g / n_v);
//  - Eq. 6 grid vs MRPT grid: same occupied/free decision on the cells within
//    --band metres of a vector that both maps know;
//  - insertion speed (scans/s) of both, and time per scan over the first and
//    the last 10 % of the log (sequential insertScan);
//  - the batch path (buildPerScan + mergeAll) used by the EM loop;
//  - n_g/n_v as in Table 1 (final static map): the batch per-scan vectors
//    classified by the E-step (Eq. 14-15) at these poses, the dynamic ones
//    removed, the static ones merged (Eq. 4), as EmSlam's final static map.
//
//   gv-bench-map [--config FILE.ini] [--max-scans N] [--band M] [--repeat R] LOG...
#include "estep/EStep.h"
#include "io/ErrorText.h"
#include "map/GlobalMap.h"
#include "map/MemoryAccounting.h"
#include "map/OccupancyConversion.h"
#include "extraction/VectorExtractor.h"
#include "common/ArgParser.h"
#include "io/Progress.h"
#include "io/TextParsing.h"
#include <gridvector/io/LogReader.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <numeric>

using namespace gridvector;
using Clock = std::chrono::steady_clock;

namespace
{
const double kBand = 0.2;  //!< --band [m]
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

struct Agreement
{
	size_t band = 0;  //!< grid cells within the band of a vector
	size_t both = 0;  //!< ... known (occupied or free) in both maps
	size_t same = 0;  //!< ... with the same decision
	size_t occBoth = 0, occSame = 0;  //!< restricted to cells MRPT says occupied
	double pct() const { return both ? 100.0 * same / both : 0; }
};

/** Cells of `grid` whose centre lies within `band` of a vector's segment. */
std::vector<uint8_t> bandMask(const std::vector<GridVector>& vs, const mrpt::maps::COccupancyGridMap2D& g, double band)
{
	const int nx = int(g.getSizeX()), ny = int(g.getSizeY());
	const double res = g.getResolution(), x0 = g.getXMin(), y0 = g.getYMin();
	std::vector<uint8_t> mask(size_t(nx) * ny, 0);
	for (const GridVector& v : vs)
	{
		const auto s = v.start(), e = v.end();
		const double l2 = std::max(1e-12, (e.x - s.x) * (e.x - s.x) + (e.y - s.y) * (e.y - s.y));
		const int ix0 = std::max(0, int((std::min(s.x, e.x) - band - x0) / res));
		const int ix1 = std::min(nx - 1, int((std::max(s.x, e.x) + band - x0) / res));
		const int iy0 = std::max(0, int((std::min(s.y, e.y) - band - y0) / res));
		const int iy1 = std::min(ny - 1, int((std::max(s.y, e.y) + band - y0) / res));
		for (int iy = iy0; iy <= iy1; ++iy)
			for (int ix = ix0; ix <= ix1; ++ix)
			{
				const double px = x0 + (ix + 0.5) * res, py = y0 + (iy + 0.5) * res;
				const double t = std::clamp(((px - s.x) * (e.x - s.x) + (py - s.y) * (e.y - s.y)) / l2, 0.0, 1.0);
				const double dx = px - (s.x + t * (e.x - s.x)), dy = py - (s.y + t * (e.y - s.y));
				if (dx * dx + dy * dy <= band * band) mask[size_t(iy) * nx + ix] = 1;
			}
	}
	return mask;
}

/** The command line's settings, with the configuration they come from. */
struct BenchOptions
{
	GridVectorConfig cfg;
	long maxScans = 0;  //!< --max-scans (0: all)
	double band = kBand;  //!< --band [m]
	int repeat = 1;  //!< --repeat
	int samples = 0;  //!< --samples, else [gridvector_occupancy] samples_per_axis
	bool quiet = false;
};

Agreement agreement(const std::vector<GridVector>& vs, const mrpt::maps::COccupancyGridMap2D& mrptGrid,
					const BenchOptions& o)
{
	const OccupancyRaster R = OccupancyConversion::rasterise(
		vs, mrptGrid.getXMin(), mrptGrid.getYMin(), mrptGrid.getResolution(), int(mrptGrid.getSizeX()),
		int(mrptGrid.getSizeY()), o.samples, o.cfg.occupancy.maxPooling, o.cfg.grid);
	const auto mask = bandMask(vs, mrptGrid, o.band);
	Agreement a;
	for (int iy = 0; iy < R.ny; ++iy)
		for (int ix = 0; ix < R.nx; ++ix)
		{
			if (!mask[size_t(iy) * R.nx + ix]) continue;
			++a.band;
			const float free = mrptGrid.getCell(ix, iy);  // MRPT stores p(free)
			const double pm = 1.0 - free, pg = R.probability(ix, iy);
			if (free == 0.5f || !R.known(ix, iy) || pg == 0.5) continue;
			++a.both;
			a.same += (pm > 0.5) == (pg > 0.5);
			if (pm > 0.5) ++a.occBoth, a.occSame += pg > 0.5;
		}
	return a;
}

/** MRPT's own order dependence (its log-odds saturate, so recent scans
 * dominate): the same band cells of two MRPT grids, known in both. */
Agreement mrptSelfAgreement(const std::vector<GridVector>& vs, const mrpt::maps::COccupancyGridMap2D& a,
							const mrpt::maps::COccupancyGridMap2D& b, double band)
{
	const auto mask = bandMask(vs, a, band);
	Agreement r;
	for (unsigned iy = 0; iy < a.getSizeY(); ++iy)
		for (unsigned ix = 0; ix < a.getSizeX(); ++ix)
		{
			if (!mask[size_t(iy) * a.getSizeX() + ix]) continue;
			++r.band;
			const float fa = a.getCell(ix, iy), fb = b.getPos(a.idx2x(ix), a.idx2y(iy));
			if (fa == 0.5f || fb == 0.5f) continue;
			++r.both;
			r.same += (fa < 0.5f) == (fb < 0.5f);
		}
	return r;
}

struct Timing
{
	double total = 0, first10 = 0, last10 = 0;  //!< seconds; first/last: mean per scan
};

Timing perScanTiming(const std::vector<double>& t)
{
	Timing r;
	r.total = std::accumulate(t.begin(), t.end(), 0.0);
	const size_t k = std::max<size_t>(1, t.size() / 10);
	if (t.size() < 2) return r;
	r.first10 = std::accumulate(t.begin(), t.begin() + long(k), 0.0) / double(k);
	r.last10 = std::accumulate(t.end() - long(k), t.end(), 0.0) / double(k);
	return r;
}

void benchLog(const std::string& path, const BenchOptions& o)
{
	const GridVectorConfig& cfg = o.cfg;
	const long maxScans = o.maxScans;
	const double band = o.band;
	const bool quiet = o.quiet;
	io::ReadOptions ro;
	ro.includeRearLaser = false;
	ro.quiet = quiet;
	const io::LogData log = io::readLog(path, ro);
	std::vector<mrpt::math::TPose2D> poses;
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> obs;
	for (const auto& r : log.scans)
	{
		if (maxScans > 0 && long(obs.size()) >= maxScans) break;
		if (!r.hasLogPose && !r.hasOdometry) continue;
		poses.push_back(r.hasLogPose ? r.logPose : r.odometry);
		obs.push_back(r.scan);
	}
	const size_t n = obs.size();
	if (n == 0) throw std::runtime_error(path + ": no scans with a pose");

	// Sec. 3.1 extraction (timed, part of inserting a scan into a grid vector map)
	const VectorExtractor ex(cfg.extraction, cfg.grid);
	std::vector<LocalScan> scans(n);
	std::vector<double> tExtract(n), tInsert(n), tMrpt(n);
	std::vector<double> work(n), cellsWiped(n);  // deterministic work per scan (load-independent)
	for (size_t t = 0; t < n; ++t)
	{
		const auto a = Clock::now();
		scans[t] = ex.extract(*obs[t]);
		scans[t].scanIndex = int64_t(t);
		tExtract[t] = seconds(a, Clock::now());
	}
	// Sec. 3.2 sequential insertion
	// (--repeat R: the whole sequence R times, each scan's fastest time kept,
	// so that other processes on a shared machine do not decide the figures)
	GlobalMap map(cfg);
	io::Progress progress(quiet);  // drawn between the timed calls
	for (int rep = 0; rep < o.repeat; ++rep)
	{
		map.clear();
		for (size_t t = 0; t < n; ++t)
		{
			const auto a = Clock::now();
			map.insertScan(poses[t], scans[t]);
			const double dt = seconds(a, Clock::now());
			tInsert[t] = rep ? std::min(tInsert[t], dt) : dt;
			const auto& st = map.lastInsertStats();
			work[t] = double(st.wipe.candidates);
			cellsWiped[t] = double(st.wipe.cellsHit + st.wipe.cellsVisited);
			progress.show(path + ": sequential insertion " + std::to_string(rep + 1) + "/" + std::to_string(o.repeat),
						  t + 1, n);
		}
	}
	// MRPT's occupancy grid from the same scans and poses
	// (timed the same way: --repeat R fresh grids, each scan's fastest time)
	mrpt::maps::COccupancyGridMap2D grid(-10, 10, -10, 10, float(cfg.grid.resolution));
	for (int rep = 0; rep < o.repeat; ++rep)
	{
		grid = mrpt::maps::COccupancyGridMap2D(-10, 10, -10, 10, float(cfg.grid.resolution));
		grid.insertionOptions.maxDistanceInsertion = 80.0f;
		for (size_t t = 0; t < n; ++t)
		{
			const mrpt::poses::CPose3D pose(poses[t].x, poses[t].y, 0, poses[t].phi, 0, 0);
			const auto a = Clock::now();
			grid.insertObservation(*obs[t], pose);
			const double dt = seconds(a, Clock::now());
			tMrpt[t] = rep ? std::min(tMrpt[t], dt) : dt;
			progress.show(path + ": MRPT grid " + std::to_string(rep + 1) + "/" + std::to_string(o.repeat), t + 1, n);
		}
	}
	progress.done();
	mrpt::maps::COccupancyGridMap2D gridRev(-10, 10, -10, 10, float(cfg.grid.resolution));
	gridRev.insertionOptions = grid.insertionOptions;
	for (size_t k = n; k-- > 0;)
		gridRev.insertObservation(*obs[k], mrpt::poses::CPose3D(poses[k].x, poses[k].y, 0, poses[k].phi, 0, 0));
	// batch mode (EM loop)
	const auto b0 = Clock::now();
	const auto perScan = GlobalMap::buildPerScan(poses, scans, cfg);
	const auto b1 = Clock::now();
	const MergeResult merged = GlobalMap::mergeAll(perScan, cfg);
	const auto b2 = Clock::now();
	// Table 1's maps are EM's final maps, built as EmSlam builds its final static
	// map: E-step, final split, static children merged, unobserved stretches cut
	const EStep estep(cfg.estep, cfg.grid);
	const EStepResult split = estep.run(perScan);
	std::vector<GridVector> statics;
	for (const auto& v : estep.finalSplit(split.children))
		if (v.state != VectorState::Dynamic) statics.push_back(v);
	const MergeResult staticMap = estep.cutUnobserved(GlobalMap::mergeAll(statics, cfg), statics);

	const Timing te = perScanTiming(tExtract), ti = perScanTiming(tInsert), tm = perScanTiming(tMrpt);
	const MemoryReport mem = MemoryAccounting::account(map.vectors(), 0.1);
	const MemoryReport memB = MemoryAccounting::account(merged.vectors, 0.1);
	const MemoryReport memS = MemoryAccounting::account(staticMap.vectors, 0.1);
	const Agreement ag = agreement(map.vectors(), grid, o), agB = agreement(merged.vectors, grid, o);
	const Agreement agM = mrptSelfAgreement(map.vectors(), grid, gridRev, band);
	size_t perScanVectors = 0;
	for (const auto& s : scans) perScanVectors += s.vectors.size();

	std::printf("== %s: %zu scans, %zu per-scan vectors\n", path.c_str(), n, perScanVectors);
	std::printf(
		"sequential: %zu vectors, %.1f m; Table 1: n_g %zu, n_v %zu, n_g/n_v %.2f; with width %zu cells (n_g/cells "
		"%.2f); bytes grid %zu vs vectors %zu\n",
		mem.vectorCount, mem.vectorLength, mem.n_g, mem.n_v, mem.ratio, mem.cells, mem.ratioCells, mem.bytesGrid,
		mem.bytesGridVector);
	std::printf("batch:      %zu vectors, %.1f m; n_g/n_v %.2f; buildPerScan %.3f s, mergeAll %.3f s\n",
				memB.vectorCount, memB.vectorLength, memB.ratio, seconds(b0, b1), seconds(b1, b2));
	std::printf(
		"static map (Table 1: E-step at these poses, dynamic removed, static merged): %zu vectors, %.1f m (E-step: "
		"dynamic %.1f m of per-scan vectors); n_g/n_v %.2f\n",
		memS.vectorCount, memS.vectorLength, split.dynamicLength, memS.ratio);
	std::printf(
		"agreement with MRPT grid (cells within %.2f m of a vector, known in both): sequential %.2f %% (%zu/%zu of "
		"%zu; occupied %zu/%zu), batch %.2f %% (%zu/%zu)\n",
		band, ag.pct(), ag.same, ag.both, ag.band, ag.occSame, ag.occBoth, agB.pct(), agB.same, agB.both);
	std::printf("MRPT grid vs MRPT grid of the same scans inserted in reverse order, same cells: %.2f %% (%zu/%zu)\n",
				agM.pct(), agM.same, agM.both);
	std::printf(
		"speed: extract %.0f scans/s, insertScan %.0f scans/s, extract+insert %.0f scans/s; MRPT grid %.0f scans/s; "
		"ratio (extract+insert)/MRPT %.2f\n",
		n / te.total, n / ti.total, n / (te.total + ti.total), n / tm.total, tm.total / (te.total + ti.total));
	std::printf("insertScan per scan: first 10 %% %.3f ms, last 10 %% %.3f ms (map %zu vectors at the end)\n",
				1e3 * ti.first10, 1e3 * ti.last10, map.size());
	std::printf("insertScan per scan by decile [ms]:");
	for (int d = 0; d < 10; ++d)
	{
		const size_t a = n * d / 10, b = std::max(a + 1, n * (d + 1) / 10);
		std::printf(" %.3f",
					1e3 * std::accumulate(tInsert.begin() + long(a), tInsert.begin() + long(std::min(b, n)), 0.0) /
						double(b - a));
	}
	const Timing tw = perScanTiming(work), tc = perScanTiming(cellsWiped);
	std::printf(
		"\nwork per scan, first/last 10 %%: Eq. 8 triangle-vector candidates %.0f / %.0f, map cells wiped %.0f / "
		"%.0f\n",
		tw.first10, tw.last10, tc.first10, tc.last10);
	std::printf(
		"| %s | %zu | %zu | %.1f | %.1f | %.2f | %.2f | %.2f | %.1f %% | %.1f %% | %.0f | %.0f | %.2f | %.3f / %.3f | "
		"%.2f |\n",
		path.substr(path.find_last_of('/') + 1).c_str(), n, mem.vectorCount, mem.vectorLength, mem.spaceSize, mem.ratio,
		memS.ratio, mem.ratioCells, ag.pct(), agB.pct(), n / (te.total + ti.total), n / tm.total,
		tm.total / (te.total + ti.total), 1e3 * ti.first10, 1e3 * ti.last10, seconds(b0, b2));
	std::fflush(stdout);
}
}  // namespace

int main(int argc, char** argv)
{
	io::ArgParser args("gv-bench-map", "[options] LOG...");
	args.option("config", "FILE.ini", "gridvector parameters", "the library's defaults (gv-config --ini)");
	args.option("max-scans", "N", "use at most N scans of each log (0: all)", "0");
	args.option("band", "M", "compare cells within M metres of a vector", io::shortestText(kBand));
	args.option("repeat", "R", "sequential insertion R times, each scan's fastest time kept", "1");
	args.flag("quiet", "no progress (the table on stdout is the output)");
	args.option("samples", "N", "Eq. 6 sub-samples per axis of a grid cell (0: automatic)",
				"[gridvector_occupancy] samples_per_axis");
	return io::runTool(args, argc, argv, [&] {
		args.requirePositional(1, 100);
		BenchOptions o;
		if (args.has("config")) o.cfg.loadFromFile(args.get("config"));
		o.maxScans = args.getInt("max-scans", 0, 0, 100000000);
		o.band = args.getDouble("band", kBand);
		if (o.band <= 0) args.fail("--band must be > 0 (metres), got " + args.get("band"));  // -1 compared no cell
		o.repeat = int(args.getInt("repeat", 1, 1, 100));
		o.samples = int(args.getInt("samples", o.cfg.occupancy.samplesPerAxis, 0, 16));
		o.quiet = args.has("quiet");
		std::printf(
			"| log | scans | vectors | length [m] | space [m^2] | n_g/n_v | n_g/n_v static | n_g/cells | agree seq | "
			"agree batch | gv scans/s | MRPT scans/s | speed ratio | ms/scan first/last 10%% | batch [s] "
			"|\n|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
		for (const auto& log : args.positional()) benchLog(log, o);
		return 0;
	});
}
