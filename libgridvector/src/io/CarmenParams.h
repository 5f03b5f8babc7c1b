// CARMEN PARAM lines that describe the lasers, and how CARMEN's beam layout maps
// onto MRPT's symmetric CObservation2DRangeScan.
#pragma once

#include "io/TextParsing.h"

#include <cstddef>
#include <optional>
#include <string_view>

namespace gridvector::io
{
/** Coarsest angular resolution a laser PARAM may give [deg]. */
constexpr double kMaxResolutionDeg = 180.0;

/** What PARAM lines said about one laser (unset: not given in the log). */
struct CarmenLaserParams
{
	std::optional<double> resolutionDeg;  //!< laser_*_laser_resolution [deg]
	std::optional<double> fovDeg;  //!< laser_*_laser_fov (radians if <= 2*pi+0.01 in the log, else degrees)
	std::optional<double> maxRange;  //!< robot_*_laser_max [m]
	double offsetX = 0;  //!< robot_*laser_offset, along the robot's x (negated for the rear laser) [m]
	double offsetY = 0;  //!< robot_*laser_side_offset [m]
	double offsetYaw = 0;  //!< robot_*laser_angular_offset [rad]
	bool flipped = false;  //!< laser_*_laser_flipped: beams run right to left
};

/** The laser-related PARAM lines of a CARMEN log (others are ignored). */
class CarmenParams
{
   public:
	/** Applies "PARAM name value"; true if it was a laser parameter. A laser
	 * parameter with an unusable value is an error at pos. */
	bool apply(std::string_view name, std::string_view value, const TextPos& pos);
	const CarmenLaserParams& front() const { return front_; }
	const CarmenLaserParams& rear() const { return rear_; }

   private:
	CarmenLaserParams front_, rear_;
};

/** CARMEN numbers beams from startAngle in steps of resolution; MRPT spreads
 * them symmetrically over aperture around the sensor's yaw. All in radians. */
struct BeamLayout
{
	double startAngle = 0;  //!< angle of beam 0 relative to the laser
	double resolution = 0;  //!< angle between neighbouring beams
	double aperture = 0;  //!< resolution * (n - 1)
	double yawOffset = 0;  //!< startAngle + aperture / 2: MRPT sensor yaw for the same beam angles
	bool resolutionInferred = false;  //!< no PARAM: guessed from the beam count
};

/** Layout of an n-beam FLASER/RLASER: resolution from PARAM, else 1 deg for
 * 180/181 beams, 0.5 deg for 360/361, 0.25 deg for 720/721, else FOV/(n-1);
 * field of view from PARAM, else resolution * (n-1) for odd n and resolution * n
 * for even n (CARMEN's 180-beam scans run from -90 to +89 deg); startAngle = -FOV/2. */
BeamLayout carmenBeamLayout(size_t n, const CarmenLaserParams& p);

/** Layout of a message that states it (ROBOTLASER1, RAWLASERx): start and resolution in radians. */
BeamLayout explicitBeamLayout(size_t n, double startAngle, double resolution);

}  // namespace gridvector::io
