// Eq. 8, Fig. 2: the wipe triangle of a new vector and its effect on a map vector's grid.
#pragma once

#include <gridvector/GridVector.h>

#include <mrpt/math/TPoint2D.h>

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace gridvector
{
/** Fig. 2: how a wipe triangle sees one point. */
enum class WipePart : uint8_t
{
	Outside = 0,  //!< part a: untouched
	Visited = 1,  //!< part b: a beam passed through, n_visit += 1
	Hit = 2  //!< part c: a beam ended here, n_occupy += 1 and n_visit += 1
};

/** The triangle from the sensor position O to the endpoints S, E of a newly
 * observed vector v_j (all in global coordinates): the fan of beams that
 * produced v_j (Eq. 8, Fig. 2).
 *
 * A point P = O + a (S - O) + b (E - O) lies in the beams' cone when a, b >= 0;
 * its signed distance to the line of SE (towards O) is d = d(O) (1 - a - b),
 * and u is its coordinate along SE (u(S) <= u <= u(E) over the segment).
 * Part c ("near v_j", Fig. 2): in the cone, |d| <= hitBand and
 * u(S) - hitBand <= u <= u(E) + hitBand, i.e. within hitBand of the segment
 * SE (a box around it): on the vector, also slightly behind it, where noisy
 * endpoints land. Part b: the rest of the triangle OSE (beams passed through,
 * none ended). Everything else is part a.
 *
 * The box, not just the band along SE's line: at grazing incidence d(O) is
 * tiny and the cone behind the line widens fast, so a band |d| <= hitBand
 * alone reached metres (km on csail) past the segment's ends along the rays,
 * where no beam ended, and in front of the line it made the whole thin
 * triangle, up to the sensor, "hit". Near normal incidence (both ends seen
 * within 45 deg of the normal) the cone within the band never leaves the box:
 * the parts are those of the band alone. Parts b and c together are convex:
 * the cone cut at d = -hitBand and by the box's two ends (an end is not a cut
 * where the triangle itself reaches past it, on the sensor's side), so a grid
 * row still meets them in one interval (forEachCellAt).
 *
 * Weight of an increment (see weight()): the paper's Fig. 2 adds 1 per cell
 * per triangle. Algorithm 1, however, counts one per beam endpoint, so a cell
 * with k endpoints of one scan gets k; a wipe of weight 1 then cannot balance
 * it and cells next to a wall that catch a few noisy endpoints stay
 * "occupied" although every scan's beams pass through them. With
 * beamsPerRadian > 0 an increment instead counts the beams of the fan that
 * cross the cell: beamsPerRadian * (width of the cell across the ray) / range,
 * the region-by-region equivalent of the per-beam counting model, in the same
 * unit as Algorithm 1. */
class WipeTriangle
{
   public:
	/** beamsPerRadian: angular density of the fan's beams (0: weight 1 per cell, the paper's unit). */
	WipeTriangle(const mrpt::math::TPoint2D& sensor, const mrpt::math::TPoint2D& start, const mrpt::math::TPoint2D& end,
				 double hitBand, double beamsPerRadian = 0);

	/** Beams of the fan counted in a cell of side `res` centred at p whose grid
	 * runs along the unit vector `axis` (1 when beamsPerRadian is 0). Part b:
	 * the beams crossing the cell (its width across the ray over the range).
	 * Part c: the beams ending in it, i.e. hitting the new vector's chord
	 * through the cell (chord length x sin(incidence) over the range). */
	double weight(const mrpt::math::TPoint2D& p, const mrpt::math::TPoint2D& axis, double res, WipePart part) const;
	/** Beams of the fan for a vector built from `points` endpoints seen from `sensor`. */
	static double beamDensity(const mrpt::math::TPoint2D& sensor, const mrpt::math::TPoint2D& start,
							  const mrpt::math::TPoint2D& end, double points);

	/** No area: the sensor (nearly) on the vector's line, or a zero-length vector. */
	bool degenerate() const { return degenerate_; }
	/** Fig. 2's part of a point (partOf() on its cone coordinates; forEachCellAt uses the same predicate). */
	WipePart classify(const mrpt::math::TPoint2D& p) const
	{
		if (degenerate_) return WipePart::Outside;
		double a, b;
		coords(p.x, p.y, a, b);
		return partOf(a, b, along(p.x, p.y));
	}

	/** Axis-aligned bounding box of parts b and c (the cone cut at d = -hitBand and by the box's ends). */
	double minX() const { return minX_; }
	double minY() const { return minY_; }
	double maxX() const { return maxX_; }
	double maxY() const { return maxY_; }

	/** Region by region: for each row of m's grid, the interval of the row's
	 * line inside the cone is computed in closed form and only the columns
	 * whose centres fall in it are visited; f(row, col, part) is called for
	 * every cell of part b or c. Cost O(rows + cells touched). */
	template <class F>
	void forEachCell(const GridVector& m, F&& f) const
	{
		forEachCellAt(m, [&](int r, int c, WipePart p, const mrpt::math::TPoint2D&) { f(r, c, p); });
	}
	/** As forEachCell, with the cell's centre (global): f(row, col, part, centre). */
	template <class F>
	void forEachCellAt(const GridVector& m, F&& f) const;

	/** True if the axis-aligned box [minX, maxX] x [minY, maxY] lies wholly
	 * outside parts b and c (beyond one of the edges of their polygon): no cell
	 * whose centre is in the box can be updated. Conservative (false when unsure). */
	bool misses(double minX, double minY, double maxX, double maxY) const;
	/** Eq. 8 for this triangle on one map vector (weights as weight()); returns cells updated. */
	size_t apply(GridVector& m) const;

   private:
	/** Cone coordinates (a, b) of a point (inline: called for every cell a triangle reaches). */
	void coords(double x, double y, double& a, double& b) const
	{
		const double px = x - o_.x, py = y - o_.y;
		a = i00_ * px + i01_ * py;
		b = i10_ * px + i11_ * py;
	}
	/** Coordinate along SE from O's foot (inline: as coords). */
	double along(double x, double y) const { return edge_.x * (x - o_.x) + edge_.y * (y - o_.y); }
	/** Tolerance of the cone's edges a = 0, b = 0 (a point on an edge ray is in the cone). */
	static constexpr double kEdgeTol = 1e-12;
	/** Fig. 2 in cone coordinates: the one predicate of classify() and of the walk's cells. */
	WipePart partOf(double a, double b, double u) const
	{
		if (a < -kEdgeTol || b < -kEdgeTol || a + b > sMax_ || u < lo_ || u > hi_) return WipePart::Outside;
		return a + b >= sHit_ && u >= hitLo_ && u <= hitHi_ ? WipePart::Hit : WipePart::Visited;
	}
	/** Sets the bounding box of the triangle o, s, e clipped to lo_ <= along() <= hi_. */
	void boundingBox(const mrpt::math::TPoint2D& o, const mrpt::math::TPoint2D& s, const mrpt::math::TPoint2D& e);
	/** Columns [k0, k1] of a grid row holding every centre in parts b and c (a superset: its bounds are
	 * widened by 1e-9 against rounding, the cells are then tested by partOf; inline: once per row and map vector). */
	bool rowSpan(const GridVector& m, const mrpt::math::TPoint2D& rowOrigin, const mrpt::math::TPoint2D& dir, int& k0,
				 int& k1) const;
	/** Intersect [lo, hi] with {u : g0 + g1 u >= c}; false if it becomes empty. */
	static bool clipLinear(double g0, double g1, double c, double& lo, double& hi);

	mrpt::math::TPoint2D o_;
	double i00_ = 0, i01_ = 0, i10_ = 0, i11_ = 0;  //!< inverse of [S-O, E-O]
	double sHit_ = 1, sMax_ = 1;  //!< a+b bounds of part c
	double hitLo_ = 0, hitHi_ = 0;  //!< along() bounds of part c: the segment's ends +- hitBand
	double lo_ = 0, hi_ = 0;  //!< along() bounds of parts b and c (+-infinity where no cut)
	double minX_ = 0, minY_ = 0, maxX_ = 0, maxY_ = 0;
	double beams_ = 0, maxWeight_ = 1;
	mrpt::math::TPoint2D edge_{1, 0};  //!< unit direction S -> E
	bool degenerate_ = true;
};

inline bool WipeTriangle::clipLinear(double g0, double g1, double c, double& lo, double& hi)
{
	if (std::abs(g1) < 1e-15)
	{
		if (g0 < c) return false;
	}
	else if (g1 > 0)
		lo = std::max(lo, (c - g0) / g1);
	else
		hi = std::min(hi, (c - g0) / g1);
	return lo <= hi;
}

inline bool WipeTriangle::rowSpan(const GridVector& m, const mrpt::math::TPoint2D& q, const mrpt::math::TPoint2D& d,
								  int& k0, int& k1) const
{
	const double res = m.resolution();
	double a0, b0, a1, b1;
	coords(q.x, q.y, a0, b0);
	a1 = i00_ * d.x + i01_ * d.y;
	b1 = i10_ * d.x + i11_ * d.y;
	double lo = 0.5 * res, hi = (m.cols() - 0.5) * res;  // column centres
	constexpr double eps = 1e-9;  // widens the interval only: partOf decides each cell
	if (!clipLinear(a0, a1, -eps, lo, hi) || !clipLinear(b0, b1, -eps, lo, hi) ||
		!clipLinear(-(a0 + b0), -(a1 + b1), -sMax_ - eps, lo, hi))
		return false;
	const double u0 = along(q.x, q.y), u1 = edge_.x * d.x + edge_.y * d.y;
	if (!clipLinear(u0, u1, lo_ - eps, lo, hi) || !clipLinear(-u0, -u1, -hi_ - eps, lo, hi)) return false;
	// ceil and floor of values in [-1e-9, cols]: int(ceil(x)) and int(floor(x)) without the libm calls
	const double x0 = lo / res - 0.5 - 1e-9, x1 = hi / res - 0.5 + 1e-9;
	int c0 = int(x0), c1 = int(x1);
	c0 += double(c0) < x0;
	c1 -= double(c1) > x1;
	k0 = std::max(0, c0);
	k1 = std::min(m.cols() - 1, c1);
	return k0 <= k1;
}

template <class F>
void WipeTriangle::forEachCellAt(const GridVector& m, F&& f) const
{
	if (degenerate_ || m.cols() < 1) return;
	const mrpt::math::TPoint2D d = m.direction(), n = m.leftNormal();
	const double res = m.resolution();
	constexpr int block = 64;
	double cx[block], cy[block], as[block], bs[block], us[block];
	for (int r = 0; r < m.rows(); ++r)
	{
		const double w = (r - m.halfWidth()) * res, wx = w * n.x, wy = w * n.y;
		const mrpt::math::TPoint2D q(m.start().x + wx, m.start().y + wy);
		int k0, k1;
		if (!rowSpan(m, q, d, k0, k1)) continue;
		for (int b = k0; b <= k1; b += block)
		{
			const int nb = std::min(block, k1 - b + 1);
			for (int j = 0; j < nb; ++j)  // the cells' centres and cone coordinates, branch-free (vectorised)
			{
				const double u = (b + j + 0.5) * res;
				cx[j] = m.start().x + u * d.x + wx;  // as GridVector::cellCentre, to the last bit
				cy[j] = m.start().y + u * d.y + wy;
				const double px = cx[j] - o_.x, py = cy[j] - o_.y;
				as[j] = i00_ * px + i01_ * py;  // coords(), same operations
				bs[j] = i10_ * px + i11_ * py;
				us[j] = edge_.x * px + edge_.y * py;  // along()
			}
			for (int j = 0; j < nb; ++j)
			{
				const WipePart part = partOf(as[j], bs[j], us[j]);  // classify()'s predicate, cell by cell
				if (part != WipePart::Outside) f(r, b + j, part, mrpt::math::TPoint2D(cx[j], cy[j]));
			}
		}
	}
}

}  // namespace gridvector
