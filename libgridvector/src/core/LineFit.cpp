#include <gridvector/LineFit.h>

#include <cmath>

namespace gridvector
{
double Line2D::distance(const mrpt::math::TPoint2D& p) const
{
	return std::cos(theta) * p.x + std::sin(theta) * p.y - rho;
}

mrpt::math::TPoint2D Line2D::project(const mrpt::math::TPoint2D& p) const
{
	const double d = distance(p);
	return {p.x - d * std::cos(theta), p.y - d * std::sin(theta)};
}

void LineMoments::add(double x, double y, double weight)
{
	w += weight;
	sx += weight * x;
	sy += weight * y;
	sxx += weight * x * x;
	syy += weight * y * y;
	sxy += weight * x * y;
}

void LineMoments::add(const LineMoments& o)
{
	w += o.w, sx += o.sx, sy += o.sy, sxx += o.sxx, syy += o.syy, sxy += o.sxy;
}

LineMoments LineMoments::minus(const LineMoments& o) const
{
	LineMoments r;
	r.w = w - o.w, r.sx = sx - o.sx, r.sy = sy - o.sy;
	r.sxx = sxx - o.sxx, r.syy = syy - o.syy, r.sxy = sxy - o.sxy;
	return r;
}

// Eq. 3 fitted by least squares (Lu & Milios 1997b): minimise sum w (x cos + y sin - rho)^2.
bool LineMoments::fit(Line2D& out) const
{
	if (w <= 0) return false;
	const double mx = sx / w, my = sy / w;
	const double cxx = sxx / w - mx * mx, cyy = syy / w - my * my, cxy = sxy / w - mx * my;
	if (cxx + cyy <= 1e-18) return false;
	out.theta = 0.5 * std::atan2(-2.0 * cxy, cyy - cxx);
	out.rho = mx * std::cos(out.theta) + my * std::sin(out.theta);
	if (out.rho < 0)
	{
		out.rho = -out.rho;
		out.theta += out.theta > 0 ? -M_PI : M_PI;
	}
	return true;
}

double LineMoments::residual(const Line2D& l) const
{
	const double c = std::cos(l.theta), s = std::sin(l.theta);
	// sum w (c x + s y - rho)^2 expanded over the moments
	return c * c * sxx + s * s * syy + 2 * c * s * sxy - 2 * l.rho * (c * sx + s * sy) + l.rho * l.rho * w;
}

PrefixMoments::PrefixMoments(const std::vector<mrpt::math::TPoint2D>& pts) : PrefixMoments(pts, 0, pts.size()) {}

PrefixMoments::PrefixMoments(const std::vector<mrpt::math::TPoint2D>& pts, size_t first, size_t last) : off_(first)
{
	m_.resize(last - first + 1);
	for (size_t i = first; i < last; ++i)
	{
		m_[i - first + 1] = m_[i - first];
		m_[i - first + 1].add(pts[i].x, pts[i].y);
	}
}

}  // namespace gridvector
