// Beyond the paper: a short static "wall" of a door is one of its states.
#include "doors/WallAsState.h"

#include "doors/DoorGeometry.h"
#include "doors/JoinStates.h"
#include "doors/SweptArc.h"

#include <cmath>

namespace gridvector::doors
{
using mrpt::math::TPoint2D;

void wallAsState(const std::vector<GridVector>& v, Door& d, double reach, std::vector<bool>& taken,
				 const DoorOptions& opts)
{
	const size_t shortWall = d.wall;
	const GridVector& w = v[shortWall];
	if (w.length() > reach || taken[shortWall]) return;
	double best = opts.maxDoorLength;
	for (size_t s = 0; s < v.size(); ++s)
	{
		if (v[s].state != VectorState::Static || taken[s] || v[s].length() <= best) continue;
		const auto [along, off] = alongAndOff(v[s], d.hinge);
		if (off <= kMaxWallOffset && std::abs(along) <= v[s].length() / 2 + opts.maxCornerGap)
			best = v[s].length(), d.wall = s;
	}
	if (d.wall == shortWall) return;
	const bool startAtHinge = dist(w.start(), d.hinge) <= dist(w.end(), d.hinge);
	const TPoint2D vertex = startAtHinge ? w.start() : w.end(), tip = startAtHinge ? w.end() : w.start();
	const double a = std::atan2(tip.y - d.hinge.y, tip.x - d.hinge.x);
	if (dist(vertex, d.hinge) > opts.maxVertexDistance || !inSweep(d, v[d.wall], a, opts.minStateDiffDeg)) return;
	addLeaf(d, shortWall, a, dist(tip, d.hinge), taken, opts);
}

}  // namespace gridvector::doors
