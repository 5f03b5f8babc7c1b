// Odometry readings over time, interpolated at scan times (for logs whose scans
// carry no pose: CARMEN RAWLASER, MRPT observation-only rawlogs).
#pragma once

#include <mrpt/math/TPose2D.h>

#include <optional>
#include <vector>

namespace gridvector::io
{
class OdometryTrack
{
   public:
	void add(double t, const mrpt::math::TPose2D& pose);
	bool empty() const { return samples_.empty(); }
	size_t size() const { return samples_.size(); }
	/** Pose at time t: linear interpolation (angles along the shorter arc) between
	 * the readings around t; the nearest reading outside their time span;
	 * nullopt if there are no readings. */
	std::optional<mrpt::math::TPose2D> at(double t) const;

   private:
	void sortIfNeeded() const;
	mutable std::vector<std::pair<double, mrpt::math::TPose2D>> samples_;
	mutable bool sorted_ = true;
};

}  // namespace gridvector::io
