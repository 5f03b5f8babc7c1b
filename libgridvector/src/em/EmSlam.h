// Sec. 4, Eq. 11-13: the modified EM-SLAM — E-step (Eq. 14-15) and M-step (Eq. 16-25) alternated.
#pragma once

#include "doors/DoorDetector.h"
#include "doors/DoorExclusion.h"
#include "em/SelfCheck.h"
#include "estep/EStep.h"
#include "map/GlobalMap.h"
#include <gridvector/GridVectorConfig.h>
#include "mstep/MStep.h"
#include "extraction/VectorExtractor.h"

#include <mrpt/math/TPose2D.h>

#include <functional>
#include <vector>

namespace gridvector
{
/** Figures of one EM iteration (Fig. 11: share of constraints changed). */
struct EmIteration
{
	int index = 0;  //!< 1-based
	double changedShare = 0;  //!< constraints added, removed or recomputed / constraints
	size_t changedVectors = 0;  //!< parents whose children (M_chd) changed in the E-step
	size_t staticVectors = 0, dynamicVectors = 0;
	double staticLength = 0, dynamicLength = 0;
	MStepReport mstep;
	double eSeconds = 0, mSeconds = 0;
	double wipeSeconds =
		0;  //!< of eSeconds: the map of the trajectory, Eq. 4 unmerged + Eq. 8 (GlobalMap::buildPerScan)
	double classifySeconds = 0;  //!< of eSeconds: Eq. 14-15 on that map (EStep::run)
	bool eSkipped = false;  //!< no pose moved enough since the last E-step: its result stands
	/** Sec. 5.3 (doors.during_em): doors on this E-step's map, kept out of the next M-step
	 * (of eSeconds: their seconds); all zero with the key off. */
	DoorExclusionFigures doors;
};

struct EmResult
{
	std::vector<mrpt::math::TPose2D> poses;  //!< x_t of every scan
	std::vector<EmIteration> iterations;
	bool converged = false;
	std::vector<GridVector> perScan;  //!< last E-step's children m_{i,t} (global, state set)
	MergeResult staticMap, dynamicMap;  //!< merged static / dynamic vectors (Eq. 4)
	std::vector<GridVector> finalVectors;  //!< staticMap then dynamicMap vectors, state set (door leaves dynamic)
	std::vector<Door> doors;  //!< Sec. 5.4 on finalVectors (Door::leaves, Door::wall index it; a wall cut at a door
							  //!< state keeps its index for its first piece)
	double finalMapSeconds = 0;
	double finalMergeSeconds = 0;  //!< of finalMapSeconds: the final split and the Eq. 4 merges (GlobalMap::mergeAll)
	double doorSeconds = 0;  //!< of finalMapSeconds: Sec. 5.4 and the door-state cuts
	size_t keyframes = 0;  //!< scans EM worked on (the others follow their odometry)
	PoseGraphFit finalGraph;  //!< the last M-step's pose graph at the final trajectory (the self-check's)
};

/** Runs EM: M-step (all vectors static at first, from raw odometry), then
 * E-step on the map built with the new trajectory, until an M-step changes no
 * constraint and the E-step no vector (or mstep.max_iterations). */
class EmSlam
{
   public:
	explicit EmSlam(const GridVectorConfig& cfg = {});

	/** Called after each iteration with its figures and the trajectory. */
	using IterationCallback = std::function<void(const EmIteration&, const std::vector<mrpt::math::TPose2D>&)>;
	/** Progress within an iteration: stage name, iteration, share of the stage done. */
	using ProgressCallback = std::function<void(const char* stage, int iteration, double fraction)>;

