#include "io/AtomicFile.h"
#include "io/Counted.h"
#include "io/FileBytes.h"
#include <gridvector/io/LogReader.h>
#include "io/TextParsing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace gridvector::io
{
Trajectory readTrajectory(const std::string& path)
{
	ReadLimits lim;
	lim.onHead = [](std::string_view) { return kMaxLineBytes; };
	const std::vector<char> text = readFileBytes(path, nullptr, lim);
	Trajectory out;
	LineCursor cur(text);
	std::string_view line;
	TextPos pos{path, 0};
	while (cur.next(line))
	{
		pos.line = cur.lineNumber();
		const auto t = splitTokens(line);
		if (t.empty() || t[0][0] == '#') continue;
		if (t.size() < 4) parseError(pos, "expected 't x y theta', found " + io::counted(t.size(), "field"));
		out.emplace_back(parseDouble(t[0], pos, "t"),
						 mrpt::math::TPose2D(parseDouble(t[1], pos, "x"), parseDouble(t[2], pos, "y"),
											 parseDouble(t[3], pos, "theta")));
	}
	return out;
}

std::vector<std::optional<mrpt::math::TPose2D>> posesAtScans(const LogData& log, const Trajectory& traj,
															 const std::string& source, double maxDt)
{
	const size_t n = log.scans.size();
	std::vector<std::optional<mrpt::math::TPose2D>> out(n);
	bool perScan = traj.size() == n;
	for (size_t i = 0; perScan && i < n; ++i) perScan = std::abs(traj[i].first - log.scans[i].timestamp) <= maxDt;
	if (perScan)
	{
		for (size_t i = 0; i < n; ++i) out[i] = traj[i].second;
		return out;
	}
	const auto earlier = [](const Trajectory::value_type& a, const Trajectory::value_type& b) {
		return a.first < b.first;
	};
	Trajectory sorted = traj;
	std::stable_sort(sorted.begin(), sorted.end(), earlier);
	for (size_t i = 0; i < n; ++i)
	{
		const double t = log.scans[i].timestamp;
		const auto it =
			std::lower_bound(sorted.begin(), sorted.end(), t, [](const auto& p, double v) { return p.first < v; });
		const Trajectory::value_type* best = nullptr;
		for (auto c : {it, it == sorted.begin() ? sorted.end() : std::prev(it)})
			if (c != sorted.end() && std::abs(c->first - t) <= maxDt &&
				(!best || std::abs(c->first - t) < std::abs(best->first - t)))
				best = &*c;
		if (!best) continue;
		const auto [lo, hi] = std::equal_range(sorted.begin(), sorted.end(), *best, earlier);
		for (auto c = lo; c != hi; ++c)
			if (!(c->second == best->second))
			{
				char buf[96];
				std::snprintf(buf, sizeof buf, "%.6f", best->first);
				throw std::runtime_error(
					source + ": " + std::to_string(hi - lo) + " different poses at t = " + buf +
					": scans cannot be matched to poses by time (a file with one pose per scan, in "
					"the log's order, is matched by position)");
			}
		out[i] = best->second;
	}
	return out;
}

void writeTrajectory(const std::string& path, const Trajectory& traj)
{
	AtomicFile f(path);
	std::ostream& os = f.stream();
	char buf[160];
	for (const auto& [t, p] : traj)
	{
		std::snprintf(buf, sizeof buf, "%.6f %.6f %.6f %.6f\n", t, p.x, p.y, p.phi);
		os << buf;
	}
	f.commit();
}

}  // namespace gridvector::io
