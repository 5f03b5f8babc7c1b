// --init: start EM from a prior trajectory (e.g. gv-graphslam's trajectory.txt).
#pragma once

#include <gridvector/io/LogReader.h>

#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace gridvector::app
{
/** Starting poses for EM: each scan takes its pose of `path` (io::posesAtScans: by position
 * for a per-scan file, else nearest in time within maxDt); a scan with none follows its
 * predecessor by its odometry increment. Throws "PATH: ..." if no scan matches. */
std::vector<mrpt::math::TPose2D> initialTrajectory(const io::LogData& log,
												   const std::vector<mrpt::math::TPose2D>& odometry,
												   const std::string& path, double maxDt = 0.05);
}  // namespace gridvector::app
