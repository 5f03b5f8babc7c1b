// Eq. 8 extended (beyond the paper, map.wipe_vectorless_beams): the beams that made no vector.
#pragma once

#include <gridvector/GridVector.h>
#include "extraction/VectorExtractor.h"
#include "map/VectorIndex.h"

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cstdint>
#include <vector>

namespace gridvector
{
/** The beams of one scan that no extracted vector explains (robot frame):
 * beams ending in clutter (their endpoint lies in none of the scan's own
 * vectors' grids) and beams without a usable return (invalid, too short, at
 * maximum range), which end at the scan's maximum range without a hit. */
struct ScanBeams
{
	mrpt::math::TPoint2D origin{0, 0};  //!< sensor position (robot frame)
	std::vector<mrpt::math::TPoint2D> ends;  //!< beam ends (robot frame)
	std::vector<uint8_t> returned;  //!< 1: the end is an obstacle (a range reading)

	/** The beams of `scan` not explained by `own` (its extraction). */
	static ScanBeams of(const mrpt::obs::CObservation2DRangeScan& scan, const LocalScan& own,
						double minRange = 0.0);
};

/** Eq. 8 only updates map cells through the wipe triangles of extracted
 * vectors, so beams that end in clutter or at maximum range never clear the
 * map vectors' cells they cross, and clutter hits inside a map vector's grid
 * are not counted; an occupancy grid counts every beam. This opt-in
 * extension (beyond the paper) credits each unexplained beam, in the unit of
 * Algorithm 1 and the per-beam wipe (one per beam): n_visit += 1 in every cell
 * of a map vector it crosses before its end, and n_occupy += 1, n_visit += 1
 * in the cell its end lies in (returned beams only). Map vectors of the same
 * scan (scanIndex == ownScan >= 0) are skipped.
 * Cost: per beam, the spatial index query of its box plus the cells crossed
 * (Amanatides-Woo traversal of each candidate's grid). */
class BeamWipe
{
   public:
	struct Stats
	{
		size_t beams = 0;  //!< beams credited
		size_t candidates = 0;  //!< (beam, map vector) pairs from the index
		size_t cellsHit = 0, cellsVisited = 0;
	};

	static Stats apply(const mrpt::math::TPose2D& robotPose, const ScanBeams& beams, std::vector<GridVector>& map,
					   const VectorIndex& index, int64_t ownScan = -1);

	/** The cells of m's grid the segment a -> b (global) crosses, in order:
	 * f(row, col, last) with last = true for the cell containing b. */
	template <class F>
	static void traverse(const GridVector& m, const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b, F&& f);
};

template <class F>
void BeamWipe::traverse(const GridVector& m, const mrpt::math::TPoint2D& a, const mrpt::math::TPoint2D& b, F&& f)
{
	// grid coordinates: X = u / res (column = floor X), Y = w / res + h + 1/2 (row = floor Y)
	const double res = m.resolution();
	const mrpt::math::TPoint2D ga = m.toGridFrame(a), gb = m.toGridFrame(b);
	const double x0 = ga.x / res, y0 = ga.y / res + m.halfWidth() + 0.5;
	const double dx = gb.x / res - x0, dy = gb.y / res + m.halfWidth() + 0.5 - y0;
	// Liang-Barsky clip of t in [0, 1] to the box [0, cols] x [0, rows]
	double t0 = 0, t1 = 1;
	auto clip = [&](double p, double q) {  // p t <= q
		if (std::abs(p) < 1e-15) return q >= 0;
		const double r = q / p;
		if (p < 0) t0 = std::max(t0, r);
		else t1 = std::min(t1, r);
		return t0 <= t1;
	};
	if (!clip(-dx, x0) || !clip(dx, m.cols() - x0) || !clip(-dy, y0) || !clip(dy, m.rows() - y0)) return;
	const double eps = 1e-9;
	const double xs = x0 + (t0 + eps) * dx, ys = y0 + (t0 + eps) * dy;
	int col = std::clamp(int(std::floor(xs)), 0, m.cols() - 1), row = std::clamp(int(std::floor(ys)), 0, m.rows() - 1);
	const bool endsInside = t1 >= 1.0;
	const int stepX = dx > 0 ? 1 : -1, stepY = dy > 0 ? 1 : -1;
	const double tdx = std::abs(dx) > 1e-15 ? 1.0 / std::abs(dx) : 1e300;
	const double tdy = std::abs(dy) > 1e-15 ? 1.0 / std::abs(dy) : 1e300;
	double tmx = std::abs(dx) > 1e-15 ? ((dx > 0 ? col + 1 - x0 : x0 - col) / std::abs(dx)) : 1e300;
	double tmy = std::abs(dy) > 1e-15 ? ((dy > 0 ? row + 1 - y0 : y0 - row) / std::abs(dy)) : 1e300;
	while (true)
	{
		const double tNext = std::min(tmx, tmy);
		const bool last = tNext >= t1;
		f(row, col, last && endsInside);
		if (last) return;
		if (tmx < tmy) col += stepX, tmx += tdx;
		else row += stepY, tmy += tdy;
		if (col < 0 || col >= m.cols() || row < 0 || row >= m.rows()) return;
	}
}

}  // namespace gridvector
