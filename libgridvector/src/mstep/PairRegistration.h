// Sec. 4.2: one constraint <j, i> of Eq. 21 by vector matching (Sohn & Kim 2008) of two scans' static vectors.
#pragma once

#include "mstep/ConstraintSet.h"

namespace gridvector
{
/** Registers pairs of scans into constraints and tells whether a constraint's correspondences changed. */
class PairRegistration
{
   public:
	PairRegistration(const GridVectorConfig& cfg, const ConstraintSet& book);

	/** Registers scan `to` against scan `from` from `guess`; true if accepted (overlap and loop edges need
	 * mstep.overlap_min_share). */
	bool registerPair(uint32_t from, uint32_t to, EdgeKind kind, const Scans& scans, const mrpt::math::TPose2D& guess,
					  Constraint& out, MStepReport& rep) const;
	/** Sec. 4.3: the corresponding static length of two scans at the estimate (how far their ranges cover each other).
	 */
	double overlapLength(uint32_t from, uint32_t to, const Scans& scans, const Poses& poses) const;
	/** Eq. 24-25: did this edge's vector correspondences change at the estimate? */
	bool correspondencesChanged(const Constraint& c, const Scans& scans, const Poses& poses) const;

	const VectorMatcher& matcher() const { return matcher_; }

   private:
	const GridVectorConfig& cfg_;
	const ConstraintSet& book_;
	VectorMatcher matcher_;
};

}  // namespace gridvector
