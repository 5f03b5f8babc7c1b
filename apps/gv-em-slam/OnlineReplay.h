// gv-em-slam --online: the log replayed scan by scan through OnlineEmSlam, as a robot would feed it.
#pragma once

#include "em/EmSlam.h"
#include "extraction/VectorExtractor.h"
#include "io/Progress.h"
#include "mstep/Constraint.h"
#include <gridvector/io/LogReader.h>

#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace gridvector::app
{
struct OnlineReplay
{
	/** Every scan's LocalScan for the self-check (sensorOrigin) and, with `keepVectors`, --refine (V_t);
	 * without, no vectors: OnlineEmSlam keeps the keyframes' own, and a copy of every scan's would be the
	 * run's largest allocation growing with scans (doc/benchmarks.md, "session 16 measurements"). */
	std::vector<LocalScan> scans;
	size_t localVectors = 0;  //!< sum of |V_t| over the scans
	std::vector<mrpt::math::TPose2D> causal;  //!< x_t as known when scan t came in (trajectory_online.txt)
	/** Per scan [s]: vector extraction, OnlineEmSlam::addScan and, where an optimisation was due, its
	 * take and apply (the robot's thread). */
	std::vector<double> latency;
	std::vector<double> latencyCpu;  //!< the same as this thread's CPU time (robust to a loaded machine)
	/** Per optimisation [s]: OnlineEmSlam::runOptimisation (a background thread's on a robot; run here
	 * right after its scan, on the same core, so the replay is deterministic). */
	std::vector<double> background, backgroundCpu;
	std::vector<double> synchronous;  //!< per scan [s]: latency and background together
	/** The live map (OnlineEmSlam::vectors(): every vector's state as the E-step on the sequential map
	 * had it) after the last scan, before finish(): what a robot reads mid-run (vectors_live.txt). */
	std::vector<GridVector> live;
	EmResult result;  //!< the final trajectory and map (after OnlineEmSlam::finish), as the batch's
	MStepReport report;  //!< the online run's registrations and edges
	size_t loopScans = 0, registeredScans = 0;
	double finishSeconds = 0;  //!< OnlineEmSlam::finish and the final map
};

/** Every scan extracted (Sec. 3.1) and given to OnlineEmSlam with its odometry, timed; then finish(),
 * the final map (OnlineEmSlam::finalMap: the batch's, at the online trajectory), doors (Sec. 5.4:
 * leaves dynamic) and the final trajectory in `result`. `keepVectors` (--refine): `scans` keeps every V_t for the
 * batch EM, and `result` gets no final map (the batch builds its own). */
OnlineReplay replayOnline(const io::LogData& log, const std::vector<mrpt::math::TPose2D>& odometry,
						  const VectorExtractor& ex, const GridVectorConfig& cfg, io::Progress& progress,
						  bool keepVectors);

/** report.json's "online" object: latency (median, p99, max in ms, wall clock and thread CPU time),
 * the background optimisations (count, median, max in ms) and both summed per scan, keyframes, edges,
 * and whether
 * --refine ran the batch EM after it. */
std::string onlineJson(const OnlineReplay& r, bool refined);

}  // namespace gridvector::app
