// Dead-reckoning odometry synthesised from a true trajectory with the noise
// model of ../shared/bench/mkbench.py (used by gv-sim and gv-bench-log).
#pragma once

#include "sim/Random.h"

#include <mrpt/math/TPose2D.h>

#include <optional>

namespace gridvector::sim
{
struct OdometryNoiseOptions
{
	double sigmaT = 0.05;  //!< relative translation noise: each step's (dx, dy) is scaled by 1 + N(0, sigmaT)
	double sigmaR = 0.02;  //!< rotation noise added to each step's dtheta [rad]
	double driftDegPerM = 0.8;  //!< systematic yaw drift per metre travelled [deg/m]
};

/** mkbench.py's model: for consecutive true poses, the relative motion (dx, dy,
 * dtheta) in the previous pose's frame becomes k*(dx, dy), dtheta + N(0, sigmaR)
 * + drift*|(dx, dy)| with k = 1 + N(0, sigmaT), compounded onto the odometry
 * pose, which starts at (0, 0, 0). Random draws happen in mkbench's order. */
class NoisyOdometry
{
   public:
	NoisyOdometry(const OdometryNoiseOptions& opt, Random& rng) : opt_(opt), rng_(rng) {}
	/** Feeds the next true pose; returns the odometry pose at it. */
	mrpt::math::TPose2D step(const mrpt::math::TPose2D& truePose);

   private:
	OdometryNoiseOptions opt_;
	Random& rng_;
	std::optional<mrpt::math::TPose2D> prev_;
	double ox_ = 0, oy_ = 0, oth_ = 0;
};

/** atan2(sin a, cos a), as mkbench.py's wrap(). */
double wrapAngle(double a);

}  // namespace gridvector::sim
