// gv-em-slam's output files (all written atomically).
#pragma once

#include "doors/DoorDetector.h"
#include "em/EmSlam.h"
#include "em/SelfCheck.h"
#include "map/MemoryAccounting.h"

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace gridvector::app
{
/** `x1 y1 x2 y2 p_static static|dynamic` per vector. */
void writeVectors(const std::string& path, const std::vector<GridVector>& vectors);
/** Static blue, dynamic red, doors green (hinge dot, one line per leaf state), path grey. */
void writeSvg(const std::string& path, const std::vector<GridVector>& vectors, const std::vector<Door>& doors,
			  const std::vector<mrpt::math::TPose2D>& poses);
/** `hinge_x hinge_y length angle_min angle_max states` per door (angles in rad). */
void writeDoors(const std::string& path, const std::vector<Door>& doors);
/** Every state of every door with its wall as detected and its leaves (Sec. 5.4, Fig. 10), for
 * diagnostics (bench/em-slam/door_evidence.py): `hinge_x hinge_y length angle_min angle_max states
 * | W x1 y1 x2 y2 | leaf indices into vectors.txt | A state directions in degrees`. */
void writeDoorStates(const std::string& path, const std::vector<Door>& doors);
/** Debugging aid (GV_EM_DEBUG_DIR, bench/em-slam/edge_errors.py): one registration edge a line in scan
 * indices (`key`: each keyframe's scan): from to kind rejected dof degeneracy rms matched_length
 * correspondences z.x z.y z.phi and the upper triangle of `information(c)`, the information the pose
 * graph uses (I00 I01 I02 I11 I12 I22, in the frame of Eq. 21's error); false if it cannot be written. */
bool writeEdgeDump(const std::string& path, const std::map<EdgeKey, Constraint>& edges, const std::vector<size_t>& key,
				   const std::function<Eigen::Matrix3d(const Constraint&)>& information);
/** mrpt::maps::CGridVectorMap holding `vectors`, gzip-serialised. */
void writeGvmap(const std::string& path, const GridVectorConfig& cfg, const std::vector<GridVector>& vectors);

/** Everything report.json holds. */
struct RunFigures
{
	std::string input;
	std::string init;  //!< --init's trajectory file; empty: raw odometry
	size_t scans = 0, localVectors = 0;
	double readSeconds = 0, extractSeconds = 0, emSeconds = 0, outputSeconds = 0, totalSeconds = 0;
	size_t doors = 0;
	MemoryReport memory;
	std::string configJson;  //!< the full effective configuration (GridVectorConfig::toJson)
	std::string onlineJson;  //!< --online's figures (a JSON object); empty: a batch run
	SelfCheckEvidence selfCheck;
	SelfCheckVerdict verdict;
};
/** report.json (io::writeJsonFile: keys in this order, dump(2), a non-finite number as null);
 * `config` is run.configJson parsed, so it is one JSON tree with the rest. */
void writeReport(const std::string& path, const RunFigures& run, const EmResult& res);

}  // namespace gridvector::app
