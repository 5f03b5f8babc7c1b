// The range at which a log's laser reports "no return", when the log declares a larger
// maximum than its sensor has (mkbench.py declares 81 m for every log; ACES's scanner
// saturates at exactly 50 m, 620 readings).
#pragma once
#include <gridvector/io/LogReader.h>

#include <optional>

namespace gridvector::io
{
/** The largest valid reading of the log, when at least `minShare` of the scans contain it
 * exactly (a saturation value, not a wall); nullopt when the declared maxima stand. */
std::optional<double> saturationRange(const LogData& log, double minShare = 0.01);

/** Every scan's maxRange becomes `range`; readings at or beyond it are invalid. */
void applyMaxRange(LogData& log, double range);
}  // namespace gridvector::io
