// Sensor max range of a CARMEN log from its readings (the "no return" value, see NoReturnRange.h).
#include "io/NoReturnRange.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace gridvector::io
{
namespace
{
/** Every valid reading ascending (`beams`), and each distinct value with the number of scans holding it. */
struct Readings
{
	std::vector<float> beams;
	std::vector<std::pair<float, uint32_t>> held;

	explicit Readings(const LogData& log)
	{
		std::vector<float> perScan, all;
		for (const auto& r : log.scans)
		{
			perScan.clear();
			for (size_t k = 0; k < r.scan->getScanSize(); k++)
				if (r.scan->getScanRangeValidity(k)) perScan.push_back(r.scan->getScanRange(k));
			beams.insert(beams.end(), perScan.begin(), perScan.end());
			std::sort(perScan.begin(), perScan.end());
			perScan.erase(std::unique(perScan.begin(), perScan.end()), perScan.end());
			all.insert(all.end(), perScan.begin(), perScan.end());
		}
		std::sort(beams.begin(), beams.end());
		std::sort(all.begin(), all.end());
		for (size_t a = 0, b = 0; a < all.size(); a = b)
		{
			while (b < all.size() && all[b] == all[a]) ++b;
			held.emplace_back(all[a], uint32_t(b - a));
		}
	}
	/** Readings in [lo, hi). */
	double count(double lo, double hi) const
	{
		if (hi <= lo) return 0;
		auto at = [&](double x) { return std::lower_bound(beams.begin(), beams.end(), float(x)) - beams.begin(); };
		return double(at(hi) - at(lo));
	}
};
}  // namespace

// From the largest reading down: a value held by enough scans whose window outnumbers kNoReturnSpike-fold
// the readings above it and in the metre below it is a no-return code; the smallest value of its window held
// as often is the code's lowest. Codes below the first are looked for within kNoReturnCodeSpan.
std::optional<double> saturationRange(const LogData& log, double minShare, size_t minScans)
{
	const Readings rd(log);
	const double need = std::max(double(minScans), minShare * double(log.scans.size()));
	double limit = std::numeric_limits<double>::infinity(), first = limit;
	bool found = false;
	for (size_t k = rd.held.size(); k-- > 0;)
	{
		const double v = rd.held[k].first;
		if (v >= limit || double(rd.held[k].second) < need) continue;
		if (found && v < first - kNoReturnCodeSpan) break;  // far below the codes found: real readings
		const double lo = v - kNoReturnJitter, hi = std::min(limit, v + kNoReturnJitter);
		const double inWindow = rd.count(lo, hi);
		if (inWindow < kNoReturnSpike * std::max(rd.count(hi, limit), rd.count(lo - 1.0, lo))) break;  // not a spike
		size_t j = k;
		while (j > 0 && rd.held[j - 1].first >= lo) --j;
		while (double(rd.held[j].second) < need) ++j;  // ends at k at the latest
		limit = rd.held[j].first;
		first = std::min(first, v);
		found = true;
		k = j;
	}
	if (!found) return std::nullopt;
	return limit;
}

void applyMaxRange(LogData& log, double range)
{
	for (auto& r : log.scans)
	{
		auto& s = *r.scan;
		s.maxRange = float(range);
		for (size_t k = 0; k < s.getScanSize(); k++)
			if (s.getScanRange(k) >= float(range)) s.setScanRangeValidity(k, false);
	}
}
}  // namespace gridvector::io
