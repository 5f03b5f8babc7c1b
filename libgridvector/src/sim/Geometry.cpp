#include "sim/Geometry.h"

#include <algorithm>

namespace gridvector::sim
{
double rayToSegment(const Vec2& o, const Vec2& d, const Segment& s)
{
	const Vec2 e = s.b - s.a;
	const double den = d.cross(e);
	if (std::abs(den) < 1e-12) return kNoHit;  // parallel
	const Vec2 w = s.a - o;
	const double t = w.cross(e) / den;  // along the ray
	const double u = w.cross(d) / den;  // along the segment
	if (t < 0 || u < 0 || u > 1) return kNoHit;
	return t;
}

double rayToCircle(const Vec2& o, const Vec2& d, const Circle& c)
{
	const Vec2 m = o - c.c;
	const double b = m.dot(d);
	const double cc = m.dot(m) - c.r * c.r;
	if (cc <= 0) return kNoHit;  // inside
	const double disc = b * b - cc;
	if (disc < 0 || b > 0) return kNoHit;
	return -b - std::sqrt(disc);
}

double projectOnSegment(const Vec2& p, const Segment& s)
{
	const Vec2 e = s.b - s.a;
	const double l2 = e.dot(e);
	if (l2 <= 0) return 0;
	return std::clamp((p - s.a).dot(e) / l2, 0.0, 1.0);
}

double distanceToSegment(const Vec2& p, const Segment& s) { return (p - s.at(projectOnSegment(p, s))).norm(); }

double segmentDistance(const Segment& s, const Segment& t)
{
	const Vec2 e = s.b - s.a, f = t.b - t.a;
	const double d1 = e.cross(t.a - s.a), d2 = e.cross(t.b - s.a);
	const double d3 = f.cross(s.a - t.a), d4 = f.cross(s.b - t.a);
	if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0;
	return std::min(
		{distanceToSegment(s.a, t), distanceToSegment(s.b, t), distanceToSegment(t.a, s), distanceToSegment(t.b, s)});
}

}  // namespace gridvector::sim
