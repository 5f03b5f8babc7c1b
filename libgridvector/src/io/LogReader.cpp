#include "io/CarmenReader.h"
#include "io/FileBytes.h"
#include <gridvector/io/LogReader.h>
#include "io/Counted.h"
#include "io/NoReturnRange.h"
#include "io/RawlogReader.h"

#include <algorithm>
#include <cstdio>
#include <cctype>
#include <stdexcept>

namespace gridvector::io
{
namespace
{
bool endsWith(const std::string& s, const std::string& suffix)
{
	return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/** CARMEN logs are text; rawlogs are MRPT binary serialisations. */
bool looksLikeText(std::string_view bytes)
{
	const size_t n = std::min<size_t>(bytes.size(), 4096);
	return std::all_of(bytes.begin(), bytes.begin() + n, [](char c) {
		const auto u = static_cast<unsigned char>(c);
		return std::isprint(u) || std::isspace(u);
	});
}

bool isRawlog(const std::string& name, std::string_view head)
{
	return endsWith(name, ".rawlog") || (!endsWith(name, ".log") && !endsWith(name, ".clf") && !looksLikeText(head));
}

/** Before the whole file is read: a rawlog's first byte is a class-name length with bit 7 set (MRPT >= 0.5.5),
 * or the low byte of a non-zero length, never 0; text has no NUL either (so /dev/zero stops here). CARMEN
 * lines are at most kMaxLineBytes long. */
ReadLimits logLimits(const std::string& path, const std::string& name)
{
	ReadLimits lim;
	lim.onHead = [path, name](std::string_view head) -> size_t {
		if (!head.empty() && head[0] == '\0')
			throw std::runtime_error(path + ": neither a CARMEN log nor an MRPT rawlog (it starts with a NUL byte)");
		return isRawlog(name, head) ? 0 : kMaxLineBytes;
	};
	return lim;
}
}  // namespace

namespace
{
// CARMEN declares one maximum for the log; a saturating scanner's real "no return" is lower.
void applyNoReturnRange(LogData& log)
{
	const auto range = saturationRange(log);
	if (!range) return;
	float declared = 0;
	for (const auto& r : log.scans) declared = std::max(declared, r.scan->maxRange);
	if (*range >= double(declared) - 0.011) return;  // already the declared maximum
	applyMaxRange(log, *range);
	log.noReturnRange = *range;
	char buf[224];
	std::snprintf(buf, sizeof buf,
				  "readings of %.2f m and more (a spike at the top, in >= %g %% and >= %zu of the scans) are the "
				  "scanner's no-return value: max range %.2f m instead of %.2f m",
				  *range, 100 * kNoReturnMinShare, kNoReturnMinScans, *range, double(declared));
	log.warnings.push_back(buf);
	log.summary += std::string("; ") + buf;
}
}  // namespace

LogData readLog(const std::string& path, const ReadOptions& opt)
{
	std::string name = path;
	std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
	if (endsWith(name, ".gz")) name.resize(name.size() - 3);
	const std::vector<char> bytes = readFileBytes(path, nullptr, logLimits(path, name));
	const bool rawlog = isRawlog(name, std::string_view(bytes.data(), bytes.size()));
	if (rawlog) return parseRawlog(bytes, path, opt);
	LogData log = parseCarmenLog(bytes, path, opt);
	if (opt.detectNoReturnRange) applyNoReturnRange(log);
	return log;
}

void requireScans(const LogData& log)
{
	if (log.scans.empty())
		throw std::runtime_error(log.source + ": no laser scans (" + describeContents(log.contents) + ")");
}

std::string describeContents(const LogContents& c)
{
	const auto n = [](size_t k) { return std::to_string(k); };
	std::string s;
	if (c.format == LogContents::Format::Carmen)
		s = n(c.odometryRecords) + " ODOM, " + n(c.paramLines) + " PARAM";
	else
	{
		s = c.sensoryFrames ? "actions+sensory-frames format (" + counted(c.actionSets, "action set") + ", " +
								  counted(c.sensoryFrames, "sensory frame") + ")"
							: "observation-only format (" + counted(c.observations, "observation") + ")";
		s += c.odometryRecords   ? "; odometry from " + counted(c.odometryRecords, "odometry observation")
			 : c.movementActions ? "; odometry from robot-movement actions"
								 : "; no odometry";
	}
	for (const auto& [k, count] : c.ignored) s += ", " + n(count) + " " + k + " ignored";
	return s;
}

Trajectory trajectoryOf(const LogData& log, bool logPose)
{
	Trajectory t;
	for (const auto& s : log.scans)
		if (logPose ? s.hasLogPose : s.hasOdometry) t.emplace_back(s.timestamp, logPose ? s.logPose : s.odometry);
	return t;
}

}  // namespace gridvector::io
