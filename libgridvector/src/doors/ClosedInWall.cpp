// Beyond the paper: the closed leaf inside a wall merged across the doorway.
#include "doors/ClosedInWall.h"

#include "doors/DoorGeometry.h"
#include "doors/SweptArc.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace gridvector::doors
{
void closedInWall(const std::vector<GridVector>& v, Door& d, const DoorOptions& opts)
{
	const GridVector& w = v[d.wall];
	if (w.length() <= opts.maxDoorLength) return;
	const auto [start, width] = statesArc(d.angles);
	const double closed = closedDirection(start + width / 2, w), minDiff = radians(opts.minStateDiffDeg);
	if (std::any_of(d.angles.begin(), d.angles.end(),
					[&](double a) { return std::abs(mrpt::math::wrapToPi(a - closed)) < minDiff; }))
		return;  // the closed state is a state: stateSpans has it
	const auto [along, off] = alongAndOff(w, d.hinge);
	const double ahead = std::cos(closed - w.psi()) > 0 ? along : -along;  // the hinge's place in the closed direction
	if (off > kMaxWallOffset || std::abs(along) >= w.length() / 2 ||
		w.length() / 2 - ahead < d.length - opts.maxLengthDiff)
		return;
	d.closedInWall = true;
	d.closedAngle = closed;
}

}  // namespace gridvector::doors
