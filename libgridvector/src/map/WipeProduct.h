// Eq. 8 over a whole trajectory: every scan's wipe triangles over every other scan's vectors.
#pragma once

#include <gridvector/GridVector.h>
#include "map/ScanWipe.h"

#include <mrpt/math/TPoint2D.h>

#include <cstddef>
#include <vector>

namespace gridvector
{
/** The full product of Eq. 8 in batch mode, prod_q prod_{v_j in V_q} p(m_{i,p} | v_j, x_q)
 * for every per-scan vector m_{i,p} and every scan q != p, computed map vector
 * by map vector: the triangles of all scans are built once and listed in the
 * buckets they reach (TriangleBuckets), and each vector takes the triangles
 * that may reach its band, scan by scan in ascending order. Every cell receives the same increments in the same order
 * as ScanWipe::apply run scan by scan (the scan's own vectors left out), so
 * the result is the same bit for bit in both weightings; only the memory
 * access differs (one vector's cells stay in cache while all its scans are
 * added, instead of every scan visiting every vector it reaches).
 *
 * Cost: O(pairs (triangle, vector) whose boxes meet) + O(cells reached):
 * for a fixed world this grows with the square of the passes through each
 * place (every pass's vectors are wiped by every other pass's scans). */
class WipeProduct
{
   public:
	/** hitBand, countBeams: as ScanWipe; indexCellSize: bucket side of the triangles' buckets [m] (speed only). */
	WipeProduct(double hitBand, bool countBeams, double indexCellSize)
		: hitBand_(hitBand), beams_(countBeams), cell_(indexCellSize)
	{}

	/** map: the per-scan vectors in global coordinates, those of scan t at
	 * positions [first[t], first[t + 1]) (first.size() == sensors.size() + 1);
	 * sensors[t]: the sensor position of scan t (the triangles' apex). */
	ScanWipe::Stats apply(const std::vector<mrpt::math::TPoint2D>& sensors, const std::vector<size_t>& first,
						  std::vector<GridVector>& map) const;
	/** The same with scan t's triangles at hitBands[t] (ScanWipe::hitBandFor) instead of hitBand. */
	ScanWipe::Stats apply(const std::vector<mrpt::math::TPoint2D>& sensors, const std::vector<size_t>& first,
						  std::vector<GridVector>& map, const std::vector<double>& hitBands) const;

   private:
	double hitBand_;
	bool beams_;
	double cell_;
};

}  // namespace gridvector
