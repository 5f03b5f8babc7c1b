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

// Eq. 8 for one scan's marks on one map vector: part c -> n_occupy and n_visit, part b -> n_visit.
bool ScanWipe::add(Mark* mk, const Span& span, std::vector<GridCell>& cells, bool countBeams, Stats& st)
{
	// branch-free: an unmarked cell adds 0 (x + 0 == x), a marked one its increments
	bool any = false;
	size_t hit = 0, visited = 0;
	for (size_t i = span.first; i < span.last; ++i)
	{
		Mark& x = mk[i];
		const bool marked = x.hit != 0 || x.pass != 0, isHit = x.hit > 0;
		any |= marked;
		hit += isHit;
		visited += marked && !isHit;
		GridCell& c = cells[i];
		if (countBeams)
		{
			c.n_occupy += x.hit;  // Eq. 8, part c
			c.n_visit += x.hit + x.pass;  // parts b and c
		}
		else
		{
			c.n_occupy += isHit ? 1.f : 0.f;  // c wins over b
			c.n_visit += marked ? 1.f : 0.f;
		}
		x = Mark{};
	}
	st.cellsHit += hit;
	st.cellsVisited += visited;
	return any;
}

// Eq. 8 for a scan's only triangle over m: a mark of one triangle is its weight (0 + w == w).
bool ScanWipe::addAlone(const WipeTriangle& tri, GridVector& m, bool countBeams, Stats& st)
{
	size_t hit = 0, visited = 0;
	const mrpt::math::TPoint2D axis = m.direction();
	const double res = m.resolution();
	tri.forEachCellAt(m, [&](int r, int c, WipePart part, const mrpt::math::TPoint2D& centre) {
		const float w = countBeams ? float(tri.weight(centre, axis, res, part)) : 1.f;
		if (w == 0) return;  // an unmarked cell
		GridCell& cell = m.cell(r, c);
		if (part == WipePart::Hit)
		{
			++hit;
			cell.n_occupy += w;  // Eq. 8, part c
		}
		else
			++visited;
		cell.n_visit += w;  // parts b and c
	});
	st.cellsHit += hit;
	st.cellsVisited += visited;
	return hit + visited > 0;
}

// Eq. 8 for one scan q: the triangles of V_q over the map vectors near them.
ScanWipe::Stats ScanWipe::apply(const mrpt::math::TPoint2D& sensor, const std::vector<Segment>& scanVectors,
								std::vector<GridVector>& map, const VectorIndex& index, const SkipFn& limit)
{
	Stats st;
	marks_.clear();
	touched_.clear();
	if (offset_.size() < map.size()) offset_.resize(map.size(), 0);
	if (span_.size() < map.size()) span_.resize(map.size());
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
			mark(tri, m, cap, beams_, [&] { return marksOf(slot, m.cells().size()); }, span_[slot]);
		}
	}
	for (uint32_t slot : touched_)
	{
		st.vectorsTouched += add(marks_.data() + (offset_[slot] - 1), span_[slot], map[slot].cells(), beams_, st);
		offset_[slot] = 0;
		span_[slot] = Span{};
	}
	return st;
}

}  // namespace gridvector
