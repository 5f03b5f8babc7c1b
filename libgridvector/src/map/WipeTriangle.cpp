#include "map/WipeTriangle.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridvector
{
using mrpt::math::TPoint2D;

// Fig. 2: the wipe triangle of v_j from the sensor at x_q.
WipeTriangle::WipeTriangle(const TPoint2D& sensor, const TPoint2D& start, const TPoint2D& end, double hitBand,
						   double beamsPerRadian)
	: o_(sensor), beams_(beamsPerRadian)
{
	const double ax = start.x - sensor.x, ay = start.y - sensor.y;
	const double bx = end.x - sensor.x, by = end.y - sensor.y;
	const double len = std::hypot(end.x - start.x, end.y - start.y);
	const double det = ax * by - ay * bx;
	// distance of O to the far edge's line: |det| / |E - S| (twice the area over the base)
	const double dO = len > 0 ? std::abs(det) / len : 0.0;
	// degenerate also when a point is not finite (NaN fails every comparison: each cell would be "Visited")
	if (!(len >= 1e-9 && dO >= 1e-6 && std::isfinite(det) && std::isfinite(hitBand))) return;
	degenerate_ = false;
	edge_ = TPoint2D((end.x - start.x) / len, (end.y - start.y) / len);
	i00_ = by / det, i01_ = -bx / det;
	i10_ = -ay / det, i11_ = ax / det;
	sHit_ = 1.0 - hitBand / dO;
	sMax_ = 1.0 + hitBand / dO;
	// part c's box along SE; an end cuts parts b and c only where the triangle stays inside it
	const double uS = along(start.x, start.y), uE = along(end.x, end.y);
	hitLo_ = uS - hitBand, hitHi_ = uE + hitBand;
	constexpr double inf = std::numeric_limits<double>::infinity();
	lo_ = hitLo_ <= 0 ? hitLo_ : -inf;  // along(O) = 0
	hi_ = hitHi_ >= 0 ? hitHi_ : inf;
	boundingBox(sensor, {sensor.x + sMax_ * ax, sensor.y + sMax_ * ay}, {sensor.x + sMax_ * bx, sensor.y + sMax_ * by});
	// no cell is crossed by more beams than the fan holds
	maxWeight_ = std::max(1.0, beams_ * std::abs(std::atan2(det, ax * bx + ay * by)) + 1.0);
}

// The cone cut at d = -hitBand (triangle O, O + sMax (S - O), O + sMax (E - O)) clipped to lo_ <= along() <= hi_.
void WipeTriangle::boundingBox(const TPoint2D& o, const TPoint2D& s, const TPoint2D& e)
{
	TPoint2D poly[5] = {o, s, e}, out[5];  // a triangle cut twice: at most 5 corners
	int n = 3;
	const auto clip = [&](double sign, double bound) {  // keep sign * (along() - bound) <= 0
		if (!std::isfinite(bound)) return;
		int k = 0;
		for (int i = 0; i < n; ++i)
		{
			const TPoint2D &p = poly[i], &q = poly[(i + 1) % n];
			const double fp = sign * (along(p.x, p.y) - bound), fq = sign * (along(q.x, q.y) - bound);
			if (fp <= 0) out[k++] = p;
			if ((fp < 0 && fq > 0) || (fp > 0 && fq < 0))
				out[k++] = TPoint2D(p.x + fp / (fp - fq) * (q.x - p.x), p.y + fp / (fp - fq) * (q.y - p.y));
		}
		std::copy(out, out + k, poly);
		n = k;
	};
	clip(-1, lo_);
	clip(1, hi_);
	minX_ = maxX_ = poly[0].x, minY_ = maxY_ = poly[0].y;  // O is never cut off
	for (int i = 1; i < n; ++i)
	{
		minX_ = std::min(minX_, poly[i].x), maxX_ = std::max(maxX_, poly[i].x);
		minY_ = std::min(minY_, poly[i].y), maxY_ = std::max(maxY_, poly[i].y);
	}
}

double WipeTriangle::beamDensity(const TPoint2D& o, const TPoint2D& s, const TPoint2D& e, double points)
{
	const double ax = s.x - o.x, ay = s.y - o.y, bx = e.x - o.x, by = e.y - o.y;
	const double fan = std::abs(std::atan2(ax * by - ay * bx, ax * bx + ay * by));
	return fan > 1e-9 && points > 1 ? (points - 1) / fan : 0.0;
}

// Beams counted in a cell: angular density x (width across the ray, or chord of the new vector) / range.
double WipeTriangle::weight(const TPoint2D& p, const TPoint2D& axis, double res, WipePart part) const
{
	if (beams_ <= 0) return 1.0;
	const double rx = p.x - o_.x, ry = p.y - o_.y, r = std::sqrt(rx * rx + ry * ry);
	if (r < 1e-9) return maxWeight_;
	const double ux = rx / r, uy = ry / r;
	double across;
	if (part == WipePart::Hit)
	{
		// chord of the new vector through the cell, seen under its incidence angle
		const double along = std::abs(edge_.x * axis.x + edge_.y * axis.y);
		const double side = std::abs(edge_.x * axis.y - edge_.y * axis.x);
		const double chord = res / std::max({along, side, 1e-9});
		across = chord * std::abs(ux * edge_.y - uy * edge_.x);
	}
	else  // the square's width perpendicular to the ray
		across = res * (std::abs(ux * axis.x + uy * axis.y) + std::abs(ux * axis.y - uy * axis.x));
	return std::min(maxWeight_, beams_ * across / r);
}

// Separating axes among the edges of parts b and c: a = 0, b = 0, a + b = sMax, along() = lo_, hi_
// (the box's corners all beyond one).
bool WipeTriangle::misses(double minX, double minY, double maxX, double maxY) const
{
	if (degenerate_) return true;
	constexpr double eps = 1e-9;
	bool allA = true, allB = true, allFar = true, allLo = true, allHi = true;
	for (const double x : {minX, maxX})
		for (const double y : {minY, maxY})
		{
			double a, b;
			coords(x, y, a, b);
			allA = allA && a < -eps;
			allB = allB && b < -eps;
			allFar = allFar && a + b > sMax_ + eps;
			const double u = along(x, y);
			allLo = allLo && u < lo_ - eps;
			allHi = allHi && u > hi_ + eps;
		}
	return allA || allB || allFar || allLo || allHi;
}

// Eq. 8 / Fig. 2: part c -> n_occupy, n_visit += 1; part b -> n_visit += 1; part a untouched.
size_t WipeTriangle::apply(GridVector& m) const
{
	size_t n = 0;
	const mrpt::math::TPoint2D axis = m.direction();
	forEachCellAt(m, [&](int r, int c, WipePart part, const TPoint2D& centre) {
		GridCell& cell = m.cell(r, c);
		const float w = float(weight(centre, axis, m.resolution(), part));
		if (part == WipePart::Hit) cell.n_occupy += w;
		cell.n_visit += w;
		++n;
	});
	return n;
}

}  // namespace gridvector
