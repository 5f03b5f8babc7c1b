// Eq. 8: the update of the map vectors by all wipe triangles of one scan.
#pragma once

#include <gridvector/GridVectorConfig.h>
#include <gridvector/LocalScan.h>

#include <gridvector/GridVector.h>
#include "map/VectorIndex.h"
#include "map/WipeTriangle.h"

#include <mrpt/math/TPoint2D.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <utility>
#include <vector>

namespace gridvector
{
/** prod_{m_{i,p}} prod_{v_j in V_q} p(m_{i,p} | v_j, x_q) of Eq. 8 for one scan q:
 * the triangles of every vector of V_q (sensor position and vectors in global
 * coordinates) update each map vector found through the spatial index.
 *
 * Two weightings (WipeTriangle):
 *  - per cell (countBeams = false, the paper's Fig. 2): one scan observes a
 *    cell once; if two of its triangles reach the same cell (the shared ray of
 *    adjacent vectors at a corner), the cell counts once, as a hit if either
 *    triangle says hit;
 *  - per beam (countBeams = true): each triangle adds the number of its beams
 *    crossing the cell (Segment::points endpoints spread over the fan), so
 *    that wipes and Algorithm 1 count in the same unit; contributions of
 *    several triangles add up (they are different beams).
 *
 * Keeps scratch buffers between calls; one instance per thread. */
class ScanWipe
{
   public:
	explicit ScanWipe(double hitBand, bool countBeams = true) : hitBand_(hitBand), beams_(countBeams) {}

	/** Eq. 8 part c's band for a scan: map.hit_band, or its scanner's noise allowance where that is wider
	 * (a cell within the range noise of the line is not seen through; ExtractionOptions::noiseAllowance). */
	static double hitBandFor(const GridVectorConfig& cfg, const LocalScan& scan)
	{
		return std::max(cfg.map.hitBand, cfg.extraction.noiseAllowance(scan.rangeSigma));
	}
	/** The band of the triangles made from now on (a scan's: hitBandFor). */
	void setHitBand(double hitBand) { hitBand_ = hitBand; }

	struct Stats
	{
		size_t triangles = 0;  //!< non-degenerate triangles
		size_t candidates = 0;  //!< (triangle, map vector) pairs from the index
		size_t vectorsTouched = 0;  //!< map vectors with at least one cell updated
		size_t cellsHit = 0;  //!< cells of part c
		size_t cellsVisited = 0;  //!< cells of part b only
	};

	/** A new vector in global coordinates and the beam endpoints it was built
	 * from (its n_acc total; used by the per-beam weighting). */
	struct Segment
	{
		mrpt::math::TPoint2D start, end;
		double points = 0;
	};

	/** limit(segment, slot): which parts of the triangle of scanVectors[segment]
	 * update map vector `slot`: Hit = all (b and c), Visited = part b only,
	 * Outside = none. The scan's own vectors get none (Algorithm 1 counted
	 * them); in sequential mode the map vectors a new vector is about to be
	 * merged into get part b only: its endpoints reach them through its own
	 * Algorithm 1 counts, the beams passing in front of it only through the wipe. */
	using SkipFn = std::function<WipePart(size_t segment, uint32_t slot)>;
	/** `index` lists every map vector's slot with its Box2D::of box (a candidate
	 * whose box lies beyond one edge of a triangle is skipped without reading it). */
	Stats apply(const mrpt::math::TPoint2D& sensor, const std::vector<Segment>& scanVectors,
				std::vector<GridVector>& map, const VectorIndex& index, const SkipFn& limit = {});
	Stats apply(const mrpt::math::TPoint2D& sensor, const std::vector<GridVector>& scanVectors,
				std::vector<GridVector>& map, const VectorIndex& index, const SkipFn& limit = {});

	static Segment segmentOf(const GridVector& globalVector)
	{
		return {globalVector.start(), globalVector.end(), globalVector.totalPoints()};
	}
	/** The wipe triangle apply() builds for a new vector seen from `sensor`. */
	WipeTriangle triangleOf(const mrpt::math::TPoint2D& sensor, const Segment& v) const;

	/** Eq. 8 of one scan on m, completed: the scan's triangles `tris` were applied
	 * to m with the parts `applied[k]` (apply()'s limit) and m gets what the parts
	 * `wanted[k]` (each at least applied[k]) add on top. Exact in both weightings
	 * (per cell: a cell still counts once per scan, a hit if any triangle says
	 * hit). True if a cell changed. */
	static bool complete(const std::vector<WipeTriangle>& tris, const std::vector<WipePart>& applied,
						 const std::vector<WipePart>& wanted, GridVector& m, bool countBeams, Stats& st);

	/** What one scan's triangles leave on a map cell before Eq. 8 adds it
	 * (per cell: 1 or 0; per beam: the beams counted). */
	struct Mark
	{
		float hit = 0, pass = 0;
	};
	/** Cells [first, last) of a map vector that a scan's marks cover. */
	struct Span
	{
		uint32_t first = UINT32_MAX, last = 0;
	};
	/** One triangle on map vector m, parts up to `cap`: marks m's cells
	 * (row-major, as m.cells()) and widens `span`. `marks()` returns the
	 * vector's marks; it is called when the triangle first reaches a cell. */
	template <class GetMarks>
	static void mark(const WipeTriangle& tri, const GridVector& m, WipePart cap, bool countBeams, GetMarks&& marks,
					 Span& span);
	/** Eq. 8 with one scan's marks on `cells` (those in span), counted into
	 * st; the marks are zeroed for the next scan. True if any cell changed. */
	static bool add(Mark* marks, const Span& span, std::vector<GridCell>& cells, bool countBeams, Stats& st);
	/** mark() then add() for a scan of which only this triangle reaches m
	 * (no other triangle to share a cell with): the same increments, no marks. */
	static bool addAlone(const WipeTriangle& tri, GridVector& m, bool countBeams, Stats& st);

   private:
	Mark* marksOf(uint32_t slot, size_t cells);
	double hitBand_;
	bool beams_;
	std::vector<uint32_t> candidates_;
	std::vector<Mark> marks_;  //!< per cell of the touched vectors, back to back
	std::vector<size_t> offset_;  //!< slot -> first mark + 1 (0: not touched by this scan)
	std::vector<uint32_t> touched_;
	std::vector<Span> span_;  //!< slot -> cells touched by this scan
};

template <class GetMarks>
void ScanWipe::mark(const WipeTriangle& tri, const GridVector& m, WipePart cap, bool countBeams, GetMarks&& marks,
					Span& span)
{
	Mark* mk = nullptr;  // the vector's marks, fetched when the triangle reaches one of its cells
	const uint32_t cols = uint32_t(m.cols());
	const mrpt::math::TPoint2D axis = m.direction();
	const double res = m.resolution();
	tri.forEachCellAt(m, [&](int r, int c, WipePart part, const mrpt::math::TPoint2D& centre) {
		if (part > cap) return;
		if (!mk) mk = marks();
		const uint32_t i = uint32_t(r) * cols + uint32_t(c);
		span.first = std::min(span.first, i);
		span.last = std::max(span.last, i + 1);
		Mark& x = mk[i];
		float& w = part == WipePart::Hit ? x.hit : x.pass;
		w = countBeams ? w + float(tri.weight(centre, axis, res, part)) : 1.f;  // per beam: add; per cell: once
	});
}

}  // namespace gridvector
