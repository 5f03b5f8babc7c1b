// Trajectory accuracy: ATE-RMSE after the best SE(2) alignment and Kuemmerle et
// al. (2009) relation errors, computed exactly as ../shared/bench/evaltraj.py.
#pragma once

#include <gridvector/io/LogReader.h>

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <utility>
#include <vector>

namespace gridvector::eval
{
struct TrajectoryEvalOptions
{
	double maxTimeDiff = 0.05;  //!< estimate matched to a reference pose within this [s]
	double loopDistance = 3.0;  //!< loop pairs: closer than this in the reference [m]
	size_t loopMinSeparation = 20;  //!< ... and at least this many matched poses apart
	size_t maxLoopPairs = 2000;  //!< loop pairs are thinned to every (count / this)-th
};

struct TrajectoryMetrics
{
	size_t matched = 0;
	double ateRmse = 0;  //!< [m]
	double localT = 0, localRDeg = 0;  //!< consecutive pairs: mean |dt| [m], mean |dr| [deg]
	size_t localPairs = 0;
	double loopT = 0, loopRDeg = 0;  //!< loop pairs (NaN if none)
	size_t loopPairs = 0;
};

/** (estimate, reference) pose pairs, in the reference's order. */
using PosePairs = std::vector<std::pair<mrpt::math::TPose2D, mrpt::math::TPose2D>>;

/** For every reference pose, the estimate nearest in time within maxTimeDiff, if any (evaltraj.py's
 * matching: of the two estimates around the reference time, the nearer; the first of equal times). */
PosePairs matchByTimestamp(const io::Trajectory& est, const io::Trajectory& ref, double maxTimeDiff);

struct PoseMatch
{
	PosePairs pairs;
	std::vector<double> times;  //!< the reference time of each pair
	bool byOrder = false;  //!< est[i] with ref[i]
	std::string why;  //!< byOrder: the time shared by different poses ("365 estimate poses share t = ... and differ")
};

/** gv-eval traj's matching: matchByTimestamp, unless matching by time is ambiguous, i.e. the estimate
 * nearest in time to some reference pose shares its time with a different estimate pose (csail-corrected
 * prints six digits: 365 of its 406 scans at one time, all matched to one of them). Then by order when
 * estimate and reference have one pose per scan of the same log: as many poses, the i-th within
 * maxTimeDiff of each other in time (gv-em-slam's trajectory.txt against the log's own poses); otherwise
 * throws std::runtime_error("N estimate poses share t = T and differ: ..."). */
PoseMatch matchPoses(const io::Trajectory& est, const io::Trajectory& ref, double maxTimeDiff);

/** The metrics of matched pairs. Throws std::runtime_error("too few matched poses (n)") when fewer than 3. */
TrajectoryMetrics evaluatePairs(const PosePairs& pairs, const TrajectoryEvalOptions& opt = {});

/** evaluatePairs(matchByTimestamp(est, ref, opt.maxTimeDiff), opt): evaltraj.py's figures. */
TrajectoryMetrics evaluateTrajectory(const io::Trajectory& est, const io::Trajectory& ref,
									 const TrajectoryEvalOptions& opt = {});

/** The rigid transform (x, y, phi) that best maps the estimates' positions onto the
 * references' (the alignment of the ATE): p_ref ~ R(phi) p_est + (x, y). Used to bring an
 * estimated map into the truth's frame. Throws std::runtime_error("too few matched poses (n)") below 3 pairs. */
mrpt::math::TPose2D alignmentTransform(const PosePairs& pairs);

/** alignmentTransform(matchPoses(est, ref, maxTimeDiff).pairs): gv-eval traj's matching rule. */
mrpt::math::TPose2D alignmentTransform(const io::Trajectory& est, const io::Trajectory& ref, double maxTimeDiff = 0.05);

/** Localisation error: the estimate is in the reference's frame (a robot localised on a map built in
 * that frame), so nothing is aligned. */
struct LocalizationMetrics
{
	size_t matched = 0;
	double rmse = 0;  //!< translation RMSE over all matched poses [m]
	double finalT = 0, finalRDeg = 0;  //!< error of the last matched pose [m], [deg]
	bool converged = false;  //!< the last pose's error is below the threshold
	double firstBelow =
		NAN;  //!< seconds from the first matched pose to the first one whose error is below the threshold
	double convergedAfter =
		NAN;  //!< seconds from the first matched pose to the first one from which every error stays below the threshold
	double rmseAfter = NAN, maxAfter = NAN;  //!< translation RMSE and maximum from that pose on [m]
};

/** The metrics of matched pairs (times: the reference time of each, as PoseMatch::times); converged
 * means below `threshold` metres. Throws std::runtime_error("too few matched poses (n)") when fewer than 3. */
LocalizationMetrics evaluateLocalization(const PosePairs& pairs, const std::vector<double>& times, double threshold);

std::string formatText(const LocalizationMetrics& m);
nlohmann::ordered_json toJson(const LocalizationMetrics& m);  //!< gv-eval traj --absolute --json

/** evaltraj.py's output line: "n=... ate_rmse_m=... rel_local_t_m=... ...". */
std::string formatText(const TrajectoryMetrics& m);
nlohmann::ordered_json toJson(
	const TrajectoryMetrics& m);  //!< gv-eval traj --json (keys in this order; a non-finite figure is null when dumped)

}  // namespace gridvector::eval
