#include "sim/OdometryNoise.h"
#include "sim/RobotPath.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridvector::sim
{
std::vector<mrpt::math::TPose2D> followRoute(const mrpt::math::TPose2D& start, const std::vector<Vec2>& route, int laps,
											 const MotionOptions& m, size_t maxSteps)
{
	if (route.empty()) throw std::invalid_argument("empty robot route");
	if (m.speed <= 0 || m.turnRateDeg <= 0 || m.dt <= 0)
		throw std::invalid_argument("speed, turn rate and dt must be > 0");
	const double maxTurn = m.turnRateDeg * M_PI / 180.0 * m.dt, maxMove = m.speed * m.dt;
	std::vector<mrpt::math::TPose2D> out{start};
	mrpt::math::TPose2D p = start;
	size_t target = 0;
	int lap = 0;
	size_t idle = 0;  // waypoints reached in a row without moving
	const auto done = [&] { return maxSteps ? out.size() >= maxSteps : lap >= laps; };
	while (!done())
	{
		const Vec2 d = route[target] - Vec2(p.x, p.y);
		const double dist = d.norm();
		if (dist < 1e-3)
		{
			if (++idle > route.size() + 1) throw std::invalid_argument("robot route has zero length");
			if (++target == route.size()) target = 0, lap++;
			continue;
		}
		idle = 0;
		const double heading = std::atan2(d.y, d.x), err = wrapAngle(heading - p.phi);
		if (std::abs(err) > maxTurn)
			p.phi = wrapAngle(p.phi + std::copysign(maxTurn, err));  // turn on the spot
		else
		{
			p.phi = heading;
			const double step = std::min(maxMove, dist);
			p.x += step * std::cos(p.phi);
			p.y += step * std::sin(p.phi);
			if (step == dist) p.x = route[target].x, p.y = route[target].y;
		}
		out.push_back(p);
	}
	return out;
}

}  // namespace gridvector::sim
