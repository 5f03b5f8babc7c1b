// Input logs (CARMEN .log/.clf and MRPT .rawlog, plain or gzip) as a list of
// laser scans with odometry, and "t x y theta" trajectory files.
#pragma once

#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace gridvector::io
{
/** One laser scan of a log with what the log says about the robot at that time. */
struct ScanRecord
{
	double timestamp = 0;  //!< seconds, the log's real timestamp
	/** aperture, rightToLeft, maxRange, sensorPose, per-beam validity set correctly */
	mrpt::obs::CObservation2DRangeScan::Ptr scan;
	mrpt::math::TPose2D odometry;  //!< robot odometry pose at the scan's time (dead reckoning)
	bool hasOdometry = false;
	/** The pose the log attaches to the scan (CARMEN FLASER's first pose:
	 * SLAM-corrected in *-corrected logs). */
	mrpt::math::TPose2D logPose;
	bool hasLogPose = false;
};

/** What a log file holds besides the scans kept, counted by the reader. */
struct LogContents
{
	enum class Format
	{
		Carmen,
		Rawlog
	} format = Format::Carmen;
	size_t odometryRecords = 0;  //!< CARMEN ODOM lines; rawlog CObservationOdometry objects
	size_t paramLines = 0;  //!< CARMEN PARAM lines
	size_t actionSets = 0, sensoryFrames = 0;  //!< rawlog: actions+sensory-frames format when sensoryFrames > 0
	size_t observations = 0;  //!< rawlog: observations outside sensory frames (observation-only format)
	bool movementActions = false;  //!< rawlog: robot-movement actions (the odometry when there are no odometry objects)
	std::map<std::string, size_t> ignored;  //!< what was passed over, by CARMEN message or MRPT class
};

/** The contents in words, as the readers' summaries give them: CARMEN "14541 ODOM, 3 PARAM, 910 NEFF
 * ignored"; rawlog "actions+sensory-frames format (250 action sets, 250 sensory frames); odometry from
 * robot-movement actions, 250 mrpt::obs::CObservationBearingRange ignored". */
std::string describeContents(const LogContents& c);

struct LogData
{
	std::vector<ScanRecord> scans;
	std::string source;  //!< the path read
	LogContents contents;  //!< what else the file holds
	std::string summary;  //!< one line: what was read (counts, laser geometry, contents, warnings)
	std::vector<std::string> warnings;  //!< oddities that are not errors (also in summary)
	double noReturnRange = 0;  //!< > 0: the scanner's no-return value found and applied (ReadOptions)
};

struct ReadOptions
{
	bool quiet = true;  //!< false: progress on stderr when it is a terminal
	bool includeRearLaser = true;  //!< CARMEN RLASER / RAWLASER2 scans
	std::string sensorLabel;  //!< rawlogs: keep only scans with this label (empty: all)
	/** CARMEN: a spike of readings at the top of the ranges, one value shared exactly by >= 1 % of the scans
	 * and by >= 10 of them, is the scanner's "no return" code (ACES: 50.00 m under a declared 81 m; codes
	 * that jitter, 51.06-51.16 m), and every scan's maxRange becomes it (NoReturnRange.h); a warning says so. */
	bool detectNoReturnRange = true;
};

/** Detects CARMEN (.log/.clf, optionally .gz) vs MRPT rawlog (.rawlog, optionally
 * gz-compressed; both the actions+sensory-frames and the observation-only format).
 * Throws std::runtime_error("file:line: what is wrong"). */
LogData readLog(const std::string& path, const ReadOptions& opt = {});

/** Throws "path: no laser scans (describeContents)" if log has no scan: e.g.
 * "kf-slam_demo.rawlog: no laser scans (actions+sensory-frames format (...), 120 CObservationBearingRange ignored)". */
void requireScans(const LogData& log);

using Trajectory = std::vector<std::pair<double, mrpt::math::TPose2D>>;

/** Trajectory files "t x y theta" (one pose per line, '#' comments, extra columns ignored). */
Trajectory readTrajectory(const std::string& path);
/** The pose of `traj` (read from `source`) for each scan of `log`. A trajectory with one pose per
 * scan, in the log's order and within maxDt of each scan's time (gv-em-slam's and gv-graphslam's
 * trajectory.txt), is matched by position, so logs with repeated timestamps (csail-corrected prints
 * six digits) get their own poses back; otherwise each scan takes the pose nearest in time within
 * maxDt (none: unset). Throws "source: ..." if that nearest time is shared by poses that differ
 * (matching by time would pick one of them arbitrarily). */
std::vector<std::optional<mrpt::math::TPose2D>> posesAtScans(const LogData& log, const Trajectory& traj,
															 const std::string& source, double maxDt = 0.05);
/** Writes "t x y theta" lines (%.6f), atomically. */
void writeTrajectory(const std::string& path, const Trajectory& traj);

/** The odometry (or, with logPose=true, the log's own pose) of every scan that has one. */
Trajectory trajectoryOf(const LogData& log, bool logPose = false);

}  // namespace gridvector::io
