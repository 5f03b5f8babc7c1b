// gv-carmen2rawlog: CARMEN log -> MRPT rawlog with correct timestamps, aperture
// and max range (a replacement for MRPT 2.5's carmen2rawlog).
#include "common/ArgParser.h"
#include "io/Counted.h"
#include "io/AtomicFile.h"
#include <gridvector/io/LogReader.h>
#include "io/RawlogWriter.h"

#include "io/NoReturnRange.h"

#include <cstdio>
#include <iostream>

using namespace gridvector::io;

namespace
{
/** What the scans' max range is now, for the summary line. */
std::string rangeNoteOf(const LogData& log, const std::string& mode)
{
	if (mode == "declared") return "; declared max range kept";
	if (mode == "auto" && log.noReturnRange <= 0) return "; declared max range kept";
	float r = 0;
	for (const auto& s : log.scans) r = std::max(r, s.scan->maxRange);
	char buf[64];
	std::snprintf(buf, sizeof buf, "; max range set to %.2f m", double(r));
	return buf;
}
}  // namespace

int main(int argc, char** argv)
{
	ArgParser args("gv-carmen2rawlog", "IN.log[.gz] OUT.rawlog [options]");
	args.option("format", "obs|sf",
				"obs: CObservationOdometry + CObservation2DRangeScan; "
				"sf: actions + sensory frames (for rbpf-slam)",
				"obs");
	args.flag("no-compress", "write an uncompressed rawlog (without it: gzip, as MRPT does)");
	args.flag("front-only", "drop rear-laser scans (RLASER, RAWLASER2)");
	args.option("max-range", "auto|declared|M",
				"auto: a reading shared exactly by >= 1 % and >= 10 of the scans at the log's maximum, below the "
				"declared maximum, is the scanner's no-return value (as the CARMEN reader does for every tool); "
				"declared: keep the log's declared maximum; M: readings at or beyond M metres are 'no return' "
				"(invalid) and every scan's maxRange is M",
				"auto");
	args.flag("quiet", "no progress and no summary");
	return runTool(args, argc, argv, [&] {
		args.requirePositional(2, 2);
		const std::string format = args.get("format", "obs");
		if (format != "obs" && format != "sf") args.fail("--format must be obs or sf, got '" + format + "'");
		const bool quiet = args.has("quiet");

		const std::string rangeMode = args.get("max-range", "auto");
		const bool fixedRange = rangeMode != "auto" && rangeMode != "declared";
		const double range = fixedRange ? args.getDouble("max-range", 0) : 0;
		if (fixedRange && !(range > 0)) args.fail("--max-range must be auto, declared or a positive number");
		checkWritableFile(args.positional()[1]);  // before the read, not after it
		ReadOptions ro;
		ro.quiet = quiet;
		ro.includeRearLaser = !args.has("front-only");
		ro.detectNoReturnRange = rangeMode == "auto";
		LogData log = readLog(args.positional()[0], ro);
		if (log.scans.empty()) throw std::runtime_error(args.positional()[0] + ": no laser scans to convert");
		if (fixedRange) gridvector::io::applyMaxRange(log, range);
		const std::string rangeNote = rangeNoteOf(log, rangeMode);

		RawlogWriteOptions wo;
		wo.format = format == "sf" ? RawlogFormat::SensoryFrames : RawlogFormat::Observations;
		wo.compress = !args.has("no-compress");
		writeRawlog(args.positional()[1], log, wo);
		if (!quiet)
		{
			size_t odo = 0;
			for (const auto& s : log.scans) odo += s.hasOdometry;
			std::cout << log.summary << rangeNote << "\n"
					  << "wrote " << args.positional()[1] << ": " << gridvector::io::counted(log.scans.size(), "scan")
					  << ", "
					  << (format == "sf" ? gridvector::io::counted(log.scans.size(), "robot-movement action")
										 : gridvector::io::counted(odo, "odometry observation"))
					  << " (" << (format == "sf" ? "actions+sensory-frames" : "observation-only") << " format"
					  << (wo.compress ? ", gzip" : "") << ")\n";
		}
		return 0;
	});
}
