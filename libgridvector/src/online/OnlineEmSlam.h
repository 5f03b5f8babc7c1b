// Sec. 6's future work, "sequential mode, which allows a robot to incrementally estimate the dynamic
// objects and the most likely map while walking through the environment": EM-SLAM scan by scan.
#pragma once

#include "doors/Door.h"
#include "mstep/ConstraintSet.h"
#include "mstep/GraphOptimisation.h"
#include "mstep/LoopClosure.h"
#include "mstep/LoopSearch.h"
#include "mstep/OverlapEdges.h"
#include "mstep/PairRegistration.h"
#include "mstep/PassFinder.h"
#include "online/ClassifiedMap.h"

#include <gridvector/GridVectorConfig.h>
#include <gridvector/LocalScan.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>

#include <memory>
#include <vector>

namespace gridvector::online
{
/** What one OnlineEmSlam::addScan did. */
struct OnlineStep
{
	mrpt::math::TPose2D pose;  //!< x_t as known now
	bool registered = false;  //!< the pose came from a registration (else from the odometry alone)
	bool keyframe = false;  //!< the scan became a node of the pose graph and went into the map
	size_t loops = 0;  //!< loop edges this scan added (after the consistency check)
	std::vector<EdgeKey> edges;  //!< the registration edges (j, i) the keyframe i added, after the check
	bool optimised = false;  //!< a loop edge made an optimisation of the pose graph due (Eq. 22, see takeOptimisation)
	size_t classified = 0;  //!< map vectors whose cells the scan changed (Eq. 8; Eq. 14-15 redone for them when asked)
	size_t reanchored = 0;  //!< keyframes re-inserted into the map being re-anchored
};

/** Online EM-SLAM: one scan (its vectors V_t, Sec. 3.1) and its odometry at a time.
 *
 * Per scan: the pose now, registered (Sec. 4.2, VectorMatcher) against the last keyframe from the
 * odometry guess. Per keyframe (EmSlam::isKeyframe, as the batch's): sequential edges to its
 * mstep.sequential_window predecessors (PairRegistration), for every earlier pass near it that the
 * batch registers into (the first and the most recent, PassFinder::registeredPass) an overlap edge where the estimate already links the passes (Sec. 4.3, OverlapEdges) or else a loop
 * search in the window of the odometry model (LoopSearch), the new edges checked for consistency
 * (verifyOverlaps); then the scan's vectors added to the map with Eq. 8's full product updated both
 * ways and the E-step (Eq. 14-15) on the vectors that changed (ClassifiedMap: the batch E-step's map
 * and verdicts, scan by scan). A loop edge kept makes Eq. 22 on the whole graph due
 * (GraphOptimisation): the one step whose cost grows with the map. It runs outside addScan, in
 * three parts so that a robot can give the middle one to a background thread: takeOptimisation()
 * (a copy of the graph), runOptimisation() (the solve) and applyOptimisation() (the corrected
 * keyframes, those added meanwhile carried along). When that moved a pose by more than
 * EmSlam::movedEnough's threshold, the map is rebuilt at the corrected poses kReanchorPerScan
 * keyframes per scan, and replaces the live map when it has caught up. So addScan's cost is that
 * of the robot's surroundings: the keyframes of every pass through them (ClassifiedMap).
 *
 * Registrations use every vector of a keyframe as it was extracted: the batch's first M-step
 * (before any E-step); EmSlam from trajectory() refines them (gv-em-slam --online --refine). */
class OnlineEmSlam
{
   public:
	/** The map being re-anchored takes this many keyframes per scan: its cost per scan stays that
	 * of a few insertions, and it catches up with a robot that adds at most one keyframe a scan. */
	static constexpr size_t kReanchorPerScan = 2;

	/** finish() searches the whole trajectory for edges (overlap, loop) and re-optimises at most this
	 * often: the first round finds what the estimate at the time hid; later ones find little. */
	static constexpr int kClosingRounds = 2;

	explicit OnlineEmSlam(const GridVectorConfig& cfg = {});
	OnlineEmSlam(const OnlineEmSlam&) = delete;  // its parts refer to its members
	OnlineEmSlam& operator=(const OnlineEmSlam&) = delete;

	/** One scan: `scan` in the robot frame, `odometry` the dead-reckoning pose it was taken at. */
	OnlineStep addScan(const LocalScan& scan, const mrpt::math::TPose2D& odometry);
	/** End of the run: a last optimisation, the batch M-step's edge search over the whole trajectory
	 * and Eq. 22 again (kClosingRounds), and the map re-anchored to the result at once. The search's
	 * edges join passes the run left unlinked, so they are loop closures: where one is far from the
	 * estimate (farFromEstimate), Eq. 22 graduates its kernel as for a far loop-search edge (else the
	 * kernel at its final width down-weights and the chi2 test rejects every edge of the place, and
	 * the drift the run left there stays). */
	void finish();

