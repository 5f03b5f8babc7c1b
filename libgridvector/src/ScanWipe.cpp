#include <gridvector/ScanWipe.h>

#include <algorithm>
#include <cstdint>

namespace gridvector
{
ScanWipe::Stats ScanWipe::apply(const mrpt::math::TPoint2D& sensor,
								const std::vector<GridVector>& scanVectors, std::vector<GridVector>& map,
								const VectorIndex& index, const SkipFn& limit)
{
	std::vector<Segment> segs;
	segs.reserve(scanVectors.size());
	for (const GridVector& v : scanVectors) segs.push_back(segmentOf(v));
	return apply(sensor, segs, map, index, limit);
}

// Only the candidates a triangle actually reaches get marks (and are visited when the counts are
// added): most candidates from the index lie outside the triangle.
ScanWipe::Mark* ScanWipe::marksOf(uint32_t slot, size_t cells)
{
	size_t& off = offset_[slot];
	if (off == 0)
	{
		off = marks_.size() + 1;
		marks_.resize(marks_.size() + cells);
		touched_.push_back(slot);
	}
	return marks_.data() + (off - 1);
}

// Eq. 8 for one scan q: the triangles of V_q over the map vectors near them.
ScanWipe::Stats ScanWipe::apply(const mrpt::math::TPoint2D& sensor, const std::vector<Segment>& scanVectors,
								std::vector<GridVector>& map, const VectorIndex& index, const SkipFn& limit)
{
	Stats st;
	marks_.clear();
	touched_.clear();
	if (offset_.size() < map.size()) offset_.resize(map.size(), 0);
	if (span_.size() < map.size()) span_.resize(map.size(), {UINT32_MAX, 0});
	for (size_t seg = 0; seg < scanVectors.size(); ++seg)
	{
		const Segment& v = scanVectors[seg];
		const double density = beams_ ? WipeTriangle::beamDensity(sensor, v.start, v.end, v.points) : 0.0;
		const WipeTriangle tri(sensor, v.start, v.end, hitBand_, density);
		if (tri.degenerate()) continue;
		++st.triangles;
		candidates_.clear();
		index.query({tri.minX(), tri.minY(), tri.maxX(), tri.maxY()}, candidates_);
		st.candidates += candidates_.size();
		for (uint32_t slot : candidates_)
		{
			const Box2D& box = index.box(slot);  // the vector's whole band: reject before reading the vector
			if (tri.misses(box.minX, box.minY, box.maxX, box.maxY)) continue;
			const WipePart cap = limit ? limit(seg, slot) : WipePart::Hit;
			if (cap == WipePart::Outside) continue;
			const GridVector& m = map[slot];
			Mark* mk = nullptr;  // the slot's marks, made when the triangle reaches one of its cells
			const int cols = m.cols();
			const mrpt::math::TPoint2D axis = m.direction();
			const double res = m.resolution();
			tri.forEachCellAt(m, [&](int r, int c, WipePart part, const mrpt::math::TPoint2D& centre) {
				if (part > cap) return;
				if (!mk) mk = marksOf(slot, m.cells().size());
				const uint32_t i = uint32_t(r) * uint32_t(cols) + uint32_t(c);
				span_[slot].first = std::min(span_[slot].first, i);
				span_[slot].second = std::max(span_[slot].second, i + 1);
				Mark& x = mk[i];
				const float w = beams_ ? float(tri.weight(centre, axis, res, part)) : 1.f;
				float& slotW = part == WipePart::Hit ? x.hit : x.pass;
				slotW = beams_ ? slotW + w : 1.f;  // per beam: add; per cell: once
			});
		}
	}
	for (uint32_t slot : touched_)
	{
		auto& cells = map[slot].cells();
		const Mark* mk = marks_.data() + (offset_[slot] - 1);
		offset_[slot] = 0;
		const auto span = span_[slot];  // the cells this scan's triangles reached
		span_[slot] = {UINT32_MAX, 0};
		bool any = false;
		for (size_t i = span.first; i < span.second; ++i)
		{
			const Mark& x = mk[i];
			if (x.hit == 0 && x.pass == 0) continue;
			any = true;
			if (x.hit > 0) ++st.cellsHit;
			else ++st.cellsVisited;
			if (beams_)
			{
				cells[i].n_occupy += x.hit;  // Eq. 8, part c
				cells[i].n_visit += x.hit + x.pass;  // parts b and c
			}
			else
			{
				cells[i].n_occupy += x.hit > 0 ? 1.f : 0.f;  // c wins over b
				cells[i].n_visit += 1.f;
			}
		}
		st.vectorsTouched += any;
	}
	return st;
}

}  // namespace gridvector
