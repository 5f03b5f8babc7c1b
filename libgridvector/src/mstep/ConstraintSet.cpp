#include "mstep/ConstraintSet.h"
#include <mrpt/math/TPose2D.h>

#include <algorithm>
#include <cmath>

namespace gridvector
{
using mrpt::math::TPose2D;

void ConstraintSet::beginStep(const Scans& scans, const std::vector<std::vector<uint64_t>>* changedChildren)
{
	changed_.assign(scans.size(), {});
	if (changedChildren)
		for (size_t t = 0; t < scans.size() && t < changedChildren->size(); ++t)
		{
			changed_[t] = (*changedChildren)[t];
			std::sort(changed_[t].begin(), changed_[t].end());
		}
	signScans(scans);
}

// Eq. 24-25: a scan's signature covers what its registrations depend on, its static children M_chd:
// their ids and, since a child keeps its id when a split point moves (EStep::childId), a count of the
// E-steps that changed one of them (changed_, compared on the exact column ranges).
void ConstraintSet::signScans(const Scans& scans)
{
	childChanges_.resize(scans.size(), 0);
	sigs_.assign(scans.size(), 1469598103934665603ULL);
	for (size_t t = 0; t < scans.size(); ++t)
	{
		if (!changed_[t].empty()) ++childChanges_[t];
		for (const auto& s : scans[t]) sigs_[t] = (sigs_[t] ^ s.id) * 1099511628211ULL;  // FNV-1a
		sigs_[t] = (sigs_[t] ^ childChanges_[t]) * 1099511628211ULL;
	}
}

Constraint ConstraintSet::make(const EdgeKey& key, EdgeKind kind, const MatchResult& r, const TPose2D& checkedAt) const
{
	Constraint c;
	c.from = key.first;
	c.to = key.second;
	c.kind = kind;
	c.z = r.pose;
	c.information = r.information;
	c.correspondences = r.pairs;
	c.rms = r.rms;
	c.matchedLength = r.matchedLength;
	c.matchedShare = r.matchedShare;
	c.degeneracy = r.translationDegeneracy;
	c.dof = r.dof;
	c.sigFrom = sigs_[key.first];
	c.sigTo = sigs_[key.second];
	c.checkedAt = checkedAt;
	return c;
}

// Eq. 25: the static children of both scans (their ids) as when the edge was registered.
bool ConstraintSet::sameScans(const Constraint& c) const
{
	return c.sigFrom == sigs_[c.from] && c.sigTo == sigs_[c.to];
}

// Eq. 25, Fig. 5: from M_cor (the edge's correspondences) the pairs affected by a vector whose
// children M_chd the last E-step changed, ids kept or not.
bool ConstraintSet::childrenChanged(const Constraint& c) const
{
	const auto in = [](const std::vector<uint64_t>& ids, uint64_t id) {
		return std::binary_search(ids.begin(), ids.end(), id);
	};
	const auto& a = changed_[c.from];
	const auto& b = changed_[c.to];
	if (a.empty() && b.empty()) return false;
	return std::any_of(c.correspondences.begin(), c.correspondences.end(),
					   [&](const VectorPair& p) { return in(a, p.a) || in(b, p.b); });
}

void ConstraintSet::confirm(Constraint& c, const TPose2D& rel) const
{
	c.checkedAt = rel;
	c.sigFrom = sigs_[c.from], c.sigTo = sigs_[c.to];
}

void ConstraintSet::keep(const EdgeKey& key, Constraint c, MStepReport& rep)
{
	edges[key] = std::move(c);
	failed_.erase(key);
	++rep.added;
}

void ConstraintSet::fail(const EdgeKey& key, const TPose2D& rel)
{
	failed_[key] = {rel, sigs_[key.first], sigs_[key.second]};
}

bool ConstraintSet::unchangedSince(const Attempt& f, const EdgeKey& key, const TPose2D& rel) const
{
	return !movedSince(f.rel, rel) && f.sigFrom == sigs_[key.first] && f.sigTo == sigs_[key.second];
}

bool ConstraintSet::retry(const EdgeKey& key, const TPose2D& rel) const
{
	auto f = failed_.find(key);
	return f == failed_.end() || !unchangedSince(f->second, key, rel);
}

void ConstraintSet::shortOverlap(const EdgeKey& key, const TPose2D& rel)
{
	short_[key] = {rel, sigs_[key.first], sigs_[key.second]};
}

bool ConstraintSet::stillShort(const EdgeKey& key, const TPose2D& rel) const
{
	auto f = short_.find(key);
	return f != short_.end() && unchangedSince(f->second, key, rel);
}

bool ConstraintSet::movedSince(const TPose2D& before, const TPose2D& now) const
{
	return std::hypot(before.x - now.x, before.y - now.y) > kMovedGateShare * matcher_.gateRhoFinal ||
		   std::abs(mrpt::math::wrapToPi(before.phi - now.phi)) >
			   kMovedGateShare * matcher_.gatePsiFinalDeg * M_PI / 180;
}

bool ConstraintSet::hasEdgeNear(uint32_t i, uint32_t jlo, uint32_t jhi) const
{
	return anyEdgeIn(edges, jlo, jhi, i, i, [](const EdgeKey&, const Constraint&) { return true; });
}

}  // namespace gridvector
