// gv-sim's settings (a tool option set, not mapping parameters): command-line
// flags --key (underscores as dashes) and an optional .ini section [gv_sim].
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

namespace gridvector::sim
{
/** An option value SimOptions::validate refuses: which key (as in visit(), with underscores) and why. */
struct SimOptionError : std::invalid_argument
{
	SimOptionError(const std::string& key, const std::string& problem)
		: std::invalid_argument(key + ": " + problem), key(key), problem(problem)
	{}
	std::string key;  //!< e.g. "turn_rate_deg"
	std::string problem;  //!< e.g. "must be in (0, 360]"
};

struct SimOptions
{
	std::string world = "corridor-loop";
	int64_t seed = 1;
	int laps = 0;  //!< 0: the world's default
	int scans = 0;  //!< > 0: exactly this many scans (route repeated or cut)
	int people = -1;  //!< -1: the world's default
	bool doors = true;  //!< doors swing during the run (false: they stay as they start)
	bool movedObject = true;  //!< the object changes place between visits (false: it stays)
	double doorSwingPeriod = 0;  //!< > 0: each door swings every period..2 period s (0: 2-4 swings per run)
	double pauseS = 0;  //!< > 0: pausers stand still pause_s..2 pause_s s (0: 4-15 s)
	double speed = 0.5;
	double turnRateDeg = 45;
	double dt = 0.2;
	int beams = 361;
	double fovDeg = 180;
	double maxRange = 30;
	double rangeSigma = 0.01;
	double sigmaT = 0.05;
	double sigmaR = 0.005;
	double driftDegPerM = 0.8;
	double startTime = 1100000000.0;

	template <class V>
	void visit(V&& v)
	{
		v("world", world, "built-in world: corridor-loop, office, long-corridor");
		v("seed", seed, "random seed (people, doors, laser noise, odometry noise)");
		v("laps", laps, "times the robot drives its route (0: the world's default)");
		v("scans", scans, "exact number of scans, repeating or cutting the route (0: laps decide)");
		v("people", people, "number of walking people (-1: the world's default)");
		v("doors", doors, "doors swing between open and closed during the run");
		v("moved_object", movedObject, "the world's movable object changes place between two visits");
		v("door_swing_period", doorSwingPeriod,
		  "> 0: every door swings again after this to twice this [s] (0: 2-4 swings in the run)");
		v("pause_s", pauseS, "> 0: pausers stand still for this to twice this [s] (0: 4-15 s)");
		v("speed", speed, "robot speed [m/s]");
		v("turn_rate_deg", turnRateDeg, "robot turn rate [deg/s]");
		v("dt", dt, "time between scans [s]");
		v("beams", beams, "laser beams (181/361 over 180 deg; 180/360 as CARMEN's -90..+89)");
		v("fov_deg", fovDeg, "laser field of view [deg]");
		v("max_range", maxRange, "laser max range; no-return beams read this [m]");
		v("range_sigma", rangeSigma, "laser range noise, standard deviation [m]");
		v("sigma_t", sigmaT, "odometry: relative translation noise per step (mkbench model)");
		v("sigma_r", sigmaR, "odometry: rotation noise per step [rad] (mkbench: 0.02 per sparser step)");
		v("drift_deg_per_m", driftDegPerM, "odometry: systematic yaw drift [deg/m]");
		v("start_time", startTime, "timestamp of the first scan [s]");
	}

	/** Throws SimOptionError("key: what is wrong") for an unknown world or an out-of-range value. */
	void validate() const;
};

}  // namespace gridvector::sim
