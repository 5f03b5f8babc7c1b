// gv-bench-extract: grid-vector extraction throughput (Sec. 3.1) on a real log,
// single-threaded, against MRPT's own scan -> CSimplePointsMap conversion of the
// same scans in the same run (a peer every MRPT user already pays for).
//
//   gv-bench-extract LOG [--repeat N] [--config FILE.ini]
#include "extraction/VectorExtractor.h"
#include "common/ArgParser.h"
#include "io/Progress.h"
#include <gridvector/io/LogReader.h>
#include <mrpt/maps/CSimplePointsMap.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

using namespace gridvector;
using Clock = std::chrono::steady_clock;

namespace
{
const int kRepeat = 5;  //!< --repeat
double seconds(Clock::time_point a, Clock::time_point b) { return std::chrono::duration<double>(b - a).count(); }

// RMS orthogonal residual of each fitted segment (not timed).
void residuals(const VectorExtractor& ex, const mrpt::obs::CObservation2DRangeScan& scan, std::vector<double>& out)
{
	std::vector<mrpt::math::TPoint2D> pts;
	std::vector<size_t> runs;
	ex.scanToRuns(scan, pts, runs);
	runs.push_back(pts.size());
	const auto& o = ex.extractionOptions();
	for (size_t r = 0; r + 1 < runs.size(); ++r)
	{
		if (runs[r + 1] - runs[r] < size_t(o.minPoints)) continue;
		for (const auto& s : ex.splitAndMerge(pts, runs[r], runs[r + 1] - 1, scan.stdError))
		{
			if (s.last - s.first + 1 < size_t(o.minPoints)) continue;
			if (ex.makeVector(pts, s, {0, 0}).length() < o.minLength) continue;
			double ss = 0;
			for (size_t k = s.first; k <= s.last; ++k) ss += std::pow(s.line.distance(pts[k]), 2);
			out.push_back(std::sqrt(ss / double(s.last - s.first + 1)));
		}
	}
}
}  // namespace

int run(const io::ArgParser& args)
{
	args.requirePositional(1, 1);
	const std::string log = args.positional()[0];
	const int repeat = int(args.getInt("repeat", kRepeat, 1, 1'000'000));
	GridVectorConfig cfg;
	if (args.has("config")) cfg.loadFromFile(args.get("config"));
	const bool quiet = args.has("quiet");
	io::ReadOptions ro;
	ro.quiet = quiet;
	const io::LogData data = io::readLog(log, ro);
	io::requireScans(data);
	const VectorExtractor ex(cfg.extraction, cfg.grid);

	size_t vectors = 0, beams = 0;
	io::Progress progress(quiet);  // once per pass: nothing measurable in the timings
	const auto t0 = Clock::now();
	for (int r = 0; r < repeat; ++r)
	{
		for (const auto& rec : data.scans) vectors += ex.extract(*rec.scan).vectors.size();
		progress.show("extraction passes", size_t(r + 1), size_t(repeat));
	}
	const auto t1 = Clock::now();
	for (int r = 0; r < repeat; ++r)
	{
		for (const auto& rec : data.scans)
		{
			mrpt::maps::CSimplePointsMap pm;
			pm.insertObservation(*rec.scan);
			beams += pm.size();
		}
		progress.show("peer passes", size_t(r + 1), size_t(repeat));
	}
	const auto t2 = Clock::now();
	progress.done();

	std::vector<double> res;
	for (const auto& rec : data.scans) residuals(ex, *rec.scan, res);
	std::sort(res.begin(), res.end());
	const double n = double(data.scans.size()) * repeat;
	const double gvRate = n / seconds(t0, t1), pmRate = n / seconds(t1, t2);
	std::printf("log: %s\nscans: %zu x %d repeats, %zu beams/scan\n", log.c_str(), data.scans.size(), repeat,
				data.scans[0].scan->getScanSize());
	std::printf("extraction: %.0f scans/s (%.1f us/scan), %.2f vectors/scan\n", gvRate, 1e6 / gvRate,
				double(vectors) / n);
	std::printf("peer CSimplePointsMap::insertObservation: %.0f scans/s; extraction/peer speed ratio %.2f\n", pmRate,
				gvRate / pmRate);
	std::printf("fit residual (RMS per segment): median %.4f m, 90th pct %.4f m over %zu segments\n",
				res.empty() ? 0.0 : res[res.size() / 2], res.empty() ? 0.0 : res[res.size() * 9 / 10], res.size());
	return 0;
}

int main(int argc, char** argv)
{
	io::ArgParser args("gv-bench-extract", "LOG [--repeat N] [--config FILE.ini]");
	args.option("repeat", "N", "passes over the log for each timing", std::to_string(kRepeat));
	args.flag("quiet", "no progress (the figures on stdout are the output)");
	args.option("config", "FILE.ini", "gridvector parameters ([gridvector_extraction], [gridvector_grid])",
				"the library's defaults (gv-config --ini)");
	return io::runTool(args, argc, argv, [&] { return run(args); });
}
