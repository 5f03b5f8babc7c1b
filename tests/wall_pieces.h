// Test helper: grid vectors holding beam endpoints along a straight or a circular wall.
#pragma once

#include <gridvector/GridVector.h>

#include <cmath>

namespace gvtest
{
/** A vector from s to e with a beam endpoint every `spacing` metres on it. */
inline gridvector::GridVector wallPiece(mrpt::math::TPoint2D s, mrpt::math::TPoint2D e, double spacing = 0.02)
{
	gridvector::GridVector v(s, e, gridvector::GridOptions{});
	const mrpt::math::TPoint2D d = v.direction();
	for (double u = 0.01; u < v.length(); u += spacing) v.addEndpoint({s.x + u * d.x, s.y + u * d.y});
	return v;
}

/** A piece of the circle of radius R centred at (0, R) (a wall bending
 * upwards), from x0 to x1, with beam endpoints every 2 cm along the arc. */
inline gridvector::GridVector arcPiece(double R, double x0, double x1)
{
	auto y = [&](double x) { return R - std::sqrt(R * R - x * x); };
	gridvector::GridVector v({x0, y(x0)}, {x1, y(x1)}, gridvector::GridOptions{});
	for (double x = x0 + 0.01; x < x1; x += 0.02) v.addEndpoint({x, y(x)});
	return v;
}
}  // namespace gvtest
