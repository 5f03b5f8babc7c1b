#include "mstep/OverlapEdges.h"
#include "mstep/PassFinder.h"
#include <mrpt/math/TPose2D.h>

#include <algorithm>
#include <cmath>

namespace gridvector
{
using mrpt::math::TPose2D;

// The pass's pose nearest in view if it overlaps pose i, else, with mstep.overlap_most_overlapping,
// the members that share at least overlap_min_length with it, the most overlapping first.
std::vector<uint32_t> OverlapEdges::partners(uint32_t i, uint32_t nearest, const std::vector<uint32_t>& members,
											 const Scans& scans, const Poses& poses) const
{
	const double need = cfg_.mstep.overlapMinLength;
	// the overlap of j with i, 0 where it was short and nothing changed since (measured once per change)
	auto overlap = [&](uint32_t j) {
		const EdgeKey key{j, i};
		const TPose2D rel = poses[i] - poses[j];
		if (book_.stillShort(key, rel)) return 0.0;
		const double len = reg_.overlapLength(j, i, scans, poses);
		if (len < need) book_.shortOverlap(key, rel);
		return len;
	};
	if (!book_.retry({nearest, i}, poses[i] - poses[nearest])) return {};  // failed, nothing changed since
	if (overlap(nearest) >= need) return {nearest};
	if (!cfg_.mstep.overlapMostOverlapping) return {};
	std::vector<std::pair<double, uint32_t>> ranked;
	for (uint32_t j : members)
	{
		if (j == nearest || scans[j].empty() || !book_.retry({j, i}, poses[i] - poses[j])) continue;
		const double len = overlap(j);
		if (len >= need) ranked.emplace_back(-len, j);
	}
	std::sort(ranked.begin(), ranked.end());
	std::vector<uint32_t> out;
	for (const auto& r : ranked) out.push_back(r.second);
	return out;
}

// An overlap registration from another pose of the pass than the nearest (which did not see the place)
// is kept only if it cannot slide along a corridor (one whose weak direction is marginalised out cannot).
bool OverlapEdges::registerOverlap(const EdgeKey& key, bool nearest, const Scans& scans, const TPose2D& rel,
								   Constraint& c, MStepReport& rep) const
{
	return reg_.registerPair(key.first, key.second, EdgeKind::Overlap, scans, rel, c, rep) &&
		   (nearest || c.degeneracy >= cfg_.matcher.degenerateRatio || c.dof < 3);
}

// Sec. 4.3, the topology change: scans whose ranges cover each other get an edge.
// Overlap edges: for each pose, one edge into each earlier pass through its place that it is registered into
// (PassFinder::registeredPass).
std::vector<EdgeKey> OverlapEdges::add(const Scans& scans, const Poses& poses, MStepReport& rep,
									   std::vector<MovedPair>* moved) const
{
	std::vector<EdgeKey> fresh;
	const double d = cfg_.mstep.overlapDistance;
	if (d <= 0) return fresh;
	const uint32_t gap = uint32_t(std::max(1, cfg_.mstep.sequentialWindow));
	PassFinder finder(d, cfg_.mstep.passHeadingWeight);
	for (uint32_t i = 0; i < scans.size(); ++i)
	{
		reportProgress(progress_, "overlap registration", i, scans.size());
		const auto& passes = finder.next(i, poses, gap, uint32_t(cfg_.mstep.overlapRunGap), [&](uint32_t j) {
			return std::hypot(poses[i].x - poses[j].x, poses[i].y - poses[j].y) < d;
		});
		if (scans[i].empty()) continue;
		for (size_t k = 0; k < passes.size(); ++k)
		{
			const auto& p = passes[k];
			if (!PassFinder::registeredPass(k, passes.size()))
			{
				++rep.passesBeyondBound;
				continue;
			}
			if (book_.hasEdgeNear(i, p.lo, p.hi)) continue;
			for (uint32_t from : partners(i, p.nearest, p.members, scans, poses))
			{
				const EdgeKey key{from, i};
				const TPose2D rel = poses[i] - poses[from];
				Constraint c;
				if (registerOverlap(key, from == p.nearest, scans, rel, c, rep))
				{
					if (moved && beyondInitialGates(rel, c.z))
						moved->push_back({key, from == p.nearest});  // registered again once the rest is optimised
					else
					{
						book_.keep(key, std::move(c), rep);
						fresh.push_back(key);
					}
					break;
				}
				book_.fail(key, rel);
			}
		}
	}
	return fresh;
}

bool OverlapEdges::beyondInitialGates(const TPose2D& guess, const TPose2D& z) const
{
	return std::hypot(guess.x - z.x, guess.y - z.y) > cfg_.matcher.gateRhoInitial ||
		   std::abs(mrpt::math::wrapToPi(guess.phi - z.phi)) > cfg_.matcher.gatePsiInitialDeg * M_PI / 180;
}

}  // namespace gridvector
