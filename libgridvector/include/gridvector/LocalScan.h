// Sec. 3.1: V_t, the grid vectors of one scan in the robot frame (what extraction gives).
#pragma once

#include <gridvector/GridVector.h>

#include <mrpt/math/TPoint2D.h>

#include <cstdint>
#include <vector>

namespace gridvector
{
/** V_t: the local map of one scan, in the robot frame. */
struct LocalScan
{
	std::vector<GridVector> vectors;  //!< v_{i,t}, robot frame, open space on the left
	mrpt::math::TPoint2D sensorOrigin{0, 0};  //!< apex of the wipe triangles (robot frame)
	int64_t scanIndex = -1;  //!< t
	double timestamp = 0;
	size_t validBeams = 0;  //!< beams that returned a usable range
	/** The scanner's range std. dev. (its stdError; 0 if unknown): the floor of a registration's residual
	 * (VectorMatcher), Eq. 8's hit band widened by its allowance (ScanWipe::hitBandFor) [m]. */
	double rangeSigma = 0;
};

}  // namespace gridvector
