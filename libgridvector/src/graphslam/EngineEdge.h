// An edge of Eq. 22 as graphslam-engine graphs carry it (CPosePDFGaussianInf).
#pragma once

#include <Eigen/Core>
#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPosePDFGaussianInf.h>

namespace gridvector::graphslam
{
/** The engine's edge for a relative pose z with `information` in the frame of PoseGraph::error (Eq. 21):
 * MRPT's optimisers measure an edge's error as inv(EDGE) (+) inv(P1) (+) P2 (graphslam/levmarq_impl.h),
 * the same error, so the engine's graph and PoseGraph minimise the same Eq. 22. */
mrpt::poses::CPosePDFGaussianInf engineEdge(const mrpt::math::TPose2D& z, const Eigen::Matrix3d& information);

}  // namespace gridvector::graphslam
