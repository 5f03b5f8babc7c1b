// CGridVectorMap: inserting observations (Sec. 3.1 extraction + Sec. 3.2 global update).
#include "mrpt/CGridVectorMapImpl.h"
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

using namespace mrpt::maps;

gridvector::LocalScan CGridVectorMap::extractLocal(const mrpt::obs::CObservation2DRangeScan& scan) const
{
	return impl_->extractor.extract(scan);
}

bool CGridVectorMap::internal_insertObservation(const mrpt::obs::CObservation& obs,
												const std::optional<const mrpt::poses::CPose3D>& robotPose)
{
	const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs);
	if (!scan) return false;
	gridvector::LocalScan local = impl_->extractor.extract(*scan);
	local.scanIndex = int64_t(insertedScans_++);
	const mrpt::math::TPose2D pose = robotPose ? mrpt::math::TPose2D(robotPose->x(), robotPose->y(), robotPose->yaw())
											   : mrpt::math::TPose2D(0, 0, 0);
	impl_->map.insertScan(pose, local);  // m = x (+) v, Eq. 8, Algorithm 2
	return true;
}
