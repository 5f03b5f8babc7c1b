// Relative-pose estimates in information form, as graphslam-engine edges carry them.
#pragma once

#include <Eigen/Core>
#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPosePDFGaussianInf.h>

namespace gridvector::graphslam
{
/** A relative pose (x, y, phi) with its information matrix (inverse covariance). */
struct PoseEstimate
{
	mrpt::math::TPose2D mean{0, 0, 0};
	Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
};

/** Fuses two estimates of the same relative pose: information Ia + Ib, mean
 * a + (Ia + Ib)^+ Ib (b - a), linearised at a with the angle difference wrapped.
 * A direction neither constrains (singular sum) keeps a's value. */
PoseEstimate fuse(const PoseEstimate& a, const PoseEstimate& b);

/** True if b differs from a by at most maxDistance [m] and maxAngle [rad]. */
bool closeTo(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b, double maxDistance,
			 double maxAngle);

/** True if the matrix is finite, symmetric and positive semi-definite. */
bool validInformation(const Eigen::Matrix3d& information);

/** The engine's edge type (CPosePDFGaussianInf) of an estimate. */
mrpt::poses::CPosePDFGaussianInf toConstraint(const PoseEstimate& e);

}  // namespace gridvector::graphslam
