#include "doors/DoorExclusion.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace gridvector
{
namespace
{
double since(std::chrono::steady_clock::time_point t0)
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

// The map Sec. 5.4 looks at: Eq. 14 at the final threshold, Eq. 4 per state, unobserved stretches cut.
SplitMap SplitMap::of(const std::vector<GridVector>& children, const EStep& estep, const GridVectorConfig& cfg)
{
	std::vector<uint64_t> parentIds;
	std::vector<GridVector> split = estep.finalSplit(children, &parentIds);
	return fromSplit(std::move(split), parentIds, estep, cfg);
}

SplitMap SplitMap::of(std::vector<GridVector>&& children, const EStep& estep, const GridVectorConfig& cfg)
{
	std::vector<uint64_t> parentIds;
	std::vector<GridVector> split = estep.finalSplit(children, &parentIds);
	std::vector<GridVector>().swap(children);  // consumed: the map is held once more, not twice
	return fromSplit(std::move(split), parentIds, estep, cfg);
}

// The split vectors moved into the two merges' inputs and back (one copy of the map, not two).
SplitMap SplitMap::fromSplit(std::vector<GridVector> split, const std::vector<uint64_t>& parentIds,
							 const EStep& estep, const GridVectorConfig& cfg)
{
	SplitMap m;
	std::vector<GridVector> st, dy;
	std::vector<std::pair<bool, size_t>> where(split.size());  // (dynamic, position in dy or st)
	for (size_t k = 0; k < split.size(); ++k)
	{
		m.childOf[split[k].id] = parentIds[k];
		const bool dynamic = split[k].state == VectorState::Dynamic;
		std::vector<GridVector>& to = dynamic ? dy : st;
		where[k] = {dynamic, to.size()};
		to.push_back(std::move(split[k]));
	}
	m.staticMap = estep.cutUnobserved(GlobalMap::mergeAll(st, cfg), st);
	m.dynamicMap = estep.cutUnobserved(GlobalMap::mergeAll(dy, cfg), dy);
	for (size_t k = 0; k < split.size(); ++k) split[k] = std::move(where[k].first ? dy[where[k].second] : st[where[k].second]);
	m.perScan = std::move(split);
	for (const auto* r : {&m.staticMap, &m.dynamicMap})
		for (GridVector v : r->vectors)
		{
			v.state = r == &m.staticMap ? VectorState::Static : VectorState::Dynamic;
			m.vectors.push_back(std::move(v));
		}
	return m;
}

DoorExclusion::DoorExclusion(const GridVectorConfig& cfg, const EStep& estep)
	: cfg_(cfg), estep_(estep), detector_(cfg.doors)
{}

uint64_t DoorExclusion::pieceId(uint64_t childId, size_t j)
{
	constexpr int shift = 56;
	if (j == 0 || j >= 256 || childId >> shift != 0)
		throw std::overflow_error("DoorExclusion::pieceId: no id for piece " + std::to_string(j) + " of child " +
								  std::to_string(childId));
	return childId | (uint64_t(j) << shift);
}

// Sec. 5.3 "gradually": a door stays known until a later detection finds one at its hinge.
void DoorExclusion::accumulate(const std::vector<Door>& found)
{
	std::vector<Door> out = found;
	for (const Door& old : doors_)
	{
		const bool again = std::any_of(found.begin(), found.end(), [&](const Door& d) {
			return std::hypot(d.hinge.x - old.hinge.x, d.hinge.y - old.hinge.y) <= cfg_.doors.maxVertexDistance;
		});
		if (!again) out.push_back(old);
	}
	doors_ = std::move(out);
}

// Children that went whole (not cut by finalSplit) into a leaf of a door found on `map`.
std::vector<uint64_t> DoorExclusion::leafChildren(const SplitMap& map, const std::vector<Door>& found) const
{
	std::vector<uint64_t> out;
	const size_t nStatic = map.staticMap.vectors.size();
	for (const Door& d : found)
		for (size_t leaf : d.leaves)
		{
			const auto& srcs = leaf < nStatic ? map.staticMap.sources[leaf] : map.dynamicMap.sources[leaf - nStatic];
			for (uint64_t id : srcs)
			{
				const auto it = map.childOf.find(id);
				if (it != map.childOf.end() && it->second == id) out.push_back(id);
			}
		}
	std::sort(out.begin(), out.end());
	return out;
}

// The static pieces of a child the M-step may register: none of a leaf, the rest of a wall.
std::vector<GridVector> DoorExclusion::keptPieces(const GridVector& child, const Decision& d) const
{
	if (d.leaf) return {};
	std::vector<GridVector> kept;
	for (GridVector& p : estep_.splitSpans(child, d.spans))
		if (p.state == VectorState::Static)
		{
			p.id = kept.empty() ? child.id : pieceId(child.id, kept.size());
			kept.push_back(std::move(p));
		}
	return kept;
}

// Sec. 5.3: doors detected on the E-step's map and excluded from the M-step's data association.
// "Gradually": a child once found to be a door state stays out (as it was cut then), so the
// exclusion only grows and EM can converge; Eq. 25: a child newly kept out counts as changed.
std::vector<GridVector> DoorExclusion::apply(const std::vector<GridVector>& children,
											 std::vector<std::vector<uint64_t>>& changedIds, DoorExclusionFigures& fig)
{
	const auto t0 = std::chrono::steady_clock::now();
	fig = {};
	const SplitMap map = SplitMap::of(children, estep_, cfg_);
	const std::vector<Door> found = detector_.detect(map.vectors);
	accumulate(found);
	const auto leaves = leafChildren(map, found);
	std::vector<GridVector> out;
	out.reserve(children.size());
	for (const GridVector& c : children)
	{
		if (c.state != VectorState::Static)
		{
			out.push_back(c);
			continue;
		}
		auto known = decided_.find(c.id);
		if (known == decided_.end())
		{
			Decision d{std::binary_search(leaves.begin(), leaves.end(), c.id), {}};
			if (!d.leaf) d.spans = detector_.stateSpans(doors_, c);
			if (!d.leaf && d.spans.empty())
			{
				out.push_back(c);
				continue;
			}
			known = decided_.emplace(c.id, std::move(d)).first;
			if (c.scanIndex >= 0 && size_t(c.scanIndex) < changedIds.size())
				changedIds[size_t(c.scanIndex)].push_back(c.id);
		}
		auto pieces = keptPieces(c, known->second);
		++(pieces.empty() ? fig.excluded : fig.cut);
		for (auto& p : pieces) out.push_back(std::move(p));
	}
	fig.found = found.size();
	fig.doors = doors_.size();
	fig.seconds = since(t0);
	return out;
}

}  // namespace gridvector
