// The robot's true motion: a differential-drive robot following the world's
// route, turning on the spot at corners.
#pragma once

#include "sim/Geometry.h"

#include <mrpt/math/TPose2D.h>

#include <vector>

namespace gridvector::sim
{
struct MotionOptions
{
	double speed = 0.5;  //!< [m/s]
	double turnRateDeg = 45;  //!< [deg/s]
	double dt = 0.2;  //!< time between scans [s]
};

/** True poses every dt seconds, starting at `start`, driving the (closed) route
 * `laps` times. With maxSteps > 0 the result has exactly maxSteps poses: the
 * route is repeated or cut as needed. The robot turns on the spot towards the
 * next waypoint, then drives straight to it. */
std::vector<mrpt::math::TPose2D> followRoute(const mrpt::math::TPose2D& start, const std::vector<Vec2>& route, int laps,
											 const MotionOptions& m, size_t maxSteps = 0);

}  // namespace gridvector::sim
