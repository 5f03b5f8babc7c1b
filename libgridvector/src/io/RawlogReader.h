// MRPT rawlogs in both formats (actions + sensory frames, and observation-only
// as written by rawlog-grabber), plain or gzip-compressed.
#pragma once

#include <gridvector/io/LogReader.h>

#include <string>
#include <vector>

namespace gridvector::io
{
/** Reads the 2D laser scans of a rawlog.
 *
 * Odometry: from CObservationOdometry readings (interpolated at each scan's
 * time) if the rawlog has any, else the running sum of the CActionRobotMovement2D
 * increments (raw odometry increment if present, else the mean of poseChange)
 * up to the sensory frame. logPose is never set. Truncated or corrupt files throw
 * "file: entry N: what is wrong". */
LogData readRawlog(const std::string& path, const ReadOptions& opt = {});

/** The same for rawlog bytes in memory (already gunzipped). */
LogData parseRawlog(const std::vector<char>& bytes, const std::string& source, const ReadOptions& opt = {});

}  // namespace gridvector::io