	EmResult run(const std::vector<LocalScan>& scans, const std::vector<mrpt::math::TPose2D>& odometry,
				 const IterationCallback& onIteration = {}, const ProgressCallback& progress = {}) const;
	/** EM from `initial` (one pose per scan: the online EM-SLAM's or another system's trajectory) instead of
	 * the odometry; the odometry edges (Eq. 20), the keyframes and the loop-search windows stay the odometry's. */
	EmResult run(const std::vector<LocalScan>& scans, const std::vector<mrpt::math::TPose2D>& odometry,
				 const std::vector<mrpt::math::TPose2D>& initial, const IterationCallback& onIteration = {},
				 const ProgressCallback& progress = {}) const;
	/** The same, the keyframes' scans moved out of `scans` (not copied: the run holds their vectors once). */
	EmResult run(std::vector<LocalScan>&& scans, const std::vector<mrpt::math::TPose2D>& odometry,
				 const std::vector<mrpt::math::TPose2D>& initial, const IterationCallback& onIteration = {},
				 const ProgressCallback& progress = {}) const;

	/** Diagnosis: called after each M-step with the iteration (1-based), the M-step (its
	 * constraints index keyframes), the static vectors it registered (per keyframe, in its
	 * frame) and the scan index of every keyframe. */
	using MStepObserver =
		std::function<void(int iteration, const MStep&, const std::vector<std::vector<MatchSegment>>& statics,
						   const std::vector<size_t>& keyframes)>;
	void setMStepObserver(MStepObserver f) { observer_ = std::move(f); }

	/** Static children of the E-step as registration segments, in their scan's frame (with `scans`, each with its
	 * scan's rangeSigma). */
	static std::vector<std::vector<MatchSegment>> staticSegments(const std::vector<GridVector>& children,
																 const std::vector<mrpt::math::TPose2D>& poses,
																 const std::vector<LocalScan>* scans = nullptr);

	/** Scans EM works on: the first, the last, and each one whose odometry moved
	 * mstep.keyframe_distance or turned mstep.keyframe_rotation_deg since the last. */
	static std::vector<size_t> keyframes(const std::vector<mrpt::math::TPose2D>& odometry, const MStepOptions& o);
	/** keyframes()' rule for one scan: did the odometry move or turn enough since the last keyframe's? */
	static bool isKeyframe(const mrpt::math::TPose2D& lastKeyOdometry, const mrpt::math::TPose2D& odometry,
						   const MStepOptions& o);
	/** Sec. 5.4 on a final map (static then dynamic, ids 1..n): its doors, each leaf state dynamic, and
	 * the stretch of a static wall across a state cut out dynamic (EStep::splitSpans; new pieces appended,
	 * ids n+1..). Returns the doors. */
	static std::vector<Door> doorStates(std::vector<GridVector>& vectors, const EStep& estep, const DoorOptions& opts);
	/** Did a pose of `b` move from `a` by more than the E-step's re-run threshold (half a grid cell,
	 * a degree), or do they differ in length? Below it the map, and so the E-step, barely changes. */
	static bool movedEnough(const std::vector<mrpt::math::TPose2D>& a, const std::vector<mrpt::math::TPose2D>& b);
	/** Poses of all scans from the keyframes' and the odometry in between. */
	static std::vector<mrpt::math::TPose2D> expand(const std::vector<mrpt::math::TPose2D>& keyPoses,
												   const std::vector<size_t>& key,
												   const std::vector<mrpt::math::TPose2D>& odometry);

   private:
	template <class Scans>
	EmResult runOn(Scans&& scans, const std::vector<mrpt::math::TPose2D>& odometry,
				   const std::vector<mrpt::math::TPose2D>& initial, const IterationCallback& onIteration,
				   const ProgressCallback& progress) const;
	EmResult runKeyframes(const std::vector<LocalScan>& scans, const std::vector<mrpt::math::TPose2D>& odometry,
						  const std::vector<mrpt::math::TPose2D>& initial, const IterationCallback& onIteration,
						  const ProgressCallback& progress, const std::vector<size_t>& key) const;

	GridVectorConfig cfg_;
	MStepObserver observer_;
};

}  // namespace gridvector
