#include "mstep/PoseFusion.h"

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Cholesky>

#include <cmath>

namespace gridvector
{
using Eigen::Matrix3d;
using Eigen::Vector3d;
using mrpt::math::TPose2D;

PoseFusion::PoseFusion(const TPose2D& reference, const Matrix3d& information)
	: reference_(reference), pose_(reference), sumI_(information)
{}

// Gauss-Newton's one step at the reference: x = (sum I_k)^-1 sum I_k (z_k - reference).
void PoseFusion::add(const TPose2D& prediction, const Matrix3d& information)
{
	const Vector3d d(prediction.x - reference_.x, prediction.y - reference_.y,
					 mrpt::math::wrapToPi(prediction.phi - reference_.phi));
	sumI_ += information;
	sumIx_ += information * d;
	const Vector3d x = sumI_.ldlt().solve(sumIx_);
	pose_ = TPose2D(reference_.x + x.x(), reference_.y + x.y(), mrpt::math::wrapToPi(reference_.phi + x.z()));
}

Matrix3d PoseFusion::toWorld(const Matrix3d& information, double framePhi)
{
	Matrix3d R = Matrix3d::Identity();
	R.topLeftCorner<2, 2>() << std::cos(framePhi), -std::sin(framePhi), std::sin(framePhi), std::cos(framePhi);
	return R * information * R.transpose();
}

}  // namespace gridvector
