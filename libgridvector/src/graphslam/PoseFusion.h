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
bool closeTo(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b, double maxDistance, double maxAngle);

/** True if the matrix is finite, symmetric and positive semi-definite. */
bool validInformation(const Eigen::Matrix3d& information);

/** The engine's edge type (CPosePDFGaussianInf) of an estimate. MRPT's optimisers
 * measure an edge's error as inv(EDGE) (+) inv(P1) (+) P2 (graphslam/levmarq_impl.h), Eq. 21's,
 * whose translation is in the later pose's frame, while e.information is over the
 * relative pose's (x, y, phi): with errorFrame (mstep.information_in_edge_frame) it is
 * rotated into the error's frame (PoseGraph::errorFrameInformation, D^T I D). */
mrpt::poses::CPosePDFGaussianInf toConstraint(const PoseEstimate& e, bool errorFrame);

}  // namespace gridvector::graphslam
