// Beyond the paper: the stretches of a vector that lie along door states.
#include "doors/StateSpans.h"

#include "doors/DoorGeometry.h"

#include <algorithm>
#include <cmath>

namespace gridvector::doors
{
using mrpt::math::TPoint2D;

std::vector<std::pair<double, double>> stateSpans(const std::vector<Door>& doors, const GridVector& v,
												  const DoorOptions& opts)
{
	std::vector<std::pair<double, double>> out;
	const double half = v.length() / 2;
	for (const Door& d : doors)
	{
		std::vector<double> states = d.angles;
		if (d.closedInWall) states.push_back(d.closedAngle);
		for (double a : states)
		{
			if (bendDeg(a, v) >= opts.minCornerAngleDeg) continue;
			const TPoint2D tip(d.hinge.x + d.length * std::cos(a), d.hinge.y + d.length * std::sin(a));
			const auto [h, hOff] = alongAndOff(v, d.hinge);
			const auto [t, tOff] = alongAndOff(v, tip);
			if (hOff > kMaxWallOffset || tOff > kMaxWallOffset) continue;
			const double u0 = std::clamp(std::min(h, t) + half, 0.0, v.length());
			const double u1 = std::clamp(std::max(h, t) + half, 0.0, v.length());
			if (u1 > u0) out.emplace_back(u0, u1);
		}
	}
	return out;
}

}  // namespace gridvector::doors
