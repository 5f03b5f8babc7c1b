#pragma once
// Incidence of the beams that saw a vector (mstep.register_min_incidence_deg; beyond the paper).

#include "mstep/VectorMatcher.h"

#include <vector>

namespace gridvector
{
/** The largest angle [rad] under which a beam from the scan frame's origin (the sensor) meets the vector's line
 * at one of its points: at the point nearest the origin; pi/2 when that is the foot of the perpendicular. */
double largestIncidence(const MatchSegment& v);

/** Per scan, the vectors some beam saw under at least `minDeg` degrees of incidence (the others removed). */
std::vector<std::vector<MatchSegment>> facingVectors(const std::vector<std::vector<MatchSegment>>& scans, double minDeg);
}  // namespace gridvector
