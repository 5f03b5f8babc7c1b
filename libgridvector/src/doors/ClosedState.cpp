// Beyond the paper: the closed state, a dynamic leaf on its wall's line.
#include "doors/ClosedState.h"

#include "doors/DoorGeometry.h"

#include <cmath>

namespace gridvector::doors
{
namespace
{
/** On the wall's line and pointing away from the wall (not lying along it). */
bool collinearBeyond(const GridVector& wall, const Corner& c, double maxGap)
{
	const auto [tipAlong, off] = alongAndOff(wall, c.tip);
	return off <= maxGap && std::abs(tipAlong) > std::abs(alongAndOff(wall, c.vertex).first);
}
}  // namespace

bool closedStateCorner(const GridVector& wall, Corner& c, const DoorOptions& opts)
{
	if (!(c.dynamicLeaf && collinearBeyond(wall, c, opts.maxCornerGap))) return false;
	c.alongWall = true;
	if (std::abs(alongAndOff(wall, c.vertex).first) < wall.length() / 2)  // the leaf overlaps the wall
	{
		c.vertex = alongAndOff(wall, c.tip).first > 0 ? wall.end() : wall.start();  // from the wall's end
		c.leafLength = dist(c.vertex, c.tip);
	}
	return true;
}

}  // namespace gridvector::doors
