// Beyond the paper: the swept arc of a door's leaf.
#include "doors/SweptArc.h"

#include "doors/DoorGeometry.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace gridvector::doors
{
std::pair<double, double> statesArc(const std::vector<double>& as)
{
	double gap = -1;
	size_t from = 0;
	for (size_t k = 0; k < as.size(); ++k)
	{
		const double g = k + 1 < as.size() ? as[k + 1] - as[k] : as[0] + 2 * M_PI - as[k];
		if (g > gap) gap = g, from = k;
	}
	return {as[(from + 1) % as.size()], 2 * M_PI - gap};
}

double closedDirection(double mid, const GridVector& wall)
{
	double closed = wall.psi();
	if (std::abs(mrpt::math::wrapToPi(closed + M_PI - mid)) < std::abs(mrpt::math::wrapToPi(closed - mid)))
		closed += M_PI;
	return closed;
}

bool inSweep(const Door& d, const GridVector& wall, double angle, double minStateDiffDeg)
{
	auto [start, width] = statesArc(d.angles);  // counter-clockwise from start
	const double minSweep = M_PI * (kMinSweepDeg / 180);  // exactly M_PI / 2 for 90 deg
	if (width < minSweep)
	{
		// the closed leaf lies along the wall, in the wall's direction nearer the states (a state
		// or not: a closed leaf inside a wall merged across the doorway is none); the arc runs
		// from there through the states, at least minSweep wide
		const double mid = start + width / 2, closed = closedDirection(mid, wall);
		if (mrpt::math::wrapToPi(mid - closed) >= 0)  // states counter-clockwise from the closed leaf
			width = std::max(minSweep, mrpt::math::wrapTo2Pi(start + width - closed)), start = closed;
		else
			width = std::max(minSweep, mrpt::math::wrapTo2Pi(closed - start)), start = closed - width;
	}
	const double rel = mrpt::math::wrapTo2Pi(angle - start), tol = radians(minStateDiffDeg);
	return rel <= width + tol || rel >= 2 * M_PI - tol;
}

}  // namespace gridvector::doors
