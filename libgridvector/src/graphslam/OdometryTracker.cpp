#include "graphslam/OdometryTracker.h"

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/poses/CPose2D.h>

namespace gridvector::graphslam
{
using mrpt::obs::CObservation2DRangeScan;
using mrpt::obs::CObservationOdometry;

CObservation2DRangeScan::Ptr scanOf(const mrpt::obs::CSensoryFrame::Ptr& observations,
									const mrpt::obs::CObservation::Ptr& observation)
{
	if (observation) return std::dynamic_pointer_cast<CObservation2DRangeScan>(observation);
	if (observations) return observations->getObservationByClass<CObservation2DRangeScan>();
	return {};
}

bool OdometryTracker::update(const mrpt::obs::CActionCollection::Ptr& action,
							 const mrpt::obs::CSensoryFrame::Ptr& observations,
							 const mrpt::obs::CObservation::Ptr& observation)
{
	CObservationOdometry::Ptr odo;
	if (observation)
		odo = std::dynamic_pointer_cast<CObservationOdometry>(observation);
	else if (observations)
		odo = observations->getObservationByClass<CObservationOdometry>();
	if (odo)
	{
		pose_ = odo->odometry.asTPose();
		return seen_ = true;
	}
	if (!action) return false;
	const auto move = action->getBestMovementEstimation();
	if (!move || !move->poseChange) return false;
	const mrpt::poses::CPose2D inc = move->poseChange->getMeanVal();
	pose_ = (mrpt::poses::CPose2D(pose_) + inc).asTPose();
	return seen_ = true;
}

}  // namespace gridvector::graphslam
