// Sec. 5.5, Table 1: the grid vector map held in the bytes its information needs (Eq. 1-2).
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <cstdint>
#include <vector>

namespace gridvector
{
/** A map's vectors in one contiguous byte buffer: how the .gvmap stores a map from version 2 on, and
 * what report.json's "memory" counts as the map's bytes. EM and CGridVectorMap still work on the float
 * GridVectors ("bytes_working_form" beside it).
 *
 * Per vector (Eq. 1): endpoints on a 1 mm lattice (the start as a difference from the previous
 * vector's, the end from the start), cols, t, id (a difference), mergedCount and the timestamp
 * (hundredths of a second from the map's first) as varints; one byte with c_i, whether its
 * n_acc are whole numbers (Algorithm 1 counts points, Algorithm 2 moves them whole: then
 * varints) and a power-of-two scale 2^k of its counts.
 * Per cell (Eq. 2) a 2-bit kind, then only what the kind needs:
 *   0  no counts, no points (a cell of a merged grid no part covered): nothing;
 *   1  counts on the prior's ratio, no points (never observed): n_visit;
 *   2  observed, no points (a free cell crossed by beams): n_occupy, n_visit;
 *   3  with points: n_occupy, n_visit, n_acc and the gravity centre (x_acc, y_acc) / n_acc.
 * A vector whose counts reach 2^46 (k > 31) cannot be stored (std::invalid_argument), nor a
 * coordinate beyond 10^9 m.
 * Counts are IEEE half floats of count / 2^k (k >= 0, chosen so the largest count of the
 * vector stays below 2^15): relative precision 2^-11, so Eq. 6's n_occupy / n_visit is kept
 * to 0.1 % and the totals Algorithm 2 conserves to 0.05 %. The gravity centre is one byte per
 * axis over [-1/2, 3/2) cells (a merged cell's centre may lie just beyond it): 0.8 mm at 10 cm.
 * The grid's rows (2 h + 1) and resolution come from the config, as in every .gvmap. */
class CompactMap
{
   public:
	CompactMap() = default;
	static CompactMap encode(const std::vector<GridVector>& vectors);
	/** The vectors again, with the grid options they were made with (resolution, half width,
	 * prior). Throws std::runtime_error("compact map: ...") on a buffer that is not one. */
	std::vector<GridVector> decode(const GridOptions& grid) const;
	/** A buffer as stored (a .gvmap); decode() checks it. */
	static CompactMap fromBytes(std::vector<uint8_t> bytes);

	const std::vector<uint8_t>& bytes() const { return bytes_; }
	size_t vectorCount() const { return count_; }
	/** What the object holds: itself and its buffer (no slack: the buffer is shrunk to fit). */
	size_t memoryBytes() const { return sizeof(*this) + bytes_.capacity(); }

	/** Counts of a vector are scaled by 2^-k so that its largest stays below this (half floats reach 65504). */
	static constexpr float kHalfCountCeiling = 32768.f;

   private:
	std::vector<uint8_t> bytes_;
	size_t count_ = 0;
};

}  // namespace gridvector
