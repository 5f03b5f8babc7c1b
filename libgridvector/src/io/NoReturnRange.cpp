// Sensor max range of a CARMEN log from its readings (the "no return" value, see NoReturnRange.h).
#include "io/NoReturnRange.h"

#include <algorithm>

namespace gridvector::io
{
std::optional<double> saturationRange(const LogData& log, double minShare, size_t minScans)
{
	float top = 0;
	for (const auto& r : log.scans)
		for (size_t k = 0; k < r.scan->getScanSize(); k++)
			if (r.scan->getScanRangeValidity(k)) top = std::max(top, r.scan->getScanRange(k));
	if (top <= 0) return std::nullopt;
	size_t withTop = 0;
	for (const auto& r : log.scans)
		for (size_t k = 0; k < r.scan->getScanSize(); k++)
			if (r.scan->getScanRangeValidity(k) && r.scan->getScanRange(k) == top)
			{
				withTop++;
				break;
			}
	if (withTop < minScans || double(withTop) < minShare * double(log.scans.size())) return std::nullopt;
	return double(top);
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
