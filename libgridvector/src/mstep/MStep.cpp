#include "mstep/MStep.h"
#include "mstep/Consistency.h"
#include "mstep/ConstraintUpdate.h"
#include "mstep/Reregistration.h"
#include <mrpt/math/TPose2D.h>

#include <chrono>
#include <stdexcept>

namespace gridvector
{
using mrpt::math::TPose2D;

namespace
{
double secondsSince(std::chrono::steady_clock::time_point t0)
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

MStep::MStep(const GridVectorConfig& cfg)
	: cfg_(cfg),
	  book_(cfg_.matcher),
	  reg_(cfg_, book_),
	  chain_(cfg_, book_, reg_, odometry_, progress_),
	  overlaps_(cfg_, book_, reg_, progress_),
	  loops_(cfg_, book_, progress_),
	  optimiser_(cfg_)
{}

void MStep::setOdometry(std::vector<TPose2D> odometry)
{
	odometry_ = std::move(odometry);
	loops_.setOdometry(odometry_);
}

// Eq. 22 re-optimised if a constraint changed (Eq. 24; else the estimate is still optimal).
void MStep::optimise(const Scans& scans, Poses& poses, const std::vector<MovedPair>& moved, MStepReport& rep,
					 bool always)
{
	if (!moved.empty())
	{
		const auto rejected =
			optimiser_.optimise(poses, odometry_, book_.edges, rep, false);  // without the moved pairs
		if (!reregisterMoved(overlaps_, book_, optimiser_, cfg_.mstep, odometry_, scans, poses, moved, rep))
			optimiser_.countRejections(rejected, book_.edges);  // it was the last
	}
	else if (always || rep.added + rep.removed + rep.recomputed > 0)
		optimiser_.optimise(poses, odometry_, book_.edges, rep);
}

// Sec. 4.2-4.3: one M-step: the changed constraints of Eq. 24 (re-)registered, Eq. 22 re-optimised if any; Fig. 11's
// share.
MStepReport MStep::run(const Scans& scans, Poses& poses, const std::vector<std::vector<uint64_t>>* changedChildren)
{
	const auto t0 = std::chrono::steady_clock::now();
	MStepReport rep;
	optimiser_.beginStep();
	if (odometry_.size() != scans.size()) throw std::invalid_argument("MStep: odometry and scans differ in length");
	const size_t before = book_.edges.size();
	book_.beginStep(scans, changedChildren);
	const bool fromPoses = !started_ && startFromPoses_;  // a start that is not the graph's optimum
	if (!started_ && !startFromPoses_) chain_.chain(scans, poses, rep);
	else if (fromPoses) chain_.addMissing(scans, poses, rep);
	else
	{
		updateConstraints(book_, reg_, cfg_.mstep, scans, poses, rep);  // Eq. 24-25
		chain_.addMissing(scans, poses, rep);
	}
	started_ = true;
	rep.updateSeconds = secondsSince(t0);
	const auto tOverlap = std::chrono::steady_clock::now();
	std::vector<MovedPair> moved;
	auto fresh = overlaps_.add(scans, poses, rep, cfg_.mstep.overlapReregisterMoved ? &moved : nullptr);
	rep.overlapSeconds = secondsSince(tOverlap);
	const auto tLoop = std::chrono::steady_clock::now();
	loops_.closeLoops(scans, poses, fresh, rep);
	rep.loopSeconds = secondsSince(tLoop);
	rep.registrationSeconds = secondsSince(t0);
	optimise(scans, poses, moved, rep, fromPoses);
	summarise(book_, before, rep);
	rep.seconds = secondsSince(t0);
	return rep;
}

}  // namespace gridvector
