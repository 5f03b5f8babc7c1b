// gv-sim's engine: a robot driving a built-in world among walking people,
// swinging doors and a moved object, with a 2D laser and noisy odometry; every
// beam's truth is kept.
#pragma once

#include "sim/Laser.h"
#include "sim/SimOptions.h"
#include "sim/World.h"

#include <mrpt/math/TPose2D.h>

#include <functional>
#include <string>
#include <vector>

namespace gridvector::sim
{
/** A door's angle over the run: smooth swings between closed and (partly) open. */
struct DoorTimeline
{
	struct Swing
	{
		double t0, t1, from, to;  //!< run time [s] (0 = first scan), leaf angles [rad]
	};
	double initial = 0;
	std::vector<Swing> swings;
	double angleAt(double t) const;
};

struct SimScan
{
	double t = 0;
	mrpt::math::TPose2D truth;  //!< true robot (= laser) pose
	mrpt::math::TPose2D odometry;  //!< noisy dead reckoning, what the log shows
	std::vector<float> ranges;
	std::string labels;  //!< one labelChar() per beam
};

/** Consecutive beams of one scan that hit the same dynamic thing: first to last true hit point. */
struct HitRun
{
	HitKind kind = HitKind::None;
	int id = -1;
	double t = 0;
	Segment seg;
	int beams = 0;
};

struct SimStats
{
	size_t scans = 0, beams = 0, staticHits = 0, dynamicHits = 0, noHits = 0;
	size_t personHits = 0, doorHits = 0, objectHits = 0;
	size_t people = 0, doorSwings = 0;
	double pathLength = 0;  //!< true path [m]
	double duration = 0;  //!< [s]
	double dynamicShare() const { return beams ? double(dynamicHits) / double(beams) : 0.0; }
};

struct SimResult
{
	World world;  //!< as simulated (static if doors/objects were disabled)
	SimOptions options;
	LaserOptions laser;
	double laserResolution = 0;  //!< [rad]
	std::vector<SimScan> scans;
	std::vector<DoorTimeline> doors;  //!< parallel to world.doors
	double objectMoveTime = 0;  //!< run time at which every movable object jumps to its second place
	std::vector<HitRun> dynamicHits;
	std::vector<Segment> seenWalls;  //!< parts of static walls hit by static beams (gaps < 0.25 m bridged)
	SimStats stats;
};

/** Runs the simulation: deterministic for given options (seed included).
 * progress(fraction) is called now and then. Throws std::invalid_argument for bad options. */
SimResult simulate(const SimOptions& opt, const std::function<void(double)>& progress = {});

}  // namespace gridvector::sim
