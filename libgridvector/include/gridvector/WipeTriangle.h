// Eq. 8, Fig. 2: the wipe triangle of a new vector and its effect on a map vector's grid.
#pragma once

#include <gridvector/GridVector.h>

#include <mrpt/math/TPoint2D.h>

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
 * its signed distance to the far edge SE (towards O) is d(O) (1 - a - b).
 * Part c: in the cone with |d| <= hitBand (on the vector, also slightly behind
 * it, where noisy endpoints land). Part b: in the cone with d > hitBand
 * (between the sensor and the vector). Everything else is part a.
 *
 * Weight: one triangle is one observation of each cell it reaches, so it adds
 * exactly 1 to the counts of each such cell (the paper's unit: one increment
 * per cell per triangle, regardless of how many beams of the fan cross the
 * cell). ScanWipe makes that one increment per cell per *scan* where two
 * triangles of a scan meet (a shared ray at a corner). */
class WipeTriangle
{
   public:
	WipeTriangle(const mrpt::math::TPoint2D& sensor, const mrpt::math::TPoint2D& start,
				 const mrpt::math::TPoint2D& end, double hitBand);

	/** No area: the sensor (nearly) on the vector's line, or a zero-length vector. */
	bool degenerate() const { return degenerate_; }
	WipePart classify(const mrpt::math::TPoint2D& p) const;

	/** Axis-aligned bounding box of parts b and c (the cone cut at d = -hitBand). */
	double minX() const { return minX_; }
	double minY() const { return minY_; }
	double maxX() const { return maxX_; }
	double maxY() const { return maxY_; }

	/** Region by region: for each row of m's grid, the interval of the row's
	 * line inside the cone is computed in closed form and only the columns
	 * whose centres fall in it are visited; f(row, col, part) is called for
	 * every cell of part b or c. Cost O(rows + cells touched). */
	template <class F>
	void forEachCell(const GridVector& m, F&& f) const;

	/** Eq. 8 for this triangle on one map vector; returns cells updated. */
	size_t apply(GridVector& m) const;

   private:
	/** Cone coordinates (a, b) of a point. */
	void coords(double x, double y, double& a, double& b) const;
	/** Columns [k0, k1] of a grid row whose centres lie in the cone. */
	bool rowSpan(const GridVector& m, const mrpt::math::TPoint2D& rowOrigin,
				 const mrpt::math::TPoint2D& dir, int& k0, int& k1) const;

	mrpt::math::TPoint2D o_;
	double i00_ = 0, i01_ = 0, i10_ = 0, i11_ = 0;  //!< inverse of [S-O, E-O]
	double sHit_ = 1, sMax_ = 1;  //!< a+b bounds of part c
	double minX_ = 0, minY_ = 0, maxX_ = 0, maxY_ = 0;
	bool degenerate_ = true;
};

template <class F>
void WipeTriangle::forEachCell(const GridVector& m, F&& f) const
{
	if (degenerate_ || m.cols() < 1) return;
	const mrpt::math::TPoint2D d = m.direction(), n = m.leftNormal();
	const double res = m.resolution();
	for (int r = 0; r < m.rows(); ++r)
	{
		const double w = (r - m.halfWidth()) * res;
		const mrpt::math::TPoint2D q(m.start().x + w * n.x, m.start().y + w * n.y);
		int k0, k1;
		if (!rowSpan(m, q, d, k0, k1)) continue;
		for (int k = k0; k <= k1; ++k)
		{
			const double u = (k + 0.5) * res;
			double a, b;
			coords(q.x + u * d.x, q.y + u * d.y, a, b);
			const double s = a + b;
			if (s > sMax_) continue;  // guards the interval's rounding
			f(r, k, s < sHit_ ? WipePart::Visited : WipePart::Hit);
		}
	}
}

}  // namespace gridvector
