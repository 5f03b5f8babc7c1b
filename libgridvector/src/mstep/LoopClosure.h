// Beyond the paper (Sec. 5.1: no loop detection): the loop search between passes through a place that no edge
// links yet, orchestrated over the trajectory (the registration of one pair: LoopSearch).
#pragma once

#include "mstep/ConstraintSet.h"
#include "mstep/LoopSearch.h"

#include <limits>
#include <map>

namespace gridvector
{
/** A pair searched from within this of a relative pose it was searched from is not searched again (the same
 * hypotheses, the same result). */
constexpr double kSearchedNearDistance = 0.5;  // [m]
constexpr double kSearchedNearDeg = 10.0;  // [deg]
/** The loop-search window (mstep.loop_search_sigmas x the odometry model) is never narrower than this, so that
 * short paths between the poses still leave room for the registration's own error. */
constexpr double kLoopWindowMinTranslation = 1.0;  // [m]
constexpr double kLoopWindowMinRotationDeg = 10.0;  // [deg]

class LoopClosure
{
   public:
	LoopClosure(const GridVectorConfig& cfg, ConstraintSet& book, const ProgressFn& progress);

	/** The odometry path length from the first pose (the loop-search windows grow along it). */
	void setOdometry(const Poses& odometry);
	/** Every vector of each scan as extracted (mstep.loop_search_all_vectors); empty: static vectors only. */
	void setAllVectors(Scans all) { all_ = std::move(all); }

	/** Loop search between poses near each other with no edge between their passes yet (or only weak ones,
	 * mstep.loop_search_weak_links); returns the keys of the edges it added or replaced (`added`: the overlap
	 * edges added in this step, not verified yet). A pair linked only by such an edge is not searched but goes
	 * to `deferred` (pass's nearest pose, pose): searched once verifyOverlaps has decided (searchDeferred).
	 * With `only`: just these pairs. */
	std::vector<EdgeKey> search(const Scans& scans, const Poses& poses, const std::vector<EdgeKey>& added,
								MStepReport& rep, std::vector<EdgeKey>* deferred = nullptr,
								const std::vector<EdgeKey>* only = nullptr);
	/** The loop searches an unverified overlap edge deferred, for the pairs verifyOverlaps left unlinked
	 * (it dropped the edge), their edges verified in turn; their keys. */
	std::vector<EdgeKey> searchDeferred(const Scans& scans, const Poses& poses, const std::vector<EdgeKey>& deferred,
										MStepReport& rep);
	/** The step after the overlap edges `fresh`: search(), verifyOverlaps on `fresh` and the loop edges (which
	 * join `fresh`), then searchDeferred() (its edges join `fresh` too); true if a search was deferred. */
	bool closeLoops(const Scans& scans, const Poses& poses, std::vector<EdgeKey>& fresh, MStepReport& rep);

	/** Loop search only between poses at most this far apart along the odometry path [m] (default: any). */
	void setMaxPath(double metres) { maxPath_ = metres; }
	/** The path length below which the loop-search window covers mstep.loop_search_sigmas of the odometry's
	 * drift (beyond it the window is capped at mstep.loop_search_max_radius); infinite if nothing caps it. */
	double coveredPath() const;
	/** The odometry path length from the first pose to the last. */
	double pathLength() const { return path_.empty() ? 0.0 : path_.back(); }

	/** Loop-search window of the pair from the odometry model along the path between them. */
	LoopWindow windowOf(uint32_t from, uint32_t to) const;
	/** Does this edge fix the relative place (see mstep.loop_search_weak_links)? */
	bool fixesPlace(const Constraint& c) const;

	/** How an edge (j, i) with j in [jlo, jhi] and i in [ilo, ihi] links the two places. */
	enum class Link
	{
		None,  //!< no edge that fixes the place
		Unverified,  //!< only edges of `unverified` (this M-step's overlap edges before verifyOverlaps)
		Verified  //!< an edge that fixes the place and is not in `unverified`
	};
	Link linked(uint32_t jlo, uint32_t jhi, uint32_t ilo, uint32_t ihi, const std::vector<EdgeKey>& unverified) const;

   private:
	/** The loop search of pose i against pose j on `vectors` (static or all). */
	MatchResult searchPair(const Scans& vectors, uint32_t j, uint32_t i, const Poses& poses, MStepReport& rep) const;
	/** The loop search's registrations into the graph (replacing weak edges of the same pairs); their keys. */
	std::vector<EdgeKey> keep(std::vector<Constraint>& found, const std::vector<EdgeKey>& added, MStepReport& rep);
	/** Did the E-step make part of scan t dynamic (its static vectors are shorter than all its vectors)? */
	bool relabelled(uint32_t t, const Scans& scans) const;
	/** Was i searched against a j in [jlo, jhi] from (nearly) its current relative pose? */
	bool searchedNear(uint32_t i, uint32_t jlo, uint32_t jhi, const Poses& poses) const;

	const GridVectorConfig& cfg_;
	ConstraintSet& book_;
	const ProgressFn& progress_;
	LoopSearch loops_;
	Scans all_;  //!< every vector of each scan (setAllVectors), empty if not set
	std::vector<double> path_;  //!< odometry path length from the first pose
	double maxPath_ = std::numeric_limits<double>::infinity();  //!< setMaxPath
	std::map<EdgeKey, mrpt::math::TPose2D> searched_;  //!< loop searches tried (at this relative pose)
};

}  // namespace gridvector
