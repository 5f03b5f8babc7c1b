// Sec. 3.2: the three correspondence criteria between two vectors in global coordinates.
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <mrpt/math/TPoint2D.h>

namespace gridvector
{
/** The quantities the three criteria compare, for diagnostics and tests. */
struct CorrespondenceTest
{
	double dPsi = 0;  //!< |psi_a - psi_b| wrapped to [0, pi] [rad]
	double dTheta = 0;  //!< |theta_a - theta_b| wrapped to [0, pi] [rad]
	double dRho = 0;  //!< |rho_a - rho_b| with rho measured from the pair's midpoint [m]
	double centreDistance = 0;  //!< |c_a - c_b| [m]
	double halfLengths = 0;  //!< (l_a + l_b) / 2 [m]
	bool match = false;
};

/** Criterion 1: directions psi close (opposite directions never match: open
 * space on different sides). Criterion 2: lines (theta, rho) of Eq. 3 close.
 * Criterion 3: centre distance below half the summed lengths.
 *
 * rho is the signed distance of the line from an origin; taken from the world
 * origin, a tiny angle difference becomes a large rho difference far from it
 * (|delta rho| ~ distance * |delta theta|). Both rho are therefore measured
 * from the midpoint of the two centres: the same criterion, independent of
 * where the world origin happens to be. */
CorrespondenceTest testCorrespondence(const mrpt::math::TPoint2D& sa, const mrpt::math::TPoint2D& ea,
									  const mrpt::math::TPoint2D& sb, const mrpt::math::TPoint2D& eb,
									  const MapOptions& opt);

inline CorrespondenceTest testCorrespondence(const GridVector& a, const GridVector& b, const MapOptions& opt)
{
	return testCorrespondence(a.start(), a.end(), b.start(), b.end(), opt);
}

/** How far beyond a vector's grid band (Box2D::of) a correspondent can lie:
 * corresponding vectors overlap along their direction (criterion 3) and are
 * at most max_rho_diff apart at their centres' midpoint, drifting apart by at
 * most l/2 sin(max_direction_diff) over the vector's half length. */
double correspondenceSearchMargin(double length, const MapOptions& opt);

/** testCorrespondence(a, b, opt).match, with the cheap rejections first
 * (opposite directions, criterion 3 on squared distances, criterion 1 on the
 * cosine of the directions): the same decisions, without the trigonometry for
 * the many pairs of a dense neighbourhood that fail early. */
bool corresponds(const GridVector& a, const GridVector& b, const MapOptions& opt);

}  // namespace gridvector
