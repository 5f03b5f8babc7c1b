#include <gridvector/DoorDetector.h>

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace gridvector
{
using mrpt::math::TPoint2D;

namespace
{
double dist(const TPoint2D& a, const TPoint2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }
}  // namespace

DoorDetector::DoorDetector(const DoorOptions& opts) : opts_(opts) {}

// Fig. 10: a corner is built by a static vector (the wall) and a door candidate meeting at an end.
// The candidate is dynamic; a static one of door length counts too, as a state that Eq. 6 could
// not see change (an open leaf nobody looked through after it closed) — detect() only keeps doors
// with a dynamic state. A dynamic candidate may continue the wall's line (a closed leaf).
std::vector<Corner> DoorDetector::corners(const std::vector<GridVector>& v) const
{
	std::vector<Corner> out;
	for (size_t d = 0; d < v.size(); ++d)
	{
		const double len = v[d].length();
		if (len < opts_.minDoorLength - opts_.maxLengthDiff || len > opts_.maxDoorLength + opts_.maxLengthDiff)
			continue;
		const bool dynamicLeaf = v[d].state == VectorState::Dynamic;
		for (size_t s = 0; s < v.size(); ++s)
		{
			if (s == d || v[s].state != VectorState::Static) continue;
			double best = opts_.maxCornerGap;
			int end = -1;
			for (int de = 0; de < 2; ++de)
				for (const TPoint2D& se : {v[s].start(), v[s].end()})
				{
					const double g = dist(de ? v[d].end() : v[d].start(), se);
					if (g <= best) best = g, end = de;
				}
			if (end < 0) continue;
			Corner c;
			c.wall = s;
			c.leaf = d;
			c.dynamicLeaf = dynamicLeaf;
			c.vertex = end ? v[d].end() : v[d].start();
			const TPoint2D tip = end ? v[d].start() : v[d].end();
			c.leafAngle = std::atan2(tip.y - c.vertex.y, tip.x - c.vertex.x);
			c.leafLength = len;
			const double turn = std::abs(mrpt::math::wrapToPi(c.leafAngle - v[s].psi()));
			const double bend = std::min(turn, M_PI - turn) * 180 / M_PI;
			if (bend < opts_.minCornerAngleDeg && !(dynamicLeaf && collinearBeyond(v[s], c.vertex, tip)))
				continue;
			out.push_back(c);
		}
	}
	return out;
}

// A closed leaf: on the wall's line, pointing away from the wall (not lying along it).
bool DoorDetector::collinearBeyond(const GridVector& wall, const TPoint2D& vertex, const TPoint2D& tip) const
{
	const TPoint2D d = wall.direction(), c = wall.centre();
	auto along = [&](const TPoint2D& p) { return (p.x - c.x) * d.x + (p.y - c.y) * d.y; };
	const double off = std::abs((tip.x - c.x) * d.y - (tip.y - c.y) * d.x);
	return off <= opts_.maxCornerGap && std::abs(along(tip)) > std::abs(along(vertex));
}

bool DoorDetector::sameDoor(const Corner& a, const Corner& b) const
{
	return a.wall == b.wall && dist(a.vertex, b.vertex) <= opts_.maxVertexDistance &&
		   std::abs(a.leafLength - b.leafLength) <= opts_.maxLengthDiff;
}

// Sec. 5.4: corners sharing the wall, close vertices, equal leaf lengths -> hinge + states.
std::vector<Door> DoorDetector::detect(const std::vector<GridVector>& v) const
{
	auto cs = corners(v);
	// the longest wall first: a static open leaf can also act as a "wall" of the closed state
	std::stable_sort(cs.begin(), cs.end(),
					 [&](const Corner& a, const Corner& b) { return v[a.wall].length() > v[b.wall].length(); });
	std::vector<Door> doors;
	std::vector<bool> used(cs.size(), false);
	const double minDiff = opts_.minStateDiffDeg * M_PI / 180;
	for (size_t i = 0; i < cs.size(); ++i)
	{
		if (used[i]) continue;
		std::vector<size_t> group{i};
		for (size_t j = i + 1; j < cs.size(); ++j)
			if (!used[j] && sameDoor(cs[i], cs[j])) group.push_back(j);
		// distinct states: leaf directions at least min_state_diff apart
		std::vector<double> angles;
		for (size_t k : group)
		{
			const bool distinct = std::all_of(angles.begin(), angles.end(), [&](double a) {
				return std::abs(mrpt::math::wrapToPi(a - cs[k].leafAngle)) >= minDiff;
			});
			if (distinct) angles.push_back(cs[k].leafAngle);
		}
		// Sec. 5.4: the door candidate is a dynamic vector; static states only join one
		const bool anyDynamic = std::any_of(group.begin(), group.end(), [&](size_t k) { return cs[k].dynamicLeaf; });
		if (angles.size() < 2 || !anyDynamic) continue;
		Door d;
		d.wall = cs[i].wall;
		double len = 0;
		for (size_t k : group)
		{
			used[k] = true;
			d.hinge.x += cs[k].vertex.x / group.size();
			d.hinge.y += cs[k].vertex.y / group.size();
			len += cs[k].leafLength;
			d.leaves.push_back(cs[k].leaf);
		}
		d.length = len / group.size();
		if (d.length < opts_.minDoorLength || d.length > opts_.maxDoorLength) continue;
		std::sort(angles.begin(), angles.end());
		d.angles = angles;
		// one hinge is one door, even if several walls/leaf copies meet there
		const bool dup = std::any_of(doors.begin(), doors.end(), [&](const Door& o) {
			return dist(o.hinge, d.hinge) <= opts_.maxVertexDistance;
		});
		if (!dup) doors.push_back(d);
	}
	return doors;
}

}  // namespace gridvector
