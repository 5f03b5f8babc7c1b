#include "io/CarmenParams.h"
#include "io/InputLimits.h"

#include <cmath>
#include <string>

namespace gridvector::io
{
namespace
{
constexpr double kDeg = M_PI / 180.0;

bool parseFlag(std::string_view v, const TextPos& pos, std::string_view name)
{
	if (v == "1" || v == "on" || v == "yes" || v == "true") return true;
	if (v == "0" || v == "off" || v == "no" || v == "false") return false;
	parseError(pos, "PARAM " + std::string(name) + " is '" + printableToken(v) + "' (expected 0/1/on/off)");
}

/** A value in (0, hi]. */
double positive(std::string_view v, const TextPos& pos, std::string_view name, double hi, const char* unit)
{
	const double d = parseDouble(v, pos, "PARAM " + std::string(name));
	if (d <= 0) parseError(pos, "PARAM " + std::string(name) + " is " + printableToken(v) + " (must be > 0)");
	if (d > hi)
		parseError(pos, "PARAM " + std::string(name) + " is " + printableToken(v) + " (at most " + shortestText(hi) +
							" " + unit + ")");
	return d;
}

double bounded(std::string_view v, const TextPos& pos, std::string_view name, double limit, const char* unit)
{
	return parseBounded(v, pos, "PARAM " + std::string(name), limit, unit);
}

/** CARMEN writes the field of view in radians (3.14159) or, in some tools, degrees (180). */
double fovToDegrees(double v) { return v <= 2 * M_PI + 0.01 ? v / kDeg : v; }

double inferredResolutionDeg(size_t n, const CarmenLaserParams& p)
{
	if (n == 180 || n == 181) return 1.0;
	if (n == 360 || n == 361) return 0.5;
	if (n == 720 || n == 721) return 0.25;
	const double fov = p.fovDeg.value_or(180.0);
	return n > 1 ? fov / double(n - 1) : fov;
}
}  // namespace

bool CarmenParams::apply(std::string_view name, std::string_view value, const TextPos& pos)
{
	const bool front = name.find("front") != std::string_view::npos;
	const bool rear = name.find("rear") != std::string_view::npos;
	if (!front && !rear) return false;
	CarmenLaserParams& l = front ? front_ : rear_;
	const double sign = front ? 1.0 : -1.0;
	if (name == "laser_front_laser_resolution" || name == "laser_rear_laser_resolution")
		l.resolutionDeg = positive(value, pos, name, kMaxResolutionDeg, "deg");
	else if (name == "laser_front_laser_fov" || name == "laser_rear_laser_fov")
		l.fovDeg = fovToDegrees(positive(value, pos, name, 360, "deg"));  // radians: at most 2 pi, read as 360.6 deg
	else if (name == "robot_front_laser_max" || name == "robot_rear_laser_max")
		l.maxRange = positive(value, pos, name, kMaxRangeLimit, "m");
	else if (name == "robot_frontlaser_offset" || name == "robot_rearlaser_offset")
		l.offsetX = sign * bounded(value, pos, name, kMaxSensorOffset, "m");
	else if (name == "robot_frontlaser_side_offset" || name == "robot_rearlaser_side_offset")
		l.offsetY = bounded(value, pos, name, kMaxSensorOffset, "m");
	else if (name == "robot_frontlaser_angular_offset" || name == "robot_rearlaser_angular_offset")
		l.offsetYaw = bounded(value, pos, name, kMaxAngle, "rad");
	else if (name == "laser_front_laser_flipped" || name == "laser_rear_laser_flipped")
		l.flipped = parseFlag(value, pos, name);
	else
		return false;
	return true;
}

BeamLayout carmenBeamLayout(size_t n, const CarmenLaserParams& p)
{
	BeamLayout b;
	b.resolutionInferred = !p.resolutionDeg.has_value();
	const double resDeg = p.resolutionDeg ? *p.resolutionDeg : inferredResolutionDeg(n, p);
	const double fovDeg = p.fovDeg ? *p.fovDeg : resDeg * double(n % 2 == 1 ? n - 1 : n);
	b.resolution = resDeg * kDeg;
	b.startAngle = -0.5 * fovDeg * kDeg;
	b.aperture = b.resolution * double(n > 0 ? n - 1 : 0);
	b.yawOffset = b.startAngle + 0.5 * b.aperture;
	return b;
}

BeamLayout explicitBeamLayout(size_t n, double startAngle, double resolution)
{
	BeamLayout b;
	b.resolution = resolution;
	b.startAngle = startAngle;
	b.aperture = resolution * double(n > 0 ? n - 1 : 0);
	b.yawOffset = startAngle + 0.5 * b.aperture;
	return b;
}

}  // namespace gridvector::io
