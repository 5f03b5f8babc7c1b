// Beyond the paper's words: a door's leaf turns about its hinge and from its wall.
#include "doors/LeafTurns.h"

#include "doors/DoorGeometry.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace gridvector::doors
{
bool statesOnOneLine(const std::vector<double>& angles, double minStateDiffDeg)
{
	const double minDiff = radians(minStateDiffDeg);
	return std::all_of(angles.begin(), angles.end(), [&](double a) {
		const double turn = std::abs(mrpt::math::wrapToPi(a - angles[0]));
		return std::min(turn, M_PI - turn) < minDiff;
	});
}

bool turnsFromWall(const GridVector& wall, const Door& d)
{
	return std::any_of(d.angles.begin(), d.angles.end(), [&](double a) { return bendDeg(a, wall) >= kMinOpenDeg; });
}

}  // namespace gridvector::doors
