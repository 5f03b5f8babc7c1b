#include <gridvector/ScanWipe.h>

#include <algorithm>

namespace gridvector
{
// Eq. 8 for one scan q: triangles of V_q over the map, at most one update per cell.
ScanWipe::Stats ScanWipe::apply(const mrpt::math::TPoint2D& sensor,
								const std::vector<GridVector>& scanVectors, std::vector<GridVector>& map,
								const VectorIndex& index, const std::function<bool(uint32_t)>& skip)
{
	std::vector<Segment> segs;
	segs.reserve(scanVectors.size());
	for (const GridVector& v : scanVectors) segs.push_back({v.start(), v.end()});
	return apply(sensor, segs, map, index, skip);
}

ScanWipe::Stats ScanWipe::apply(const mrpt::math::TPoint2D& sensor,
								const std::vector<Segment>& scanVectors, std::vector<GridVector>& map,
								const VectorIndex& index, const std::function<bool(uint32_t)>& skip)
{
	Stats st;
	marks_.clear();
	offset_.clear();
	touched_.clear();
	for (const Segment& v : scanVectors)
	{
		const WipeTriangle tri(sensor, v.start, v.end, hitBand_);
		if (tri.degenerate()) continue;
		++st.triangles;
		candidates_.clear();
		index.query({tri.minX(), tri.minY(), tri.maxX(), tri.maxY()}, candidates_);
		st.candidates += candidates_.size();
		for (uint32_t slot : candidates_)
		{
			if (skip && skip(slot)) continue;
			GridVector& m = map[slot];
			auto [it, fresh] = offset_.try_emplace(slot, marks_.size());
			if (fresh)
			{
				marks_.resize(marks_.size() + m.cells().size(), 0);
				touched_.push_back(slot);
			}
			uint8_t* mk = marks_.data() + it->second;
			const int cols = m.cols();
			tri.forEachCell(m, [&](int r, int c, WipePart part) {
				uint8_t& x = mk[size_t(r) * cols + c];
				x = std::max(x, uint8_t(part));
			});
		}
	}
	for (uint32_t slot : touched_)
	{
		GridVector& m = map[slot];
		const uint8_t* mk = marks_.data() + offset_[slot];
		bool any = false;
		auto& cells = m.cells();
		for (size_t i = 0; i < cells.size(); ++i)
		{
			if (mk[i] == uint8_t(WipePart::Outside)) continue;
			any = true;
			if (mk[i] == uint8_t(WipePart::Hit))
			{
				cells[i].n_occupy += 1.f;
				++st.cellsHit;
			}
			else
				++st.cellsVisited;
			cells[i].n_visit += 1.f;
		}
		st.vectorsTouched += any;
	}
	return st;
}

}  // namespace gridvector
