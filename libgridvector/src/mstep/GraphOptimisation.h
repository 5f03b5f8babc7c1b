// Sec. 4.2, Eq. 20-22: the pose graph of the odometry edges and the active registrations, optimised; the chi2
// rejections it makes and how often a pair may come back (mstep.reconsider_rejected / reconsider_limit).
#pragma once

#include "mstep/ConstraintSet.h"

namespace gridvector
{
/** Rejections in the first this many M-steps (the estimate still moves from the raw chain and the first loop
 * closures) do not count towards mstep.reconsider_limit. */
constexpr int kReconsiderFreeSteps = 2;

/** The constraint's information in the frame of the pose graph's error (mstep.information_in_edge_frame). */
Eigen::Matrix3d graphInformation(const Constraint& c, const MStepOptions& opts);

/** Is one of these edges (those still in `edges` and not rejected) so far from the estimate `poses` that Eq. 22
 * would graduate its kernel for it (PoseGraph::farLoop)? Else optimising for them moves the poses by less than
 * the edges' own uncertainty. */
bool farFromEstimate(const std::map<EdgeKey, Constraint>& edges, const Poses& poses,
					 const std::vector<EdgeKey>& keys, const GridVectorConfig& cfg);

/** Drives the pose graph (Eq. 22) over the odometry and the constraints of a ConstraintSet. */
class GraphOptimisation
{
   public:
	explicit GraphOptimisation(const GridVectorConfig& cfg) : cfg_(cfg), graph_(cfg.posegraph) {}

	/** Counts the M-steps (the rejections of the first kReconsiderFreeSteps do not count). */
	void beginStep() { ++steps_; }
	/** Eq. 22 over the odometry edges and the active constraints; `poses` in: initial, out: optimised. Marks
	 * and returns the edges the chi2 test rejected; `count`: they count towards mstep.reconsider_limit now
	 * (else the caller counts them with countRejections if no optimisation follows in this M-step);
	 * `graduate`: PoseGraph::optimize's. */
	std::vector<EdgeKey> optimise(Poses& poses, const Poses& odometry, std::map<EdgeKey, Constraint>& edges,
								  MStepReport& rep, bool count = true, bool graduate = false);
	void countRejections(const std::vector<EdgeKey>& keys, const std::map<EdgeKey, Constraint>& edges);

	const PoseGraph& graph() const { return graph_; }

   private:
	/** Was the pair rejected mstep.reconsider_limit times with these correspondences? */
	bool rejectionStands(const EdgeKey& key, const Constraint& c) const;
	/** Counts a rejection of the pair (reset when its correspondences differ from the last rejection's). */
	void countRejection(const EdgeKey& key, const Constraint& c);

	const GridVectorConfig& cfg_;
	PoseGraph graph_;
	int steps_ = 0;  //!< M-steps run
	/** Per pair: chi2 rejections since its correspondences last changed (mstep.reconsider_limit). */
	struct Rejections
	{
		int count = 0;
		std::vector<VectorPair> correspondences;
	};
	std::map<EdgeKey, Rejections> rejections_;
};

}  // namespace gridvector
