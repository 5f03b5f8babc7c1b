// Sec. 4.2-4.3, Eq. 16-25: the maximisation step — pose-graph SLAM over static vectors.
#pragma once

#include <gridvector/GridVectorConfig.h>
#include "mstep/LoopSearch.h"
#include "posegraph/PoseGraph.h"
#include "mstep/VectorMatcher.h"

#include <mrpt/math/TPose2D.h>

#include <functional>
#include <map>
#include <utility>
#include <vector>

namespace gridvector
{
/** An edge of the pose graph with its data association (Eq. 25's M_cor). */
struct Constraint
{
	uint32_t from = 0, to = 0;  //!< from < to
	EdgeKind kind = EdgeKind::Sequential;
	mrpt::math::TPose2D z;  //!< pose of `to` in `from`'s frame
	Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
	std::vector<VectorPair> correspondences;  //!< (vector of `from`, vector of `to`), sorted
	double rms = 0, matchedLength = 0, matchedShare = 0;
	double degeneracy = 1;  //!< smallest / largest translation information eigenvalue
	int dof = 3;  //!< 2: the weak translation direction is marginalised out of `information`
	bool rejected = false;  //!< deactivated by the pose graph's residual test
	uint64_t sigFrom = 0, sigTo = 0;  //!< static-vector signatures of both scans when registered
	mrpt::math::TPose2D checkedAt;  //!< relative pose of the estimate when last checked
};

using EdgeKey = std::pair<uint32_t, uint32_t>;

/** What one M-step did (Fig. 11 uses changedShare). */
struct MStepReport
{
	size_t constraints = 0;  //!< registration edges after the step (active or not)
	size_t active = 0;  //!< ... of which used by the optimiser
	size_t sequential = 0, overlap = 0, loop = 0;  //!< active edges by kind
	size_t added = 0, removed = 0, recomputed = 0;  //!< Eq. 24: the changed constraints
	size_t registrations = 0, failedRegistrations = 0;
	size_t unverified = 0;  //!< overlap and loop edges dropped by the pairwise consistency check
	size_t loopSearches = 0;  //!< pairs given to the loop search
	double changedShare = 0;  //!< (added + removed + recomputed) / constraints
	OptimizeStats optimisation;
	double registrationSeconds = 0, seconds = 0;
};

/** Builds and maintains the registration edges between scans and optimises
 * the pose graph (odometry edges + registrations, Eq. 21-22).
 *
 * First call (from raw odometry): each scan is registered against its
 * `sequential_window` predecessors and its pose chained from the fused
 * registrations, removing local drift. Every call: overlap edges between
 * poses whose static vectors correspond under the current trajectory
 * (one per earlier pass through the place), the loop search, and the
 * constraint selection of Eq. 24-25 — an edge is re-registered only when
 * its correspondences changed (new pairs or pairs lost through an E-step
 * state change or a moved pose) or the children M_chd of a matched vector
 * changed (Eq. 25, Fig. 5); edges whose poses no longer overlap are
 * dropped. */
class MStep
{
   public:
	explicit MStep(const GridVectorConfig& cfg = {});

	/** Dead-reckoning pose of every scan (the odometry edges). */
	void setOdometry(std::vector<mrpt::math::TPose2D> odometry);
	/** Every vector of each scan as extracted, static or dynamic, in its scan's frame: what the
	 * loop search falls back to when the static vectors find nothing (mstep.loop_search_all_vectors).
	 * Not set: the loop search uses the static vectors only. */
	void setAllVectors(std::vector<std::vector<MatchSegment>> all) { all_ = std::move(all); }

	/** One M-step. `scans[t]`: static vectors of scan t in its own frame
	 * (ids stable across iterations); `poses`: in: current estimate (ignored
	 * on the first call, which chains from odometry), out: optimised.
	 * `changedChildren[t]`: ids of the static vectors of scan t whose parent's children M_chd
	 * the E-step before this M-step changed (Eq. 25, EStep::changedChildren): the edges whose
	 * correspondences involve one are re-registered (Fig. 5) even where the ids stayed the same
	 * (a split point that moved). Null: no E-step ran since the last call. */
	MStepReport run(const std::vector<std::vector<MatchSegment>>& scans,
					std::vector<mrpt::math::TPose2D>& poses,
					const std::vector<std::vector<uint64_t>>* changedChildren = nullptr);

	/** Called now and then with the share of the scans processed in a pass. */
	void setProgress(std::function<void(const char* stage, double fraction)> f) { progress_ = std::move(f); }

	const std::map<EdgeKey, Constraint>& constraints() const { return constraints_; }
	const PoseGraph& graph() const { return graph_; }
	bool started() const { return started_; }
	/** The constraint's information in the frame of the pose graph's error (mstep.information_in_edge_frame). */
	Eigen::Matrix3d graphInformation(const Constraint& c) const;

   private:
	using Scans = std::vector<std::vector<MatchSegment>>;
	using Poses = std::vector<mrpt::math::TPose2D>;

