#include "mstep/ConstraintUpdate.h"
#include <mrpt/math/TPose2D.h>

#include <algorithm>
#include <cmath>

namespace gridvector
{
using mrpt::math::TPose2D;

namespace
{
/** A non-sequential edge whose poses moved further apart than this x mstep.overlap_distance no longer overlaps
 * (beyond the distance at which it could have been made: a margin against dropping and re-adding it). */
constexpr double kDropDistanceFactor = 1.5;
/** An overlap edge whose corresponding static length fell below this x mstep.overlap_min_length no longer overlaps
 * (half the length that made it: the same margin). */
constexpr double kDropLengthShare = 0.5;
/** A re-registered edge with the same correspondences counts as changed (Eq. 24) when its pose moved more than
 * this [m] or turned more than kChangedRotation [rad]: below, the optimiser's result does not move. */
constexpr double kChangedTranslation = 1e-3;
constexpr double kChangedRotation = 1e-4;
}  // namespace

// Eq. 24-25: an edge is recomputed only if its data association changed.
void updateConstraints(ConstraintSet& book, const PairRegistration& reg, const MStepOptions& opts, const Scans& scans,
					   const Poses& poses, MStepReport& rep)
{
	const double far = kDropDistanceFactor * opts.overlapDistance;
	for (auto it = book.edges.begin(); it != book.edges.end();)
	{
		Constraint& c = it->second;
		const TPose2D rel = poses[c.to] - poses[c.from];
		const bool nonSeq = c.kind != EdgeKind::Sequential;
		// (a loop-search edge was accepted on its own criteria, not on the overlap length)
		if (nonSeq && (std::hypot(poses[c.from].x - poses[c.to].x, poses[c.from].y - poses[c.to].y) > far ||
					   (c.kind == EdgeKind::Overlap &&
						reg.overlapLength(c.from, c.to, scans, poses) < kDropLengthShare * opts.overlapMinLength)))
		{
			it = book.edges.erase(it);  // no longer overlapping: drop (Sec. 4.3)
			++rep.removed;
			continue;
		}
		const bool same = book.sameScans(c);
		// Eq. 24-25: re-register when a matched vector's children changed, else only when the
		// correspondences changed (a rejected edge: only when the vectors of its scans changed)
		const bool keep = !book.childrenChanged(c) && (c.rejected ? same
																  : (same && !book.movedSince(c.checkedAt, rel)) ||
																		!reg.correspondencesChanged(c, scans, poses));
		if (keep)
		{
			book.confirm(c, rel);
			++it;
			continue;
		}
		Constraint fresh;
		if (!reg.registerPair(c.from, c.to, c.kind, scans, rel, fresh, rep))
		{
			if (c.kind == EdgeKind::Sequential)
			{
				// Too few static vectors left to register the pair: its last measurement (of the vectors
				// static then) stands. An E-step run on a trajectory still off at its loops calls the walls of
				// the misaligned passes dynamic (Eq. 8); dropping the pair would hand its scans to the odometry.
				book.confirm(c, rel);
				++it;
				continue;
			}
			it = book.edges.erase(it);
			++rep.removed;
			continue;
		}
		const bool changed = fresh.correspondences != c.correspondences ||
							 std::hypot(fresh.z.x - c.z.x, fresh.z.y - c.z.y) > kChangedTranslation ||
							 std::abs(mrpt::math::wrapToPi(fresh.z.phi - c.z.phi)) > kChangedRotation;
		if (changed)
			++rep.recomputed;
		else
			fresh.rejected = c.rejected;
		c = std::move(fresh);
		++it;
	}
}

// Fig. 11: the share of the constraints an M-step changed (Eq. 24).
void summarise(const ConstraintSet& book, size_t before, MStepReport& rep)
{
	rep.constraints = book.edges.size();
	for (const auto& [key, c] : book.edges)
	{
		if (c.rejected) continue;
		++rep.active;
		if (c.kind == EdgeKind::Sequential)
			++rep.sequential;
		else if (c.kind == EdgeKind::Overlap)
			++rep.overlap;
		else if (c.kind == EdgeKind::Loop)
			++rep.loop;
	}
	const size_t denom = std::max<size_t>(1, std::max(before, rep.constraints));
	rep.changedShare = double(rep.added + rep.removed + rep.recomputed) / denom;
}

}  // namespace gridvector
