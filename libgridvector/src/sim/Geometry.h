// 2D primitives for the simulator and the evaluator: points, segments, circles,
// ray casting and distances.
#pragma once

#include <cmath>
#include <limits>

namespace gridvector::sim
{
struct Vec2
{
	double x = 0, y = 0;
	Vec2() = default;
	Vec2(double x_, double y_) : x(x_), y(y_) {}
	Vec2 operator+(const Vec2& o) const { return {x + o.x, y + o.y}; }
	Vec2 operator-(const Vec2& o) const { return {x - o.x, y - o.y}; }
	Vec2 operator*(double s) const { return {x * s, y * s}; }
	double dot(const Vec2& o) const { return x * o.x + y * o.y; }
	double cross(const Vec2& o) const { return x * o.y - y * o.x; }
	double norm() const { return std::hypot(x, y); }
	static Vec2 polar(double r, double a) { return {r * std::cos(a), r * std::sin(a)}; }
};

struct Segment
{
	Vec2 a, b;
	Segment() = default;
	Segment(Vec2 a_, Vec2 b_) : a(a_), b(b_) {}
	Segment(double x1, double y1, double x2, double y2) : a(x1, y1), b(x2, y2) {}
	double length() const { return (b - a).norm(); }
	Vec2 at(double f) const { return a + (b - a) * f; }  //!< f in [0,1]
};

struct Circle
{
	Vec2 c;
	double r = 0;
};

constexpr double kNoHit = std::numeric_limits<double>::infinity();

/** Distance t >= 0 along the ray o + t*d (|d| = 1) to the segment, or kNoHit. */
double rayToSegment(const Vec2& o, const Vec2& d, const Segment& s);
/** Distance to the first crossing of the circle's boundary from outside, or kNoHit
 * (also when o is inside the circle). */
double rayToCircle(const Vec2& o, const Vec2& d, const Circle& c);
/** Euclidean distance from p to the closest point of s. */
double distanceToSegment(const Vec2& p, const Segment& s);
/** Smallest distance between two segments (0 if they cross). */
double segmentDistance(const Segment& s, const Segment& t);
/** Position of p's projection on s as a fraction of its length, clamped to [0,1]. */
double projectOnSegment(const Vec2& p, const Segment& s);

}  // namespace gridvector::sim
