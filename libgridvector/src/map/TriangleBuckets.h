// Eq. 8 in batch mode: the wipe triangles listed in the buckets their area reaches, not in those of their box.
#pragma once

#include "map/VectorIndex.h"
#include "map/WipeTriangle.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace gridvector
{
/** Uniform buckets of side `cellSize`; a triangle is listed in each bucket of its box that it does not miss
 * (WipeTriangle::misses on the bucket's square). A wipe triangle is a thin wedge from the sensor, its box up to
 * the sensor range square: listed by area, a query for a short vector's band returns a few triangles per pass
 * instead of every triangle whose box spans the place.
 *
 * Exact: a triangle that updates a cell has the cell's centre in its parts b or c, so it does not miss the
 * bucket holding that centre, which meets any box holding the cell: query() returns every triangle that can
 * update a cell of a vector whose band lies in the box (and some that cannot). */
class TriangleBuckets
{
   public:
	explicit TriangleBuckets(double cellSize);

	/** Lists triangle `id` (ids dense from 0; a degenerate triangle is not listed). */
	void insert(uint32_t id, const WipeTriangle& tri);
	/** Appends to out, each once and in ascending order, every triangle listed in a bucket meeting `box`. */
	void query(const Box2D& box, std::vector<uint32_t>& out) const;

   private:
	void insertRange(uint32_t id, const WipeTriangle& tri, int64_t x0, int64_t x1, int64_t y0, int64_t y1);

	double cell_;
	std::unordered_map<uint64_t, std::vector<uint32_t>> buckets_;
	std::vector<uint32_t> wide_;  //!< triangles whose boxes have no bucket coordinates (not finite, absurdly far)
	mutable std::vector<uint32_t> seen_;  //!< per id: the stamp of the last query that returned it
	mutable uint32_t stamp_ = 0;
};

}  // namespace gridvector
