#include "posegraph/PoseGraph.h"
#include "graphslam/PoseFusion.h"

#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

namespace gridvector::graphslam
{
PoseEstimate fuse(const PoseEstimate& a, const PoseEstimate& b)
{
	const Eigen::Matrix3d sum = a.information + b.information;
	const Eigen::Vector3d d(b.mean.x - a.mean.x, b.mean.y - a.mean.y, mrpt::math::wrapToPi(b.mean.phi - a.mean.phi));
	const Eigen::Vector3d step = sum.completeOrthogonalDecomposition().solve(b.information * d);
	PoseEstimate out;
	out.mean =
		mrpt::math::TPose2D(a.mean.x + step.x(), a.mean.y + step.y(), mrpt::math::wrapToPi(a.mean.phi + step.z()));
	out.information = sum;
	return out;
}

bool closeTo(const mrpt::math::TPose2D& a, const mrpt::math::TPose2D& b, double maxDistance, double maxAngle)
{
	return std::hypot(b.x - a.x, b.y - a.y) <= maxDistance && std::abs(mrpt::math::wrapToPi(b.phi - a.phi)) <= maxAngle;
}

bool validInformation(const Eigen::Matrix3d& information)
{
	if (!information.allFinite()) return false;
	if (!information.isApprox(information.transpose(), 1e-9) && (information - information.transpose()).norm() > 1e-9)
		return false;
	const Eigen::Vector3d ev = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(information).eigenvalues();
	return ev.minCoeff() >= -1e-9 * std::max(1.0, ev.maxCoeff());
}

// Eq. 21's error frame, as MRPT's levmarq measures an edge (inv(EDGE) (+) inv(P1) (+) P2).
mrpt::poses::CPosePDFGaussianInf toConstraint(const PoseEstimate& e, bool errorFrame)
{
	mrpt::poses::CPosePDFGaussianInf c;
	c.mean = mrpt::poses::CPose2D(e.mean);
	const Eigen::Matrix3d info = errorFrame ? PoseGraph::errorFrameInformation(e.information, e.mean) : e.information;
	for (int r = 0; r < 3; ++r)
		for (int k = 0; k < 3; ++k) c.cov_inv(r, k) = info(r, k);
	return c;
}

}  // namespace gridvector::graphslam
