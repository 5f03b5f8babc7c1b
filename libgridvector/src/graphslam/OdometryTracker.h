// What one graphslam-engine step (rawlog entry) says about odometry and the laser.
#pragma once

#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservation.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CSensoryFrame.h>

namespace gridvector::graphslam
{
/** The 2D laser scan of a step: the observation itself (observation-only
 * rawlogs) or the first one in the sensory frame (actions + sensory frames);
 * null if the step has none. */
mrpt::obs::CObservation2DRangeScan::Ptr scanOf(const mrpt::obs::CSensoryFrame::Ptr& observations,
											   const mrpt::obs::CObservation::Ptr& observation);

/** Dead-reckoning pose from either rawlog format: CObservationOdometry gives
 * the absolute odometry (observation-only rawlogs, or inside a sensory frame),
 * a CActionRobotMovement2D's mean is compounded onto the current pose. */
class OdometryTracker
{
   public:
	/** Returns true if the step carried odometry. */
	bool update(const mrpt::obs::CActionCollection::Ptr& action, const mrpt::obs::CSensoryFrame::Ptr& observations,
				const mrpt::obs::CObservation::Ptr& observation);
	const mrpt::math::TPose2D& pose() const { return pose_; }
	bool seen() const { return seen_; }

   private:
	mrpt::math::TPose2D pose_{0, 0, 0};
	bool seen_ = false;
};

}  // namespace gridvector::graphslam
