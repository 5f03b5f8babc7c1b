// Writes scans + odometry as an MRPT rawlog that MRPT's own apps can read.
#pragma once

#include <gridvector/io/LogReader.h>

#include <string>

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

}  // namespace gridvector::io