	/** Eq. 22 over a copy of the graph, made by takeOptimisation(), solved by runOptimisation(). */
	struct Optimisation
	{
		Poses poses, odometry;  //!< keyframes when taken; poses: out the optimised ones
		std::map<EdgeKey, Constraint> edges;
		MStepReport report;
		bool graduate = false;  //!< the robust kernel starts wide (PoseGraph::optimize): finish()'s, see there
	};
	/** Is an optimisation due (a loop edge since the last one was taken)? */
	bool optimisationDue() const { return due_; }
	/** takeOptimisation, runOptimisation, applyOptimisation in turn, on this thread (`graduate`: Optimisation's). */
	void optimise(bool graduate = false);
	/** The graph as it is now, to optimise; no longer due. */
	Optimisation takeOptimisation();
	/** The solve (GraphOptimisation: Eq. 22, the chi2 rejections). May run on another thread while
	 * addScan() runs; one at a time, applied in the order taken. */
	void runOptimisation(Optimisation& job);
	/** The job's poses for its keyframes, the later ones moved with the last of them, its rejections;
	 * starts the map's re-anchoring if poses moved. */
	void applyOptimisation(const Optimisation& job);

	size_t scans() const { return odometry_.size(); }
	/** x_t of the last scan. */
	mrpt::math::TPose2D currentPose() const;
	/** Every scan at the current estimate (keyframes from the graph, the others by EmSlam::expand). */
	std::vector<mrpt::math::TPose2D> trajectory() const;
	/** Scan index of every keyframe. */
	const std::vector<size_t>& keyframes() const { return keyScan_; }
	/** Every keyframe's pose (the graph's nodes) as estimated now. */
	const Poses& keyframePoses() const { return keyPose_; }
	/** Every keyframe's odometry (Eq. 22's odometry edges join consecutive ones). */
	const Poses& keyframeOdometry() const { return keyOdo_; }

	/** The map with every keyframe's vectors and their state (Eq. 14) as the batch E-step has them
	 * after the scans so far (ClassifiedMap: stateOf() per vector, at once). */
	const ClassifiedMap& map() const { return *live_; }
	/** The batch's final map from the live E-step, at any time (O(map): a query, not per scan): the
	 * children split at the final threshold and merged per state (SplitMap::of), then Sec. 5.4's doors
	 * (EmSlam::doorStates: leaf states dynamic, a wall cut across a state), as the batch; static then
	 * dynamic. `doors`: the doors found. */
	std::vector<GridVector> vectors(std::vector<Door>* doors = nullptr) const;
	std::vector<GridVector> staticMap() const;
	std::vector<GridVector> dynamicVectors() const;
	/** vectors() at the current trajectory, for the end of a run: the live map's when it is built at the
	 * current keyframe poses, else Eq. 8's full product recomputed there (GlobalMap::buildPerScan, EStep::run). */
	std::vector<GridVector> finalMap(std::vector<Door>* doors = nullptr) const;
	/** The static map as an occupancy grid (OccupancyConversion, occupancy.* keys). */
	mrpt::maps::COccupancyGridMap2D occupancyGrid() const;

	const std::map<EdgeKey, Constraint>& constraints() const { return book_.edges; }
	const PoseGraph& graph() const { return optimiser_.graph(); }
	/** The registrations, edges and last optimisation of the run so far, as one M-step's figures. */
	MStepReport report() const;

   private:
	/** The pose of a scan from the last keyframe: its registration from the odometry guess fused with that odometry
	 * (the guess alone when the registration fails or the motion model rules it out). */
	mrpt::math::TPose2D poseNow(const std::vector<MatchSegment>& segs, const mrpt::math::TPose2D& odometry,
								bool& registered) const;
	/** Keyframe i's sequential edges to its `w` predecessors and its pose fused from them and the odometry. */
	mrpt::math::TPose2D sequentialPose(uint32_t i, uint32_t w);
	/** A new keyframe's edges (sequential, overlap, loop), those kept into `st` (edges, loops). */
	void addEdges(uint32_t i, OnlineStep& st);
	/** Does one of these edges need a correction of the estimate that makes PoseGraph graduate its
	 * kernel for a loop-search edge (chi2 at keyPose_ above posegraph.graduation_trigger x Phi)? */
	bool farFromEstimate(const std::vector<EdgeKey>& keys) const;
	/** Is the overlap edge (from, to) aliased along its weak direction within its passes' loop-search window? */
	bool aliased(uint32_t from, uint32_t to, const Constraint& c) const;
	/** Up to `n` keyframes into the map being re-anchored; swaps it in when it has caught up. */
	size_t reanchor(size_t n);

	GridVectorConfig cfg_;
	ProgressFn progress_;  // none: the parts report no progress
	ConstraintSet book_;
	PairRegistration reg_;
	OverlapEdges overlaps_;
	LoopClosure loopClosure_;
	LoopSearch loopSearch_;
	PassFinder passes_;
	GraphOptimisation optimiser_;

	Scans segs_;  //!< per keyframe: its vectors for registration, in its frame
	std::vector<LocalScan> keyScans_;
	Poses keyOdo_, keyPose_;
	std::vector<size_t> keyScan_;
	Poses odometry_;  //!< every scan's
	mrpt::math::TPose2D lastPose_;
	bool due_ = false;
	uint64_t nextSegmentId_ = 1;
	MStepReport rep_;

	std::unique_ptr<ClassifiedMap> live_, next_;  //!< the map, the one being re-anchored
	Poses liveAt_, nextAt_;  //!< the keyframe poses each was built at
};

}  // namespace gridvector::online
