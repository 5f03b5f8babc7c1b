// Sec. 4.2: the sequential registrations — each scan against its mstep.sequential_window predecessors.
#pragma once

#include "mstep/PairRegistration.h"

namespace gridvector
{
/** The edges between each scan and its recent predecessors: on the first M-step chained from the odometry
 * into the first estimate (local drift removed), on later ones the missing pairs retried. */
class SequentialChain
{
   public:
	SequentialChain(const GridVectorConfig& cfg, ConstraintSet& book, const PairRegistration& reg,
					const Poses& odometry, const ProgressFn& progress)
		: cfg_(cfg), book_(book), reg_(reg), odometry_(odometry), progress_(progress)
	{}

	/** First M-step: `poses` from the odometry, each scan's pose fused from its registrations against its
	 * predecessors (information-weighted), their edges added. */
	void chain(const Scans& scans, Poses& poses, MStepReport& rep) const;
	/** Later M-steps: sequential pairs not (or no longer) in the graph retried where something changed. */
	void addMissing(const Scans& scans, const Poses& poses, MStepReport& rep) const;

   private:
	/** Registers sequential pair (j, i) of the first M-step from `chained`, else (mstep.sequential_odometry_guess)
	 * from the odometry between j and i. */
	bool registerChained(uint32_t j, uint32_t i, const Scans& scans, const mrpt::math::TPose2D& chained, Constraint& c,
						 MStepReport& rep) const;

	const GridVectorConfig& cfg_;
	ConstraintSet& book_;
	const PairRegistration& reg_;
	const Poses& odometry_;
	const ProgressFn& progress_;
};

}  // namespace gridvector
