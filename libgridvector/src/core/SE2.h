// Pose compounding (+) and its inverse on TPose2D (Lu & Milios 1997a), header-only.
#pragma once

#include <mrpt/math/TPose2D.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace gridvector::se2
{
/** a (+) b: b expressed in a's frame, moved to the world. */
inline mrpt::math::TPose2D compose(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	return {a.x + c * b.x - s * b.y, a.y + s * b.x + c * b.y, mrpt::math::wrapToPi(a.phi + b.phi)};
}

/** a^-1 (+) b: the pose of b seen from a. */
inline mrpt::math::TPose2D relative(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	const double dx = b.x - a.x, dy = b.y - a.y;
	return {c * dx + s * dy, -s * dx + c * dy, mrpt::math::wrapToPi(b.phi - a.phi)};
}

inline double distance(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b)
{
	return std::hypot(a.x - b.x, a.y - b.y);
}

}  // namespace gridvector::se2
