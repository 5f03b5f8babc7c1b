// Sec. 4.3, the topology change: "if two nodes are far apart, but their scan ranges cover each other at this
// time, a new edge will be built between them" — one overlap edge per earlier pass through a pose's place, into
// the first pass and the kRecentPasses most recent (PassFinder::registeredPass).
#pragma once

#include "mstep/PairRegistration.h"

namespace gridvector
{
/** A pair whose overlap registration moved beyond the matcher's initial gates (mstep.overlap_reregister_moved). */
struct MovedPair
{
	EdgeKey key;
	bool nearest = false;  //!< the pass's pose nearest in view (else a non-degenerate registration is needed)
};

class OverlapEdges
{
   public:
	OverlapEdges(const GridVectorConfig& cfg, ConstraintSet& book, const PairRegistration& reg,
				 const ProgressFn& progress)
		: cfg_(cfg), book_(book), reg_(reg), progress_(progress)
	{}

	/** For each pose, an edge into each earlier pass near it that it is registered into (PassFinder::registeredPass)
	 * and that has none; returns the keys of the edges it
	 * added. With `moved`, pairs whose registration moved beyond the matcher's initial gates go there instead. */
	std::vector<EdgeKey> add(const Scans& scans, const Poses& poses, MStepReport& rep,
							 std::vector<MovedPair>* moved = nullptr) const;
	/** registerPair() as an overlap edge, kept only if from the pass's nearest pose or unable to slide. */
	bool registerOverlap(const EdgeKey& key, bool nearest, const Scans& scans, const mrpt::math::TPose2D& rel,
						 Constraint& c, MStepReport& rep) const;
	/** The poses of an earlier pass an overlap edge of pose i is tried against, in order until one
	 * registers: `nearest` (in view) when it shares mstep.overlap_min_length of corresponding static
	 * vectors with i, else (mstep.overlap_most_overlapping) the members sharing that much, the most
	 * first; none when the nearest's registration failed and nothing changed since. */
	std::vector<uint32_t> partners(uint32_t i, uint32_t nearest, const std::vector<uint32_t>& members,
								   const Scans& scans, const Poses& poses) const;
	/** Did a registration move the relative pose beyond the matcher's initial gates from `guess`? */
	bool beyondInitialGates(const mrpt::math::TPose2D& guess, const mrpt::math::TPose2D& z) const;

   private:
	const GridVectorConfig& cfg_;
	ConstraintSet& book_;
	const PairRegistration& reg_;
	const ProgressFn& progress_;
};

}  // namespace gridvector
