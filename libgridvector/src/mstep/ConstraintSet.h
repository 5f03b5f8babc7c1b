// Sec. 4.3, Eq. 24-25: the registration edges with what decides whether each is still valid —
// the scans' signatures of their static children M_chd, the failed pairs, the replaced weak edges.
#pragma once

#include "mstep/Constraint.h"

#include <gridvector/GridVectorConfig.h>

#include <map>

namespace gridvector
{
/** A failed pair is retried once its relative pose moved this share of the matcher's final gates (a smaller move
 * repeats the same registration). */
constexpr double kMovedGateShare = 0.5;

/** Calls f(key, value) for the entries (j, i) of `m` (keyed (from, to)) with j in [jlo, jhi] and i in [ilo, ihi],
 * from by from, until f returns true; true if it did. One ordered lookup per `from`: the cost does not grow with
 * the edges of a `from` into other places (an early pass's poses are the `from` of every later pass's edges). */
template <class Map, class F>
bool anyEdgeIn(const Map& m, uint32_t jlo, uint32_t jhi, uint32_t ilo, uint32_t ihi, F&& f)
{
	for (uint32_t j = jlo; j <= jhi && j >= jlo; ++j)
	{
		auto it = m.lower_bound({j, ilo});
		if (it == m.end()) break;
		if (it->first.first != j)
		{
			if (it->first.first > jhi) break;
			j = it->first.first - 1;  // the next `from` that has entries
			continue;
		}
		for (; it != m.end() && it->first.first == j && it->first.second <= ihi; ++it)
			if (f(it->first, it->second)) return true;
	}
	return false;
}

/** The edges of the pose graph besides odometry, keyed (from, to), and their Eq. 24-25 bookkeeping. */
class ConstraintSet
{
   public:
	explicit ConstraintSet(const MatcherOptions& matcher) : matcher_(matcher) {}

	std::map<EdgeKey, Constraint> edges;
	std::map<EdgeKey, Constraint> replaced;  //!< weak edges a loop edge replaced, until it is verified

	/** Start of an M-step: the ids whose M_chd the last E-step changed (sorted per scan; null: none) and the
	 * scans' signatures from them. */
	void beginStep(const Scans& scans, const std::vector<std::vector<uint64_t>>* changedChildren);

	/** A constraint from a registration, stamped with both scans' signatures. */
	Constraint make(const EdgeKey& key, EdgeKind kind, const MatchResult& r,
					const mrpt::math::TPose2D& checkedAt) const;
	/** Eq. 25: the static children of both scans (their ids) as when the edge was registered? */
	bool sameScans(const Constraint& c) const;
	/** Eq. 25, Fig. 5: does a correspondence of the edge involve a vector whose children changed? */
	bool childrenChanged(const Constraint& c) const;
	/** The edge checked again at `rel` with both scans unchanged: re-stamped. */
	void confirm(Constraint& c, const mrpt::math::TPose2D& rel) const;

	/** A registered pair into the graph (no longer failed). */
	void keep(const EdgeKey& key, Constraint c, MStepReport& rep);
	/** A pair whose registration failed or was dropped, retried when something changed (retry()). */
	void fail(const EdgeKey& key, const mrpt::math::TPose2D& rel);
	/** Retry a failed registration? (poses moved or static vectors changed) */
	bool retry(const EdgeKey& key, const mrpt::math::TPose2D& rel) const;
	/** A pair whose views shared less than mstep.overlap_min_length at `rel`: measured again when something
	 * changed (as retry()). */
	void shortOverlap(const EdgeKey& key, const mrpt::math::TPose2D& rel);
	/** Was the pair's overlap short at (nearly) this relative pose, with both scans' static vectors as now? */
	bool stillShort(const EdgeKey& key, const mrpt::math::TPose2D& rel) const;
	/** Has a relative pose moved enough since a failed attempt to retry it? */
	bool movedSince(const mrpt::math::TPose2D& before, const mrpt::math::TPose2D& now) const;
	/** Is there an edge (j, i) with j in [jlo, jhi]? */
	bool hasEdgeNear(uint32_t i, uint32_t jlo, uint32_t jhi) const;

	/** Per scan: signature of its static children (ids and the E-steps that changed one). */
	const std::vector<uint64_t>& signatures() const { return sigs_; }

   private:
	void signScans(const Scans& scans);

	MatcherOptions matcher_;
	struct Attempt  //!< a failed registration or a short overlap, and what it was tried with
	{
		mrpt::math::TPose2D rel;  //!< relative pose tried
		uint64_t sigFrom = 0, sigTo = 0;
	};
	/** Is the attempt `f` still what the pair would give at `rel` (not moved, both scans unchanged)? */
	bool unchangedSince(const Attempt& f, const EdgeKey& key, const mrpt::math::TPose2D& rel) const;

	std::map<EdgeKey, Attempt> failed_;  //!< failed registrations, retried when something changed
	std::map<EdgeKey, Attempt> short_;  //!< pairs that overlapped too little, measured again when something changed
	std::vector<uint64_t> sigs_;  //!< per scan: signature of its static children (signScans)
	std::vector<uint64_t> childChanges_;  //!< per scan: E-steps that changed one of its static children
	std::vector<std::vector<uint64_t>> changed_;  //!< per scan: sorted ids whose M_chd changed
};

}  // namespace gridvector