	/** The static vectors registrations of this kind use: all, or for overlap and loop edges those some beam saw
	 * steeper than mstep.register_min_incidence_deg. */
	const Scans& registered(EdgeKind kind, const Scans& scans) const;

	void chainSequential(const Scans& scans, Poses& poses, MStepReport& rep);
	/** Registers sequential pair (j, i) of the first M-step from `chained`, else (mstep.sequential_odometry_guess)
	 * from the odometry between j and i. */
	bool registerChained(uint32_t j, uint32_t i, const Scans& scans, const mrpt::math::TPose2D& chained,
						 Constraint& c, MStepReport& rep) const;
	void updateExisting(const Scans& scans, const Poses& poses, MStepReport& rep);
	void addSequential(const Scans& scans, const Poses& poses, MStepReport& rep);
	/** A pair whose overlap registration moved beyond the matcher's initial gates (mstep.overlap_reregister_moved). */
	struct MovedPair
	{
		EdgeKey key;
		bool nearest = false;  //!< the pass's pose nearest in view (else a non-degenerate registration is needed)
	};
	/** Returns the keys of the edges it added; with `moved`, pairs whose registration moved beyond the
	 * matcher's initial gates go there instead (mstep.overlap_reregister_moved). */
	std::vector<EdgeKey> addOverlaps(const Scans& scans, const Poses& poses, MStepReport& rep,
									 std::vector<MovedPair>* moved = nullptr);
	/** A registered pair into the graph (no longer failed). */
	void keepEdge(const EdgeKey& key, Constraint c, MStepReport& rep);
	/** A pair whose registration failed or was dropped, retried when something changed (retry()). */
	void failEdge(const EdgeKey& key, const mrpt::math::TPose2D& rel);
	/** registerPair() as an overlap edge, and kept by the rule for passes (see addOverlaps). */
	bool registerOverlap(const EdgeKey& key, bool nearest, const Scans& scans, const mrpt::math::TPose2D& rel,
						 Constraint& c, MStepReport& rep);
	/** Did a registration move the relative pose beyond the matcher's initial gates from `guess`? */
	bool beyondInitialGates(const mrpt::math::TPose2D& guess, const mrpt::math::TPose2D& z) const;
	/** mstep.overlap_reregister_moved: the moved pairs registered again from the optimised `poses`,
	 * pairwise-checked and, if any is added, optimised again (returns whether it optimised). */
	bool reregisterMoved(const Scans& scans, Poses& poses, const std::vector<MovedPair>& moved, MStepReport& rep);
	/** The poses of an earlier pass an overlap edge of pose i is tried against, in order until one
	 * registers: `nearest` (in view) when it shares mstep.overlap_min_length of corresponding static
	 * vectors with i, else (mstep.overlap_most_overlapping) the members sharing that much, the most
	 * first; none when the nearest's registration failed and nothing changed since. */
	std::vector<uint32_t> overlapPartners(uint32_t i, uint32_t nearest, const std::vector<uint32_t>& members,
										  const Scans& scans, const Poses& poses) const;
	/** Loop search (LoopSearch) between poses near each other with no edge between
	 * their passes yet (or only weak ones, mstep.loop_search_weak_links); returns the keys
	 * of the edges it added or replaced (`added`: the overlap edges added in this step, not verified yet).
	 * A pair linked only by such an edge is not searched but goes to `deferred` (pass's nearest pose, pose):
	 * searched once verifyOverlaps has decided (searchDeferred). With `only`: just these pairs. */
	std::vector<EdgeKey> searchLoops(const Scans& scans, const Poses& poses, const std::vector<EdgeKey>& added,
									 MStepReport& rep, std::vector<EdgeKey>* deferred = nullptr,
									 const std::vector<EdgeKey>* only = nullptr);
	/** The loop search's registrations into the graph (replacing weak edges of the same pairs); their keys. */
	std::vector<EdgeKey> keepLoops(std::vector<Constraint>& found, const std::vector<EdgeKey>& added,
								   MStepReport& rep);
	/** The loop searches an unverified overlap edge deferred, for the pairs verifyOverlaps left unlinked
	 * (it dropped the edge), their edges verified in turn. */
	void searchDeferred(const Scans& scans, const Poses& poses, const std::vector<EdgeKey>& deferred,
						MStepReport& rep);
	/** Poses of an earlier pass the loop search registers against: the nearest in view, then
	 * the members (time order) at least mstep.loop_search_candidate_spacing along the path
	 * from every pose already taken. */
	std::vector<uint32_t> loopCandidates(uint32_t nearest, const std::vector<uint32_t>& members) const;
	/** The loop search of pose i against the candidates on `vectors` (static or all): the result
	 * with the most matched length, its pose in `from`. */
	MatchResult bestLoop(const Scans& vectors, uint32_t i, const std::vector<uint32_t>& candidates,
						 const Poses& poses, uint32_t& from, MStepReport& rep) const;
	/** Did the E-step make part of scan t dynamic (its static vectors are shorter than all its vectors)? */
	bool relabelled(uint32_t t, const Scans& scans) const;
	/** Loop-search window of the pair from the odometry model along the path between them. */
	LoopWindow windowOf(uint32_t from, uint32_t to) const;
	/** Was i searched against a j in [jlo, jhi] from (nearly) its current relative pose? */
	bool searchedNear(uint32_t i, uint32_t jlo, uint32_t jhi, const Poses& poses) const;
	/** How an edge (j, i) with j in [jlo, jhi] and i in [ilo, ihi] links the two places. */
	enum class Link
	{
		None,  //!< no edge that fixes the place
		Unverified,  //!< only edges of `unverified` (this M-step's overlap edges before verifyOverlaps)
		Verified  //!< an edge that fixes the place and is not in `unverified`
	};
	Link linked(uint32_t jlo, uint32_t jhi, uint32_t ilo, uint32_t ihi, const std::vector<EdgeKey>& unverified) const;
	/** Does this edge fix the relative place (see mstep.loop_search_weak_links)? */
	bool fixesPlace(const Constraint& c) const;
	void verifyOverlaps(const Poses& poses, const std::vector<EdgeKey>& fresh, MStepReport& rep);
	/** Returns the edges the chi2 test rejected; `count`: they count towards mstep.reconsider_limit now
	 * (else the caller counts them with countRejections if no optimisation follows in this M-step). */
	std::vector<EdgeKey> optimise(Poses& poses, MStepReport& rep, bool count = true);
	void countRejections(const std::vector<EdgeKey>& keys);

