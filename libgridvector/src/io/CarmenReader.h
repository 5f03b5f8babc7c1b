// CARMEN logs (.log/.clf, plain or gzip): FLASER, RLASER, ROBOTLASER1/2,
// RAWLASER1-4, ODOM and the laser PARAM lines, parsed here rather than with MRPT
// 2.5's carmen_log_parse_line, which stamps every scan with the same time and
// gives 180-beam scans a 90 deg aperture.
#pragma once

#include <gridvector/io/LogReader.h>

#include <string>
#include <vector>

namespace gridvector::io
{
/** Largest real reading of a SICK LMS in cm mode; 81.83..81.91 m are its error codes. */
constexpr double kSickErrorCodeRange = 81.83;

/** Reads a CARMEN log file. Every malformed line throws "file:line: what is wrong".
 *
 * - FLASER/RLASER: logPose = the first pose (laser pose; SLAM-corrected in
 *   *-corrected logs), odometry = the second pose; RLASER looks backwards.
 * - ROBOTLASER1/2: logPose = odometry = robot pose, sensorPose = laser pose
 *   relative to it; start angle, FOV, resolution, max range from the message.
 * - RAWLASER1-4: no pose in the message: odometry interpolated from ODOM lines.
 * - Beam layout: see carmenBeamLayout(). Max range: PARAM robot_*_laser_max, the
 *   message's own field, else the largest reading in the log capped at 81.83 m
 *   (the sensor's "no return" value). Beams are valid iff 0 < range < maxRange;
 *   negative, NaN or infinite ranges are errors.
 * - Other message types (NEFF, SYNC, TRUEPOS, ...) are counted in the summary. */
LogData readCarmenLog(const std::string& path, const ReadOptions& opt = {});

/** Whether a FLASER/RLASER line announcing `beams` ranges has `fields` fields (its name included):
 * the ranges, the laser pose, the odometry pose, then 'ipc_timestamp ipc_hostname logger_timestamp'
 * or a single timestamp. A wrong beam count shifts every later field, so any other count is an error. */
bool flaserFieldCountMatches(size_t beams, size_t fields);

/** The same for CARMEN text in memory; source names it in messages. */
LogData parseCarmenLog(const std::vector<char>& text, const std::string& source, const ReadOptions& opt = {});

}  // namespace gridvector::io
