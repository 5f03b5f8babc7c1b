#include "sim/OdometryNoise.h"

#include <cmath>

namespace gridvector::sim
{
double wrapAngle(double a) { return std::atan2(std::sin(a), std::cos(a)); }

mrpt::math::TPose2D NoisyOdometry::step(const mrpt::math::TPose2D& p)
{
	if (prev_)
	{
		const auto& q = *prev_;
		const double c = std::cos(q.phi), s = std::sin(q.phi);
		double dx = c * (p.x - q.x) + s * (p.y - q.y);
		double dy = -s * (p.x - q.x) + c * (p.y - q.y);
		double dth = wrapAngle(p.phi - q.phi);
		const double d = std::hypot(dx, dy);
		const double k = 1.0 + rng_.gauss(0, opt_.sigmaT);
		dx *= k;
		dy *= k;
		dth += rng_.gauss(0, opt_.sigmaR) + opt_.driftDegPerM * (M_PI / 180.0) * d;
		const double c2 = std::cos(oth_), s2 = std::sin(oth_);
		ox_ += c2 * dx - s2 * dy;
		oy_ += s2 * dx + c2 * dy;
		oth_ = wrapAngle(oth_ + dth);
	}
	prev_ = p;
	return {ox_, oy_, oth_};
}

}  // namespace gridvector::sim
