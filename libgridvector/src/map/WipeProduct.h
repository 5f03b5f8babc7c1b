// Eq. 8 over a whole trajectory: every scan's wipe triangles over every other scan's vectors.
#pragma once

#include <gridvector/GridVector.h>
#include "map/ScanWipe.h"

#include <mrpt/math/TPoint2D.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace gridvector
{
/** The full product of Eq. 8 in batch mode, prod_q prod_{v_j in V_q} p(m_{i,p} | v_j, x_q)
 * for every per-scan vector m_{i,p} and every scan q != p, computed map vector
 * by map vector: the triangles of all scans are built once and indexed, and
 * each vector takes the triangles whose box meets its band, scan by scan in
 * ascending order. Every cell receives the same increments in the same order
 * as ScanWipe::apply run scan by scan (the scan's own vectors left out), so
 * the result is the same bit for bit in both weightings; only the memory
 * access differs (one vector's cells stay in cache while all its scans are
 * added, instead of every scan visiting every vector it reaches).
 *
 * Cost: O(pairs (triangle, vector) whose boxes meet) + O(cells reached):
 * for a fixed world this grows with the square of the passes through each
 * place (every pass's vectors are wiped by every other pass's scans). */
/** Beyond the paper (Eq. 8 takes every scan q != p): with a pass gap, a map vector m_{i,p} takes the
 * triangles of its own pass through the place and of the kWipePasses passes before and after it only
 * (a pass: the scans whose triangles reach m, at most the gap apart in time). Eq. 6 is a ratio of hits to
 * passes through a cell, which those passes already estimate; the others would add evidence on the same
 * cells at a cost that grows with the square of the passes through the place. Logs whose vectors are
 * reached by at most 2 x kWipePasses + 1 passes keep the full product bit for bit. */
constexpr size_t kWipePasses = 2;

class WipeProduct
{
   public:
	/** hitBand, countBeams: as ScanWipe; indexCellSize: bucket side of the triangles' spatial index [m];
	 * passGap: scans further apart than this belong to different passes (kWipePasses; 0: every scan). */
	WipeProduct(double hitBand, bool countBeams, double indexCellSize, uint32_t passGap = 0)
		: hitBand_(hitBand), beams_(countBeams), cell_(indexCellSize), passGap_(passGap)
	{}

	/** map: the per-scan vectors in global coordinates, those of scan t at
	 * positions [first[t], first[t + 1]) (first.size() == sensors.size() + 1);
	 * sensors[t]: the sensor position of scan t (the triangles' apex). */
	ScanWipe::Stats apply(const std::vector<mrpt::math::TPoint2D>& sensors, const std::vector<size_t>& first,
						  std::vector<GridVector>& map) const;

   private:
	double hitBand_;
	bool beams_;
	double cell_;
	uint32_t passGap_;
};

}  // namespace gridvector
