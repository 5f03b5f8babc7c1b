#include "io/CarmenWriter.h"

#include <cstdio>

namespace gridvector::io
{
void CarmenWriter::comment(const std::string& text) { os_ << "# " << text << '\n'; }

void CarmenWriter::param(const std::string& name, const std::string& value)
{
	os_ << "PARAM " << name << ' ' << value << ' ' << host_ << " 0\n";
}

void CarmenWriter::odom(const mrpt::math::TPose2D& p, double tv, double rv, double t)
{
	char b[256];
	std::snprintf(b, sizeof b, "ODOM %.6f %.6f %.6f %.6f %.6f 0 %.6f %s %.6f\n", p.x, p.y, p.phi, tv, rv, t,
				  host_.c_str(), t);
	os_ << b;
}

void CarmenWriter::poseAndTime(const mrpt::math::TPose2D& p, const mrpt::math::TPose2D& o, double t)
{
	char b[256];
	std::snprintf(b, sizeof b, " %.6f %.6f %.6f %.6f %.6f %.6f %.6f %s %.6f\n", p.x, p.y, p.phi, o.x, o.y, o.phi, t,
				  host_.c_str(), t);
	os_ << b;
}

void CarmenWriter::flaser(const std::vector<float>& ranges, const mrpt::math::TPose2D& pose,
						  const mrpt::math::TPose2D& odom, double t)
{
	os_ << "FLASER " << ranges.size();
	char b[32];
	for (float r : ranges)
	{
		std::snprintf(b, sizeof b, " %.3f", double(r));
		os_ << b;
	}
	poseAndTime(pose, odom, t);
}

void CarmenWriter::flaser(const std::vector<std::string>& ranges, const mrpt::math::TPose2D& pose,
						  const mrpt::math::TPose2D& odom, double t)
{
	os_ << "FLASER " << ranges.size();
	for (const auto& r : ranges) os_ << ' ' << r;
	poseAndTime(pose, odom, t);
}

}  // namespace gridvector::io
