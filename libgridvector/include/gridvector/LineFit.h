// Least-squares line fitting in the (theta, rho) model of Eq. 3.
#pragma once

#include <mrpt/math/TPoint2D.h>

#include <cstddef>
#include <vector>

namespace gridvector
{
/** Line cos(theta) x + sin(theta) y - rho = 0 (Eq. 3). */
struct Line2D
{
	double theta = 0;
	double rho = 0;
	double distance(const mrpt::math::TPoint2D& p) const;  //!< signed
	mrpt::math::TPoint2D project(const mrpt::math::TPoint2D& p) const;  //!< foot of perpendicular
};

/** Weighted sums of points; fitting is O(1) from them, and sums of disjoint
 * runs add, which is what makes split-and-merge and Algorithm 2 cheap. */
struct LineMoments
{
	double w = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
	void add(double x, double y, double weight = 1.0);
	void add(const LineMoments& o);
	LineMoments minus(const LineMoments& o) const;
	/** Lu & Milios (1997b) closed form: total least squares. Returns false
	 * if fewer than 2 (weighted) points. */
	bool fit(Line2D& out) const;
	/** Sum of weighted squared orthogonal residuals of the best fit. */
	double residual(const Line2D& l) const;
};

/** Prefix sums of the moments of an ordered point run: moments of any
 * contiguous sub-run [i, j) in O(1). */
class PrefixMoments
{
   public:
	explicit PrefixMoments(const std::vector<mrpt::math::TPoint2D>& pts);
	/** Only the points [first, last) of pts; range() still takes indices into pts. */
	PrefixMoments(const std::vector<mrpt::math::TPoint2D>& pts, size_t first, size_t last);
	/** Moments of the points [i, j) (indices into the original vector). */
	LineMoments range(size_t i, size_t j) const { return m_[j - off_].minus(m_[i - off_]); }

   private:
	std::vector<LineMoments> m_;
	size_t off_ = 0;
};

}  // namespace gridvector
