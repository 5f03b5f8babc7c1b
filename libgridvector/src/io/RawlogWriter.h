// Writes scans + odometry as an MRPT rawlog, and scans at given poses as an MRPT
// simplemap, files that MRPT's own apps can read.
#pragma once

#include <gridvector/io/LogReader.h>

#include <optional>
#include <string>
#include <vector>

namespace gridvector::io
{
enum class RawlogFormat
{
	Observations,  //!< CObservationOdometry + CObservation2DRangeScan per scan (rawlog-grabber style)
	SensoryFrames  //!< CActionCollection(CActionRobotMovement2D) + CSensoryFrame(scan) per scan (rbpf-slam style)
};

struct RawlogWriteOptions
{
	RawlogFormat format = RawlogFormat::Observations;
	bool compress = true;  //!< gzip (level 1), as MRPT writes rawlogs
};

/** Writes log atomically. Odometry observations carry the scan's timestamp;
 * robot-movement actions are the odometry increments between consecutive scans
 * (Gaussian motion model with MRPT's default parameters), the first one zero.
 * Throws "path: cannot write (reason)". */
void writeRawlog(const std::string& path, const LogData& log, const RawlogWriteOptions& opt = {});

/** Writes a gzip mrpt::maps::CSimpleMap atomically: one frame per scan that has a pose
 * (poses[i] for log.scans[i]; scans without one are left out), the pose exact (zero
 * covariance), the frame holding the scan alone. MRPT's pf-localization builds the maps of
 * its `[MetricMap]` section from such a file (`map_file = X.simplemap`). Returns the number
 * of frames. Throws "path: cannot write (reason)", or std::invalid_argument when poses and
 * scans differ in number or no scan has a pose. */
size_t writeSimplemap(const std::string& path, const LogData& log,
					  const std::vector<std::optional<mrpt::math::TPose2D>>& poses);

}  // namespace gridvector::io
