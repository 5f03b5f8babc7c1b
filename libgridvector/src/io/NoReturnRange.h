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
/** A code's readings jitter this far about it (51.06-51.16 m, 51.14-51.25 m in two CARMEN logs) [m]. */
constexpr double kNoReturnJitter = 0.25;
/** A code outnumbers the readings above it and in the metre below it this many times (real surfaces thin
 * out with range: 14-190x for the codes seen, ~1x for the far tail of real readings). */
constexpr double kNoReturnSpike = 10;
/** A scanner's codes lie within this of each other (50.00 and 51.15 m in one log) [m]. */
constexpr double kNoReturnCodeSpan = 2.0;

/** The lowest no-return code of the log: from the largest reading down, a value that at least `minShare`
 * of the scans and at least `minScans` of them contain exactly (a saturation value, not a wall: in a
 * 20-scan log the farthest corner, seen once, is already 5 % of the scans), whose readings within
 * kNoReturnJitter outnumber kNoReturnSpike-fold those above it and those in the metre below; its
 * window's smallest value held as often. Further codes within kNoReturnCodeSpan below the first are
 * found too. nullopt when there is none: the declared maxima stand. */
std::optional<double> saturationRange(const LogData& log, double minShare = kNoReturnMinShare,
									  size_t minScans = kNoReturnMinScans);

/** Every scan's maxRange becomes `range`; readings at or beyond it are invalid. */
void applyMaxRange(LogData& log, double range);
}  // namespace gridvector::io
