// Writes CARMEN log lines (PARAM, ODOM, FLASER) in the layout the readers expect.
#pragma once

#include <mrpt/math/TPose2D.h>

#include <ostream>
#include <string>
#include <vector>

namespace gridvector::io
{
class CarmenWriter
{
   public:
	explicit CarmenWriter(std::ostream& os, std::string host = "gridvector") : os_(os), host_(std::move(host)) {}

	void comment(const std::string& text);
	/** "PARAM name value host 0" */
	void param(const std::string& name, const std::string& value);
	/** "ODOM x y theta tv rv accel t host t" */
	void odom(const mrpt::math::TPose2D& p, double tv, double rv, double t);
	/** "FLASER n r1..rn x y theta odom_x odom_y odom_theta t host t"; ranges in mm (%.3f). */
	void flaser(const std::vector<float>& ranges, const mrpt::math::TPose2D& pose, const mrpt::math::TPose2D& odom,
				double t);
	/** The same with the range fields given as text (copied verbatim). */
	void flaser(const std::vector<std::string>& ranges, const mrpt::math::TPose2D& pose,
				const mrpt::math::TPose2D& odom, double t);

   private:
	void poseAndTime(const mrpt::math::TPose2D& pose, const mrpt::math::TPose2D& odom, double t);
	std::ostream& os_;
	std::string host_;
};

}  // namespace gridvector::io