	/** Eq. 24-25: did this edge's vector correspondences change? */
	bool correspondencesChanged(const Constraint& c, const Scans& scans, const Poses& poses) const;
	/** Registers scan `to` against scan `from` from `guess`; true if accepted. */
	bool registerPair(uint32_t from, uint32_t to, EdgeKind kind, const Scans& scans,
					  const mrpt::math::TPose2D& guess, Constraint& out, MStepReport& rep) const;
	Constraint constraintOf(const EdgeKey& key, EdgeKind kind, const MatchResult& r,
							const mrpt::math::TPose2D& checkedAt) const;
	bool sameScans(const Constraint& c) const;
	/** Eq. 25, Fig. 5: does a correspondence of the edge involve a vector whose children changed? */
	bool childrenChanged(const Constraint& c) const;
	/** sigs_ from the static children's ids and the E-steps that changed them (changed_ set first). */
	void signScans(const Scans& scans);
	/** Retry a failed registration? (poses moved or static vectors changed) */
	bool retry(const EdgeKey& key, const mrpt::math::TPose2D& rel) const;
	double overlapLength(uint32_t from, uint32_t to, const Scans& scans, const Poses& poses) const;
	/** Is there an edge (j, i) with j in [jlo, jhi]? */
	bool hasEdgeNear(uint32_t i, uint32_t jlo, uint32_t jhi) const;
	/** Has a relative pose moved enough since a failed attempt to retry it? */
	bool movedSince(const mrpt::math::TPose2D& before, const mrpt::math::TPose2D& now) const;

	GridVectorConfig cfg_;
	Scans facing_;  //!< this M-step's static vectors seen steeper than mstep.register_min_incidence_deg
	VectorMatcher matcher_;
	LoopSearch loops_;
	Scans all_;  //!< every vector of each scan (setAllVectors), empty if not set
	std::vector<double> path_;  //!< odometry path length from the first pose
	std::map<EdgeKey, mrpt::math::TPose2D> searched_;  //!< loop searches tried (at this relative pose)
	PoseGraph graph_;
	Poses odometry_;
	std::map<EdgeKey, Constraint> constraints_;
	struct Failure
	{
		mrpt::math::TPose2D rel;  //!< relative pose tried
		uint64_t sigFrom = 0, sigTo = 0;
	};
	std::map<EdgeKey, Failure> failed_;  //!< failed registrations, retried when something changed
	std::vector<uint64_t> sigs_;  //!< per scan: signature of its static children (signScans)
	std::vector<uint64_t> childChanges_;  //!< per scan: E-steps that changed one of its static children
	std::vector<std::vector<uint64_t>> changed_;  //!< per scan: sorted ids whose M_chd changed (run's argument)
	/** Per pair: chi2 rejections since its correspondences last changed (mstep.reconsider_limit). */
	struct Rejections
	{
		int count = 0;
		std::vector<VectorPair> correspondences;
	};
	std::map<EdgeKey, Rejections> rejections_;
	/** Was the pair rejected mstep.reconsider_limit times with these correspondences? */
	bool rejectionStands(const EdgeKey& key, const Constraint& c) const;
	/** Counts a rejection of the pair (reset when its correspondences differ from the last rejection's). */
	void countRejection(const EdgeKey& key, const Constraint& c);
	std::map<EdgeKey, Constraint> replaced_;  //!< weak edges a loop edge replaced, until it is verified
	bool started_ = false;
	int steps_ = 0;  //!< M-steps run
	std::function<void(const char*, double)> progress_;
	void report(const char* stage, size_t i, size_t n) const
	{
		if (progress_ && (i % 16 == 0 || i + 1 == n)) progress_(stage, double(i + 1) / double(n));
	}
};

}  // namespace gridvector
