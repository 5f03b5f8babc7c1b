// Eq. 8: the update of the map vectors by all wipe triangles of one scan.
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/VectorIndex.h>
#include <gridvector/WipeTriangle.h>

#include <mrpt/math/TPoint2D.h>

#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

namespace gridvector
{
/** prod_{m_{i,p}} prod_{v_j in V_q} p(m_{i,p} | v_j, x_q) of Eq. 8 for one scan q:
 * the triangles of every vector of V_q (sensor position and vectors in global
 * coordinates) update each map vector found through the spatial index.
 *
 * One scan observes a cell once: if two of the scan's triangles reach the same
 * cell (the shared ray of adjacent vectors at a corner), the cell is counted
 * once, as a hit if either triangle says hit (part c wins over part b). Each
 * increment weighs 1 (see WipeTriangle).
 *
 * Keeps scratch buffers between calls; one instance per thread. */
class ScanWipe
{
   public:
	explicit ScanWipe(double hitBand) : hitBand_(hitBand) {}

	struct Stats
	{
		size_t triangles = 0;  //!< non-degenerate triangles
		size_t candidates = 0;  //!< (triangle, map vector) pairs from the index
		size_t vectorsTouched = 0;  //!< map vectors with at least one cell updated
		size_t cellsHit = 0;  //!< cells of part c
		size_t cellsVisited = 0;  //!< cells of part b
	};

	/** A new vector's endpoints in global coordinates. */
	struct Segment
	{
		mrpt::math::TPoint2D start, end;
	};

	/** skip(slot) true: the map vector is not updated by this scan (its own
	 * vectors, already counted by Algorithm 1). */
	Stats apply(const mrpt::math::TPoint2D& sensor, const std::vector<Segment>& scanVectors,
				std::vector<GridVector>& map, const VectorIndex& index,
				const std::function<bool(uint32_t)>& skip = {});
	Stats apply(const mrpt::math::TPoint2D& sensor, const std::vector<GridVector>& scanVectors,
				std::vector<GridVector>& map, const VectorIndex& index,
				const std::function<bool(uint32_t)>& skip = {});

   private:
	double hitBand_;
	std::vector<uint32_t> candidates_;
	std::vector<uint8_t> marks_;  //!< WipePart per cell of the touched vectors, back to back
	std::unordered_map<uint32_t, size_t> offset_;  //!< slot -> first mark
	std::vector<uint32_t> touched_;
};

}  // namespace gridvector
