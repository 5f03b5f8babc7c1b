#include <gridvector/io/CarmenReader.h>
#include <gridvector/io/FileBytes.h>
#include <gridvector/io/LogReader.h>
#include <gridvector/io/RawlogReader.h>

#include <algorithm>
#include <cctype>

namespace gridvector::io
{
namespace
{
bool endsWith(const std::string& s, const std::string& suffix)
{
	return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

/** CARMEN logs are text; rawlogs are MRPT binary serialisations. */
bool looksLikeText(const std::vector<char>& bytes)
{
	const size_t n = std::min<size_t>(bytes.size(), 4096);
	return std::all_of(bytes.begin(), bytes.begin() + n, [](char c) {
		const auto u = static_cast<unsigned char>(c);
		return std::isprint(u) || std::isspace(u);
	});
}
}  // namespace

LogData readLog(const std::string& path, const ReadOptions& opt)
{
	std::string name = path;
	std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return char(std::tolower(c)); });
	if (endsWith(name, ".gz")) name.resize(name.size() - 3);
	const std::vector<char> bytes = readFileBytes(path);
	const bool rawlog = endsWith(name, ".rawlog") ||
						(!endsWith(name, ".log") && !endsWith(name, ".clf") && !looksLikeText(bytes));
	return rawlog ? parseRawlog(bytes, path, opt) : parseCarmenLog(bytes, path, opt);
}

Trajectory trajectoryOf(const LogData& log, bool logPose)
{
	Trajectory t;
	for (const auto& s : log.scans)
		if (logPose ? s.hasLogPose : s.hasOdometry) t.emplace_back(s.timestamp, logPose ? s.logPose : s.odometry);
	return t;
}

}  // namespace gridvector::io
