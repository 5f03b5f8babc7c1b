// The range at which a log's laser reports "no return", when the log declares a larger
// maximum than its sensor has (mkbench.py declares 81 m for every log; ACES's scanner
// saturates at exactly 50 m, 620 readings).
#pragma once
#include <gridvector/io/LogReader.h>

#include <cstddef>
#include <optional>

namespace gridvector::io
{
constexpr double kNoReturnMinShare = 0.01;  //!< saturationRange: share of the scans holding the value
constexpr size_t kNoReturnMinScans = 10;  //!< ... and number of them

/** The largest valid reading of the log, when at least `minShare` of the scans and at least
 * `minScans` of them contain it exactly (a saturation value, not a wall: in a 20-scan log the
 * farthest corner, seen once, is already 5 % of the scans); nullopt when the declared maxima stand. */
std::optional<double> saturationRange(const LogData& log, double minShare = kNoReturnMinShare,
									  size_t minScans = kNoReturnMinScans);

/** Every scan's maxRange becomes `range`; readings at or beyond it are invalid. */
void applyMaxRange(LogData& log, double range);
}  // namespace gridvector::io
