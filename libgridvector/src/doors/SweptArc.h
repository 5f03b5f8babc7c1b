// Beyond the paper (Sec. 5.4 gives no door model): the arc a door's leaf sweeps about its hinge.
#pragma once

#include "doors/Door.h"

#include <gridvector/GridVector.h>

#include <utility>
#include <vector>

namespace gridvector::doors
{
/** The swept arc is at least this wide from the closed leaf: a hinged door opens to a right
 * angle [deg]. */
constexpr double kMinSweepDeg = 90.0;

/** The smallest arc holding all angles (ascending, at least one): counter-clockwise from
 * `first`, `second` wide [rad]. */
std::pair<double, double> statesArc(const std::vector<double>& angles);

/** The closed leaf's direction: the wall's direction (either way) nearer `mid` [rad]. */
double closedDirection(double mid, const GridVector& wall);

/** `angle` lies in the arc door d's leaf sweeps (within minStateDiffDeg): the smallest arc
 * holding its states; where that spans less than kMinSweepDeg, the arc from the wall's line
 * (the closed leaf, a state or not) through the states, at least kMinSweepDeg wide. */
bool inSweep(const Door& d, const GridVector& wall, double angle, double minStateDiffDeg);

}  // namespace gridvector::doors
