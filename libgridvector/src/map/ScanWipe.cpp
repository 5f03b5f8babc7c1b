#include "map/ScanWipe.h"

#include <algorithm>
#include <cstdint>

namespace gridvector
{
ScanWipe::Stats ScanWipe::apply(const mrpt::math::TPoint2D& sensor, const std::vector<GridVector>& scanVectors,
								std::vector<GridVector>& map, const VectorIndex& index, const SkipFn& limit)
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

WipeTriangle ScanWipe::triangleOf(const mrpt::math::TPoint2D& sensor, const Segment& v) const
{
	const double density = beams_ ? WipeTriangle::beamDensity(sensor, v.start, v.end, v.points) : 0.0;
	return WipeTriangle(sensor, v.start, v.end, hitBand_, density);
}

// Eq. 8 of one scan on m: the increments of the parts `wanted` minus those of the parts `applied`.
bool ScanWipe::complete(const std::vector<WipeTriangle>& tris, const std::vector<WipePart>& applied,
						const std::vector<WipePart>& wanted, GridVector& m, bool countBeams, Stats& st)
{
	std::vector<Mark> was(m.cells().size()), now(m.cells().size());
	Span spanWas, spanNow;
	const Box2D box = Box2D::of(m);
	for (size_t k = 0; k < tris.size(); ++k)
	{
		if (tris[k].misses(box.minX, box.minY, box.maxX, box.maxY)) continue;  // also a degenerate one
		if (applied[k] != WipePart::Outside)
			mark(
				tris[k], m, applied[k], countBeams, [&] { return was.data(); }, spanWas);
		if (wanted[k] != WipePart::Outside)
			mark(
				tris[k], m, wanted[k], countBeams, [&] { return now.data(); }, spanNow);
	}
	bool any = false;
	size_t hits = 0, visitsGone = 0, visits = 0;
	for (size_t i = spanNow.first; i < spanNow.last; ++i)
	{
		const Mark &a = was[i], &b = now[i];
		const bool hitA = a.hit > 0, hitB = b.hit > 0, markedA = hitA || a.pass != 0, markedB = hitB || b.pass != 0;
		GridCell& c = m.cells()[i];
		if (countBeams)
		{
			c.n_occupy += b.hit - a.hit;
			c.n_visit += (b.hit + b.pass) - (a.hit + a.pass);
		}
		else
		{
			c.n_occupy += float(hitB) - float(hitA);
			c.n_visit += float(markedB) - float(markedA);
		}
		any |= markedB != markedA || b.hit != a.hit || b.pass != a.pass;
		hits += hitB && !hitA;
		visitsGone += hitB && !hitA && markedA;  // a cell of part b only is now a hit
		visits += markedB && !markedA && !hitB;
	}
	st.cellsHit += hits;
	st.cellsVisited = st.cellsVisited + visits - std::min(st.cellsVisited + visits, visitsGone);
	return any;
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
		const WipeTriangle tri = triangleOf(sensor, scanVectors[seg]);
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
			mark(
				tri, m, cap, beams_, [&] { return marksOf(slot, m.cells().size()); }, span_[slot]);
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
