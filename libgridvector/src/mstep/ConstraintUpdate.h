// Sec. 4.3, Eq. 24-25: which constraints an M-step keeps, removes or recomputes, and Fig. 11's changed share.
#pragma once

#include "mstep/PairRegistration.h"

namespace gridvector
{
/** Eq. 24-25: every stored edge re-registered only if its data association changed (a matched vector's
 * children M_chd changed, or its correspondences at the estimate); dropped when its poses no longer overlap
 * (Sec. 4.3) or its re-registration fails. Counts removed and recomputed edges in `rep`. */
void updateConstraints(ConstraintSet& book, const PairRegistration& reg, const MStepOptions& opts, const Scans& scans,
					   const Poses& poses, MStepReport& rep);

/** The report's edge counts after the step and Fig. 11's share of changed constraints (`before`: edges before it). */
void summarise(const ConstraintSet& book, size_t before, MStepReport& rep);

}  // namespace gridvector
