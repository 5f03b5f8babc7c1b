// Sec. 5.4, Fig. 10: doors from corners of a static and a dynamic vector sharing a hinge.
#include "doors/HingeRule.h"

#include "doors/DoorGeometry.h"

#include <algorithm>
#include <cmath>

namespace gridvector::doors
{
using mrpt::math::TPoint2D;

Corner cornerAt(const std::vector<GridVector>& v, size_t s, size_t d, const TPoint2D& vertex, const TPoint2D& tip)
{
	Corner c;
	c.wall = s;
	c.leaf = d;
	c.dynamicLeaf = v[d].state == VectorState::Dynamic;
	c.vertex = vertex;
	c.tip = tip;
	c.leafAngle = std::atan2(tip.y - vertex.y, tip.x - vertex.x);
	c.leafLength = v[d].length();
	return c;
}

bool HingeRule::isCandidate(const GridVector& leaf) const
{
	const double len = leaf.length();
	return !(len < opts_.minDoorLength - opts_.maxLengthDiff || len > opts_.maxDoorLength + opts_.maxLengthDiff);
}

// Sec. 5.4: "the corner is always built up by a static vector and a dynamic vector"
std::optional<Corner> HingeRule::meetingEnds(const std::vector<GridVector>& v, size_t s, size_t d) const
{
	double best = opts_.maxCornerGap;
	int end = -1;
	for (int de = 0; de < 2; ++de)
		for (const TPoint2D& se : {v[s].start(), v[s].end()})
		{
			const double g = dist(de ? v[d].end() : v[d].start(), se);
			if (g <= best) best = g, end = de;
		}
	if (end < 0) return std::nullopt;
	return cornerAt(v, s, d, end ? v[d].end() : v[d].start(), end ? v[d].start() : v[d].end());
}

bool HingeRule::turns(const Corner& c, const GridVector& wall) const
{
	return bendDeg(c.leafAngle, wall) >= opts_.minCornerAngleDeg;
}

// Sec. 5.4: "two corners share the same static vector, while their vertices are close to each
// other, and their dynamic vectors have the same length"
bool HingeRule::sameDoor(const Corner& a, const Corner& b) const
{
	return a.wall == b.wall && dist(a.vertex, b.vertex) <= opts_.maxVertexDistance &&
		   std::abs(a.leafLength - b.leafLength) <= opts_.maxLengthDiff;
}

// Sec. 5.4: "the dynamic vectors represent different open states of the door"
std::vector<double> HingeRule::distinctStates(const std::vector<Corner>& cs, const std::vector<size_t>& group) const
{
	const double minDiff = radians(opts_.minStateDiffDeg);
	std::vector<double> angles;
	for (size_t k : group)
	{
		const bool distinct = std::all_of(angles.begin(), angles.end(), [&](double a) {
			return std::abs(mrpt::math::wrapToPi(a - cs[k].leafAngle)) >= minDiff;
		});
		if (distinct) angles.push_back(cs[k].leafAngle);
	}
	return angles;
}

// Sec. 5.4: "the dynamic one is considered as a door candidate"; two corners make a hinge
bool HingeRule::isHinge(const std::vector<Corner>& cs, const std::vector<size_t>& group,
						const std::vector<double>& angles) const
{
	const bool anyDynamic = std::any_of(group.begin(), group.end(), [&](size_t k) { return cs[k].dynamicLeaf; });
	return angles.size() >= 2 && anyDynamic;
}

// Sec. 5.4: "the vertex can be regarded as the hinge of a door"
Door HingeRule::hingeOf(const std::vector<Corner>& cs, const std::vector<size_t>& group) const
{
	Door d;
	d.wall = cs[group[0]].wall;
	double len = 0;
	for (size_t k : group)
	{
		d.hinge.x += cs[k].vertex.x / group.size();
		d.hinge.y += cs[k].vertex.y / group.size();
		len += cs[k].leafLength;
		d.leaves.push_back(cs[k].leaf);
	}
	d.length = len / group.size();
	return d;
}

bool HingeRule::hasDoorLength(const Door& d) const
{
	return !(d.length < opts_.minDoorLength || d.length > opts_.maxDoorLength);
}

}  // namespace gridvector::doors
