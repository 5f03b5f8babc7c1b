// Beyond the paper: states joining a found door from its hinge.
#include "doors/JoinStates.h"

#include "doors/DoorGeometry.h"
#include "doors/SweptArc.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace gridvector::doors
{
using mrpt::math::TPoint2D;

void addLeaf(Door& d, size_t k, double a, double r, std::vector<bool>& taken, const DoorOptions& opts)
{
	d.leaves.push_back(k);
	taken[k] = true;
	const double minDiff = radians(opts.minStateDiffDeg);
	if (r >= d.length - opts.maxLengthDiff && std::all_of(d.angles.begin(), d.angles.end(), [&](double b) {
			return std::abs(mrpt::math::wrapToPi(a - b)) >= minDiff;
		}))
	{
		d.angles.push_back(a);
		std::sort(d.angles.begin(), d.angles.end());
	}
}

void joinStates(const std::vector<GridVector>& v, Door& d, double reach, std::vector<bool>& taken,
				const DoorOptions& opts)
{
	for (size_t k = 0; k < v.size(); ++k)
	{
		if (taken[k] || v[k].length() > reach) continue;
		for (int e = 0; e < 2; ++e)
		{
			const TPoint2D vertex = e ? v[k].end() : v[k].start(), tip = e ? v[k].start() : v[k].end();
			const double r = dist(tip, d.hinge);
			if (dist(vertex, d.hinge) > opts.maxVertexDistance || r > reach || r <= opts.maxVertexDistance) continue;
			const double a = std::atan2(tip.y - d.hinge.y, tip.x - d.hinge.x);
			if (!inSweep(d, v[d.wall], a, opts.minStateDiffDeg)) continue;
			addLeaf(d, k, a, r, taken, opts);
			break;
		}
	}
}

}  // namespace gridvector::doors
