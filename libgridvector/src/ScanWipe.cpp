#include <gridvector/ScanWipe.h>

#include <algorithm>

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

// Eq. 8 for one scan q: the triangles of V_q over the map vectors near them.
ScanWipe::Stats ScanWipe::apply(const mrpt::math::TPoint2D& sensor, const std::vector<Segment>& scanVectors,
								std::vector<GridVector>& map, const VectorIndex& index, const SkipFn& limit)
{
	Stats st;
	marks_.clear();
	touched_.clear();
	if (offset_.size() < map.size()) offset_.resize(map.size(), 0);
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
			const WipePart cap = limit ? limit(seg, slot) : WipePart::Hit;
			if (cap == WipePart::Outside) continue;
			const GridVector& m = map[slot];
			size_t& off = offset_[slot];
			if (off == 0)
			{
				off = marks_.size() + 1;
				marks_.resize(marks_.size() + m.cells().size());
				touched_.push_back(slot);
			}
			Mark* mk = marks_.data() + (off - 1);
			const int cols = m.cols();
			const mrpt::math::TPoint2D axis = m.direction();
			const double res = m.resolution();
			tri.forEachCellAt(m, [&](int r, int c, WipePart part, const mrpt::math::TPoint2D& centre) {
				if (part > cap) return;
				Mark& x = mk[size_t(r) * cols + c];
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
		bool any = false;
		for (size_t i = 0; i < cells.size(); ++i)
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
