#include <gridvector/DoorExclusion.h>

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

// The column ranges of `child` the pieces cover (Eq. 25's comparison of what was kept).
std::vector<std::pair<int, int>> columnsOf(const GridVector& child, const std::vector<GridVector>& pieces)
{
	std::vector<std::pair<int, int>> out;
	const auto d = child.direction();
	for (const GridVector& p : pieces)
	{
		const double u = (p.start().x - child.start().x) * d.x + (p.start().y - child.start().y) * d.y;
		const int first = int(std::lround(u / child.resolution()));
		out.emplace_back(first, first + p.cols());
	}
	return out;
}
}  // namespace

// The map Sec. 5.4 looks at: Eq. 14 at the final threshold, Eq. 4 per state, unobserved stretches cut.
SplitMap SplitMap::of(const std::vector<GridVector>& children, const EStep& estep, const GridVectorConfig& cfg)
{
	SplitMap m;
	std::vector<uint64_t> parentIds;
	m.perScan = estep.finalSplit(children, &parentIds);
	std::vector<GridVector> st, dy;
	for (size_t k = 0; k < m.perScan.size(); ++k)
	{
		m.childOf[m.perScan[k].id] = parentIds[k];
		(m.perScan[k].state == VectorState::Dynamic ? dy : st).push_back(m.perScan[k]);
	}
	m.staticMap = estep.cutUnobserved(GlobalMap::mergeAll(st, cfg), st);
	m.dynamicMap = estep.cutUnobserved(GlobalMap::mergeAll(dy, cfg), dy);
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
{
}

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
std::vector<GridVector> DoorExclusion::keptPieces(const GridVector& child, bool leaf) const
{
	if (leaf) return {};
	const auto spans = detector_.stateSpans(doors_, child);
	if (spans.empty()) return {child};
	std::vector<GridVector> kept;
	for (GridVector& p : estep_.splitSpans(child, spans))
		if (p.state == VectorState::Static)
		{
			p.id = kept.empty() ? child.id : pieceId(child.id, kept.size());
			kept.push_back(std::move(p));
		}
	return kept;
}

// Sec. 5.3: doors detected on the E-step's map and excluded from the M-step's data association;
// Eq. 25: a child whose kept stretch changed counts as a changed child.
std::vector<GridVector> DoorExclusion::apply(const std::vector<GridVector>& children,
											 std::vector<std::vector<uint64_t>>& changedIds, DoorExclusionFigures& fig)
{
	const auto t0 = std::chrono::steady_clock::now();
	fig = {};
	const SplitMap map = SplitMap::of(children, estep_, cfg_);
	const std::vector<Door> found = detector_.detect(map.vectors);
	accumulate(found);
	const auto leaves = leafChildren(map, found);
	std::map<uint64_t, std::vector<std::pair<int, int>>> kept;
	std::vector<GridVector> out;
	out.reserve(children.size());
	for (const GridVector& c : children)
	{
		if (c.state != VectorState::Static)
		{
			out.push_back(c);
			continue;
		}
		auto pieces = keptPieces(c, std::binary_search(leaves.begin(), leaves.end(), c.id));
		const bool whole = pieces.size() == 1 && pieces[0].cols() == c.cols();
		if (!whole)
		{
			kept[c.id] = columnsOf(c, pieces);
			++(pieces.empty() ? fig.excluded : fig.cut);
		}
		const auto last = lastKept_.find(c.id);
		const bool changed = whole ? last != lastKept_.end() : last == lastKept_.end() || last->second != kept[c.id];
		if (changed && c.scanIndex >= 0 && size_t(c.scanIndex) < changedIds.size())
			changedIds[size_t(c.scanIndex)].push_back(c.id);
		for (auto& p : pieces) out.push_back(std::move(p));
	}
	lastKept_ = std::move(kept);
	fig.found = found.size();
	fig.doors = doors_.size();
	fig.seconds = since(t0);
	return out;
}

}  // namespace gridvector
