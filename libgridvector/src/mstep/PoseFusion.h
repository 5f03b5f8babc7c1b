// Sec. 4.2 (the first M-step's chain, the online keyframes): one pose from several predictions of it.
#pragma once

#include <Eigen/Core>
#include <mrpt/math/TPose2D.h>

namespace gridvector
{
/** Information-weighted fusion of predictions of one pose, linearised at a reference prediction (the odometry's,
 * Eq. 20), each with its information in the world frame (a registration's: singular along a corridor's axis). */
class PoseFusion
{
   public:
	PoseFusion(const mrpt::math::TPose2D& reference, const Eigen::Matrix3d& information);

	void add(const mrpt::math::TPose2D& prediction, const Eigen::Matrix3d& information);
	/** The fused pose (the reference until a prediction is added). */
	const mrpt::math::TPose2D& pose() const { return pose_; }

	/** A relative measurement's information (in the frame of the pose it starts from) in the world frame. */
	static Eigen::Matrix3d toWorld(const Eigen::Matrix3d& information, double framePhi);

   private:
	mrpt::math::TPose2D reference_, pose_;
	Eigen::Matrix3d sumI_;
	Eigen::Vector3d sumIx_ = Eigen::Vector3d::Zero();
};

}  // namespace gridvector
