// The ground truth of a graphslam-engine run (-g). MRPT 2.5's CGraphSlamEngine reads the file into a
// vector and indexes it with a counter it advances step by step, without a bounds check: an empty or
// short file, or a ground_truth_file_format it does not read (the vector stays empty), makes its SLAM
// metric (computeSlamMetric) read past the vector's end: a segfault, or garbage figures.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <cstddef>
#include <string>

namespace gridvector::graphslam
{
/** Checks a ground-truth file as CGraphSlamEngine::readGTFile (NavSimul) parses it: every line
 * 't x y theta', numbers separated by single spaces. Returns the number of poses; throws
 * "path:line: ground-truth lines must be ..." on a bad line, "path: no ground-truth poses" on none. */
size_t checkGroundTruthFile(const std::string& path);

/** Throws "iniPath: [GeneralConfiguration] ground_truth_file_format = 'X': ..." unless the engine
 * reads ground truth in that format (NavSimul, any case; its default). */
void requireNavSimulGroundTruth(const mrpt::config::CConfigFileBase& ini, const std::string& iniPath);

/** The engine's ground-truth index (m_GT_poses_index, NavSimul format, step 1), followed outside the
 * engine: it advances after every step of an action/observation rawlog and after every even rawlog
 * entry of an observation-only one (the kind of the first step), and the SLAM metric reads every
 * index it has reached. beforeStep() refuses the step that could read past the file's last pose. */
class GroundTruthIndex
{
   public:
	GroundTruthIndex(std::string path, size_t poses) : path_(std::move(path)), poses_(poses) {}

	/** Before engine._execGraphSlamStep(..., rawlogEntry): throws "path: N ground-truth poses, the
	 * engine reads pose N+1 at entry E of RAWLOG (one pose per scan)" when the index is past the end. */
	void beforeStep(const std::string& rawlog, size_t rawlogEntry) const;
	/** After the step; observation: the step was an observation (not an action/sensory-frame pair). */
	void afterStep(bool observation, size_t rawlogEntry);

	size_t index() const { return index_; }

   private:
	std::string path_;
	size_t poses_ = 0, index_ = 0;
	int observationOnly_ = -1;  //!< -1 until the first step, as the engine decides it
};

}  // namespace gridvector::graphslam
