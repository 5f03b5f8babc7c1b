// Beyond the paper's words (Fig. 10's leaf turns about its hinge, away from its wall): hinges
// whose states show no turning leaf are no door.
#pragma once

#include "doors/Door.h"

#include <gridvector/GridVector.h>

#include <vector>

namespace gridvector::doors
{
/** A door has a state this far or farther from its wall's line (a leaf seen open); the wall's
 * own continuation seen dynamic in kinked pieces (real logs: about 15 deg) turns less [deg]. */
constexpr double kMinOpenDeg = 30.0;

/** All states on one straight line through the vertex (either way, within minStateDiffDeg):
 * a line seen dynamic (grazing rays, a moved object) cut where a static vector ends on it. */
bool statesOnOneLine(const std::vector<double>& angles, double minStateDiffDeg);

/** One state of d at least kMinOpenDeg from its wall's line (either way). */
bool turnsFromWall(const GridVector& wall, const Door& d);

}  // namespace gridvector::doors
