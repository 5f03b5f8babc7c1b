#include "mstep/PairRegistration.h"
#include <mrpt/math/TPose2D.h>

#include <algorithm>

namespace gridvector
{
using mrpt::math::TPose2D;

namespace
{
/** Gates widened by this when testing whether an edge's stored correspondences are lost (a margin against
 * re-registering edges whose pairs sit at the final gates' edge). */
constexpr double kRecheckGateFactor = 1.5;
}  // namespace

PairRegistration::PairRegistration(const GridVectorConfig& cfg, const ConstraintSet& book)
	: cfg_(cfg), book_(book), matcher_(cfg.matcher)
{}

// Sec. 4.2: one constraint <j, i> of Eq. 21 by vector matching (Sohn & Kim 2008) of the two scans' static vectors.
bool PairRegistration::registerPair(uint32_t from, uint32_t to, EdgeKind kind, const Scans& scans, const TPose2D& guess,
									Constraint& out, MStepReport& rep) const
{
	++rep.registrations;
	const MatchResult r = matcher_.match(scans[from], scans[to], guess);
	bool ok = r.ok();
	if (ok && kind != EdgeKind::Sequential) ok = r.matchedShare >= cfg_.mstep.overlapMinShare;
	if (!ok)
	{
		++rep.failedRegistrations;
		return false;
	}
	out = book_.make({from, to}, kind, r, guess);
	return true;
}

// Sec. 4.3: how far two scans' ranges "cover each other": their static vectors' corresponding length at the estimate.
double PairRegistration::overlapLength(uint32_t from, uint32_t to, const Scans& scans, const Poses& poses) const
{
	MatchGates g;
	g.psi = cfg_.matcher.gatePsiInitialDeg * M_PI / 180;
	g.rho = cfg_.matcher.gateRhoInitial;
	g.minOverlap = cfg_.matcher.minOverlap;
	return matcher_.correspondences(scans[from], scans[to], poses[to] - poses[from], g, nullptr);
}

// Eq. 24-25 with a margin: a stored pair lost even under widened gates, or a
// new pair inside the final gates, means the data association changed.
bool PairRegistration::correspondencesChanged(const Constraint& c, const Scans& scans, const Poses& poses) const
{
	const TPose2D rel = poses[c.to] - poses[c.from];
	std::vector<VectorPair> wide, tight;
	matcher_.correspondences(scans[c.from], scans[c.to], rel, matcher_.finalGates(kRecheckGateFactor), &wide);
	if (!std::includes(wide.begin(), wide.end(), c.correspondences.begin(), c.correspondences.end())) return true;
	matcher_.correspondences(scans[c.from], scans[c.to], rel, matcher_.finalGates(), &tight);
	return !std::includes(c.correspondences.begin(), c.correspondences.end(), tight.begin(), tight.end());
}

}  // namespace gridvector
