// Sec. 5.4: the plane geometry the door rules share (distances, positions along a wall's line).
#pragma once

#include <gridvector/GridVector.h>
#include "map/VectorIndex.h"

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace gridvector::doors
{
/** A point this close to a wall's line lies on it (a T corner's vertex, a hinge, a state's tip):
 * one grid cell, what a merged wall's line is known to [m]. */
constexpr double kMaxWallOffset = 0.10;

inline double dist(const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b)
{
	return std::hypot(a.x - b.x, a.y - b.y);
}

/** The box of a vector's two ends grown by `margin`: a point farther than `margin` from the segment lies outside
 * (a cheap test before the rules' distances, which it never changes). */
inline Box2D endBox(const GridVector& v, double margin)
{
	return Box2D{std::min(v.start().x, v.end().x), std::min(v.start().y, v.end().y), std::max(v.start().x, v.end().x),
				 std::max(v.start().y, v.end().y)}
		.expanded(margin);
}

/** Could an end of `v` lie in the box? */
inline bool holdsAnEndOf(const Box2D& b, const GridVector& v)
{
	return b.holds(v.start().x, v.start().y) || b.holds(v.end().x, v.end().y);
}

inline double radians(double deg) { return deg * M_PI / 180; }

/** Position of p along the wall from its centre, and its distance from the wall's line. */
inline std::pair<double, double> alongAndOff(const GridVector& wall, const mrpt::math::TPoint2D& p)
{
	const mrpt::math::TPoint2D d = wall.direction(), c = wall.centre();
	return {(p.x - c.x) * d.x + (p.y - c.y) * d.y, std::abs((p.x - c.x) * d.y - (p.y - c.y) * d.x)};
}

/** How far a direction turns from the wall's line, either way [deg, 0..90]. */
inline double bendDeg(double angle, const GridVector& wall)
{
	const double turn = std::abs(mrpt::math::wrapToPi(angle - wall.psi()));
	return std::min(turn, M_PI - turn) * 180 / M_PI;
}

}  // namespace gridvector::doors
