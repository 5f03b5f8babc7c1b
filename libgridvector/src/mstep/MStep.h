// Sec. 4.2-4.3, Eq. 16-25: the maximisation step — pose-graph SLAM over static vectors.
#pragma once

#include "mstep/Constraint.h"
#include "mstep/ConstraintSet.h"
#include "mstep/GraphOptimisation.h"
#include "mstep/LoopClosure.h"
#include "mstep/OverlapEdges.h"
#include "mstep/PairRegistration.h"
#include "mstep/SequentialChain.h"

#include <gridvector/GridVectorConfig.h>

namespace gridvector
{
/** One M-step after another: builds and maintains the registration edges between scans and optimises
 * the pose graph (odometry edges + registrations, Eq. 21-22).
 *
 * First call (from raw odometry): the sequential chain (SequentialChain) removes local drift. Every call:
 * overlap edges (OverlapEdges), the loop search (LoopClosure), their pairwise consistency check
 * (verifyOverlaps), the constraint selection of Eq. 24-25 (updateConstraints: an edge is re-registered
 * only when its data association changed) and the optimisation (GraphOptimisation). */
class MStep
{
   public:
	explicit MStep(const GridVectorConfig& cfg = {});
	MStep(const MStep&) = delete;  // its parts refer to its members
	MStep& operator=(const MStep&) = delete;

	/** Dead-reckoning pose of every scan (the odometry edges). */
	void setOdometry(std::vector<mrpt::math::TPose2D> odometry);
	/** The first call's `poses` are the estimate to start from (another trajectory than the odometry's): its
	 * sequential pairs are registered from them instead of chained from the odometry. */
	void startFromPoses() { startFromPoses_ = true; }
	/** Every vector of each scan as extracted, static or dynamic, in its scan's frame: what the
	 * loop search falls back to when the static vectors find nothing (mstep.loop_search_all_vectors).
	 * Not set: the loop search uses the static vectors only. */
	void setAllVectors(std::vector<std::vector<MatchSegment>> all) { loops_.setAllVectors(std::move(all)); }

	/** One M-step. `scans[t]`: static vectors of scan t in its own frame
	 * (ids stable across iterations); `poses`: in: current estimate (ignored
	 * on the first call, which chains from odometry, unless startFromPoses), out: optimised.
	 * `changedChildren[t]`: ids of the static vectors of scan t whose parent's children M_chd
	 * the E-step before this M-step changed (Eq. 25, EStep::changedChildren): the edges whose
	 * correspondences involve one are re-registered (Fig. 5) even where the ids stayed the same
	 * (a split point that moved). Null: no E-step ran since the last call. */
	MStepReport run(const std::vector<std::vector<MatchSegment>>& scans, std::vector<mrpt::math::TPose2D>& poses,
					const std::vector<std::vector<uint64_t>>* changedChildren = nullptr);

	/** Called now and then with the share of the scans processed in a pass. */
	void setProgress(ProgressFn f) { progress_ = std::move(f); }

	const std::map<EdgeKey, Constraint>& constraints() const { return book_.edges; }
	const PoseGraph& graph() const { return optimiser_.graph(); }
	bool started() const { return started_; }
	/** The constraint's information in the frame of the pose graph's error (mstep.information_in_edge_frame). */
	Eigen::Matrix3d graphInformation(const Constraint& c) const { return gridvector::graphInformation(c, cfg_.mstep); }

   private:
	/** The first M-step's loop closure in rounds: the loops whose search window covers their drift first, then,
	 * from the trajectory they corrected, loops up to twice as long, and so on. */
	void closeLoopsByReach(const Scans& scans, Poses& poses, std::vector<EdgeKey>& fresh, MStepReport& rep);
	/** The optimisation that ends the M-step: without the moved pairs first, if any (mstep.overlap_reregister_moved);
	 * if no constraint changed only when `always`. */
	void optimise(const Scans& scans, Poses& poses, const std::vector<MovedPair>& moved, MStepReport& rep,
				  bool always = false);

	GridVectorConfig cfg_;
	ProgressFn progress_;
	Poses odometry_;
	ConstraintSet book_;
	PairRegistration reg_;
	SequentialChain chain_;
	OverlapEdges overlaps_;
	LoopClosure loops_;
	GraphOptimisation optimiser_;
	bool started_ = false;
	bool startFromPoses_ = false;
};

}  // namespace gridvector
