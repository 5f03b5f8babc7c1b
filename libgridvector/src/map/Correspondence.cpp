#include "map/Correspondence.h"

#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace gridvector
{
using mrpt::math::TPoint2D;

namespace
{
double angleDiff(double a, double b) { return std::abs(mrpt::math::wrapToPi(a - b)); }
}  // namespace

// Sec. 3.2: criteria 1-3.
CorrespondenceTest testCorrespondence(const TPoint2D& sa, const TPoint2D& ea, const TPoint2D& sb, const TPoint2D& eb,
									  const MapOptions& opt)
{
	CorrespondenceTest t;
	const double la = std::hypot(ea.x - sa.x, ea.y - sa.y), lb = std::hypot(eb.x - sb.x, eb.y - sb.y);
	const double psiA = std::atan2(ea.y - sa.y, ea.x - sa.x), psiB = std::atan2(eb.y - sb.y, eb.x - sb.x);
	const double thA = psiA - M_PI / 2, thB = psiB - M_PI / 2;  // Eq. 3 normals (see GridVector::line)
	const TPoint2D ca((sa.x + ea.x) / 2, (sa.y + ea.y) / 2), cb((sb.x + eb.x) / 2, (sb.y + eb.y) / 2);
	const TPoint2D mid((ca.x + cb.x) / 2, (ca.y + cb.y) / 2);
	// rho of each line with the origin moved to the midpoint of the centres
	const double rhoA = std::cos(thA) * (ca.x - mid.x) + std::sin(thA) * (ca.y - mid.y);
	const double rhoB = std::cos(thB) * (cb.x - mid.x) + std::sin(thB) * (cb.y - mid.y);
	t.dPsi = angleDiff(psiA, psiB);
	t.dTheta = angleDiff(thA, thB);
	t.dRho = std::abs(rhoA - rhoB);
	t.centreDistance = std::hypot(ca.x - cb.x, ca.y - cb.y);
	t.halfLengths = (la + lb) / 2;
	const double deg = M_PI / 180.0;
	const double dirX = (ea.x - sa.x) * (eb.x - sb.x) + (ea.y - sa.y) * (eb.y - sb.y);
	t.match = la > 0 && lb > 0 && dirX > 0 &&  // opposite directions never match
			  t.dPsi <= opt.maxDirectionDiffDeg * deg &&  // criterion 1
			  t.dTheta <= opt.maxThetaDiffDeg * deg && t.dRho <= opt.maxRhoDiff &&  // criterion 2
			  t.centreDistance < t.halfLengths;  // criterion 3
	return t;
}

// Sec. 3.2: criteria 1-3 between two grid vectors in global coordinates.
bool corresponds(const GridVector& a, const GridVector& b, const MapOptions& opt)
{
	const TPoint2D da = a.direction(), db = b.direction();
	const double cosPsi = da.x * db.x + da.y * db.y;
	if (cosPsi <= 0) return false;  // opposite directions
	// margins keep the decisions of the exact test at the boundaries
	if (cosPsi < std::cos(opt.maxDirectionDiffDeg * M_PI / 180.0) - 1e-9) return false;  // criterion 1
	const TPoint2D ca = a.centre(), cb = b.centre();
	const double d2 = (ca.x - cb.x) * (ca.x - cb.x) + (ca.y - cb.y) * (ca.y - cb.y);
	const double h = (a.length() + b.length()) / 2;
	if (d2 > h * h * (1 + 1e-9)) return false;  // criterion 3
	return testCorrespondence(a, b, opt).match;
}

double correspondenceSearchMargin(double length, const MapOptions& opt)
{
	return opt.maxRhoDiff + 0.5 * length * std::sin(opt.maxDirectionDiffDeg * M_PI / 180.0);
}

}  // namespace gridvector
