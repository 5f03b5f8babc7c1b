// gv-sim's output directory: the CARMEN log the mapper sees and the truth files
// the evaluator compares against (formats documented in doc/simulator.md).
#pragma once

#include "sim/Simulator.h"

#include <string>
#include <vector>

namespace gridvector::sim
{
/** File names inside a simulation directory. */
struct SimFiles
{
	static constexpr const char* log = "sim.log";  //!< CARMEN: PARAM, ODOM, FLASER (poses = noisy odometry)
	static constexpr const char* trajectory = "truth_trajectory.txt";  //!< t x y theta (true)
	static constexpr const char* odometry = "odometry.txt";  //!< t x y theta (as in the log)
	static constexpr const char* labels = "truth_labels.txt";  //!< t n labels, one char per beam
	static constexpr const char* walls = "truth_walls.txt";  //!< x1 y1 x2 y2 static walls/furniture
	static constexpr const char* seenWalls = "truth_seen_walls.txt";  //!< x1 y1 x2 y2 parts hit by static beams
	static constexpr const char* doors = "truth_doors.txt";  //!< hinge_x hinge_y length closed open swings
	static constexpr const char* dynamic = "truth_dynamic.txt";  //!< moved object, door swings, dynamic hits
	static constexpr const char* info = "sim_info.txt";  //!< options and statistics, "key value"
};

/** Writes every file of SimFiles into dir (created if missing), each atomically, sim_info.txt last
 * (gv-sim's output set: a directory with it is complete).
 * Throws "path: cannot write (reason)". */
void writeSimulation(const SimResult& r, const std::string& dir);

struct DoorTruth
{
	Vec2 hinge;
	double length = 0, closedAngle = 0, openAngle = 0;
	int swings = 0;
};

struct DoorSwingTruth
{
	int door = 0;
	double t0 = 0, t1 = 0, from = 0, to = 0;  //!< timestamps [s], angles [rad]
};

struct ObjectEdgeTruth
{
	std::string name;
	bool second = false;  //!< false: its place before the move
	Segment edge;
};

struct Truth
{
	std::vector<Segment> walls, seenWalls;
	std::vector<DoorTruth> doors;
	std::vector<DoorSwingTruth> doorSwings;
	std::vector<ObjectEdgeTruth> objectEdges;
	double objectMoveTime = 0;
	std::vector<HitRun> hits;
};

/** Reads the truth files of a simulation directory; malformed lines throw "file:line: what is wrong". */
Truth readTruth(const std::string& dir);
/** "x1 y1 x2 y2" per line ('#' comments). */
std::vector<Segment> readSegments(const std::string& path);
/** "hinge_x hinge_y length [closed_angle open_angle [swings]]" per line (detected doors need only three columns). */
std::vector<DoorTruth> readDoors(const std::string& path);

}  // namespace gridvector::sim
