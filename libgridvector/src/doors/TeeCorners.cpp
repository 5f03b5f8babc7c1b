// Beyond the paper: T corners, a hinge inside a wall merged across the doorway.
#include "doors/TeeCorners.h"

#include "doors/DoorGeometry.h"
#include "doors/HingeRule.h"

#include <algorithm>
#include <cmath>

namespace gridvector::doors
{
using mrpt::math::TPoint2D;

void teeCorners(const std::vector<GridVector>& v, size_t s, size_t d, const DoorOptions& opts, std::vector<Corner>& out)
{
	const double half = v[s].length() / 2;
	for (int de = 0; de < 2; ++de)
	{
		const TPoint2D vertex = de ? v[d].end() : v[d].start(), tip = de ? v[d].start() : v[d].end();
		const auto [along, off] = alongAndOff(v[s], vertex);
		if (off > kMaxWallOffset || std::abs(along) >= half) continue;
		Corner c = cornerAt(v, s, d, vertex, tip);
		c.tee = true;
		c.alongWall = bendDeg(c.leafAngle, v[s]) < opts.minCornerAngleDeg;
		const auto [tipAlong, tipOff] = alongAndOff(v[s], tip);
		if (c.alongWall && !(c.dynamicLeaf && tipOff <= kMaxWallOffset)) continue;
		out.push_back(c);
		if (c.alongWall && std::abs(tipAlong) > half)  // past the wall's end: it starts there too
		{
			c.vertex = tipAlong > 0 ? v[s].end() : v[s].start();
			c.leafLength = dist(c.vertex, tip);
			c.tee = false;
			out.push_back(c);
		}
	}
}

bool teeHingeSeenClosed(const std::vector<Corner>& cs, const std::vector<size_t>& group)
{
	const bool allTee = std::all_of(group.begin(), group.end(), [&](size_t k) { return cs[k].tee; });
	return !allTee || std::any_of(group.begin(), group.end(), [&](size_t k) { return cs[k].alongWall; });
}

}  // namespace gridvector::doors
