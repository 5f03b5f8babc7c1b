#include "mstep/MStep.h"
#include "mstep/Consistency.h"
#include "mstep/ConstraintUpdate.h"
#include "mstep/Reregistration.h"
#include <mrpt/math/TPose2D.h>

#include <chrono>
#include <limits>
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

namespace
{
/** Each round of the first M-step's loop closure reaches loops up to this times as long as the last round's: their
 * drift, after the shorter loops' correction, is again about what the window covers. */
constexpr double kReachGrowth = 2.0;
}  // namespace

// Beyond the paper (issue 21): a loop whose path is long against the window (the robot back after 700 m of a
// corridor) is met from the dead reckoning's drift, where a repeated stretch of the place can fit better than
// the place; closed after the shorter loops corrected the trajectory, its prior is near the truth.
void MStep::closeLoopsByReach(const Scans& scans, Poses& poses, std::vector<EdgeKey>& fresh, MStepReport& rep)
{
	const double total = loops_.pathLength();
	for (double reach = loops_.coveredPath();; reach *= kReachGrowth)
	{
		const bool last = !(reach > 0 && reach < total);  // (no window, loop_search_max_radius 0: one round)
		loops_.setMaxPath(last ? std::numeric_limits<double>::infinity() : reach);
		loops_.closeLoops(scans, poses, fresh, rep);
		if (last) break;
		// the next round's windows move only if this round's edges move the poses beyond their own uncertainty
		if (farFromEstimate(book_.edges, poses, fresh, cfg_))
			optimiser_.optimise(poses, odometry_, book_.edges, rep, false);  // counted by the M-step's last one
		fresh.clear();
	}
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
	const bool first = !started_;
	const bool fromPoses = first && startFromPoses_;  // a start that is not the graph's optimum
	started_ = true;
	if (first && !fromPoses)
		chain_.chain(scans, poses, rep);
	else
	{
		if (!first) updateConstraints(book_, reg_, cfg_.mstep, scans, poses, rep);  // Eq. 24-25
		chain_.addMissing(scans, poses, rep);
	}
	rep.updateSeconds = secondsSince(t0);
	const auto tOverlap = std::chrono::steady_clock::now();
	std::vector<MovedPair> moved;
	auto fresh = overlaps_.add(scans, poses, rep, cfg_.mstep.overlapReregisterMoved ? &moved : nullptr);
	rep.overlapSeconds = secondsSince(tOverlap);
	const auto tLoop = std::chrono::steady_clock::now();
	if (first)
		closeLoopsByReach(scans, poses, fresh, rep);
	else
		loops_.closeLoops(scans, poses, fresh, rep);
	rep.loopSeconds = secondsSince(tLoop);
	rep.registrationSeconds = secondsSince(t0);
	optimise(scans, poses, moved, rep, fromPoses);
	summarise(book_, before, rep);
	rep.seconds = secondsSince(t0);
	return rep;
}

}  // namespace gridvector
