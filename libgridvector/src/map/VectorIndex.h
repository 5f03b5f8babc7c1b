// Sec. 3.2: spatial hash over the map vectors, so a scan's update touches only nearby vectors.
#pragma once

#include <gridvector/GridVector.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace gridvector
{
/** Key of the bucket (ix, iy) of a uniform spatial hash (32 bits per coordinate). */
inline uint64_t bucketKey(int64_t ix, int64_t iy)
{
	return (uint64_t(uint32_t(int32_t(ix))) << 32) | uint64_t(uint32_t(int32_t(iy)));
}

/** Axis-aligned box [minX, maxX] x [minY, maxY]. */
struct Box2D
{
	double minX = 0, minY = 0, maxX = -1, maxY = -1;
	bool intersects(const Box2D& o) const
	{
		return minX <= o.maxX && o.minX <= maxX && minY <= o.maxY && o.minY <= maxY;
	}
	Box2D expanded(double m) const { return {minX - m, minY - m, maxX + m, maxY + m}; }
	bool holds(double x, double y) const { return x >= minX && x <= maxX && y >= minY && y <= maxY; }
	/** The box of a vector's whole grid band (all rows and columns). */
	static Box2D of(const GridVector& v);
};

/** Uniform spatial hash: buckets of side `cellSize` keyed by integer
 * coordinates; each vector (a slot number chosen by the owner) is listed in
 * every bucket its box overlaps.
 *
 * Complexity (k = vectors whose boxes meet the query box, B = bucket size,
 * l = a vector's box side): insert/remove O((l/B + 1)^2); query
 * O((q/B + 1)^2 + k) for a query box of side q. A scan's Eq. 8 update queries
 * the box of each wipe triangle (side <= the sensor range R), so its cost is
 * O(n_t ((R/B + 1)^2 + k)) with n_t the scan's vectors: it depends on the map
 * density around the robot, not on the map's size.
 *
 * A box that would cover more than kMaxBuckets buckets (or is not finite)
 * is kept in one list that every query scans instead of being listed bucket
 * by bucket: memory stays O(slots) whatever the boxes' sizes. (Wipe triangles
 * of walls seen at grazing angles had such boxes while their hit band reached
 * along the rays past the vector's ends; bounded to the vector since, they
 * stay under the cap on every benchmark log.)
 *
 * query() writes nothing in the index (a slot listed in several buckets is
 * reported at the first of them the query visits, known from its box), so
 * any number of threads may query one index at once while none modifies it. */
class VectorIndex
{
   public:
	/** Bucket side of the map's indexes: a few wall lengths, so a query visits a handful of
	 * buckets; it changes speed only, never which vectors are found [m]. */
	static constexpr double kCellSize = 2.0;

	explicit VectorIndex(double cellSize = kCellSize);

	void clear();
	double cellSize() const { return cell_; }
	size_t size() const { return live_; }
	bool contains(uint32_t slot) const { return slot < boxes_.size() && present_[slot]; }
	const Box2D& box(uint32_t slot) const { return boxes_[slot]; }

	/** Adds slot with its box (a slot already present is moved). */
	void insert(uint32_t slot, const Box2D& box);
	void remove(uint32_t slot);
	/** Appends to out every slot whose box intersects `box`, each once. */
	void query(const Box2D& box, std::vector<uint32_t>& out) const;

   private:
	/** Boxes covering more buckets than this are listed once, not per bucket (memory bound, no effect on results). */
	static constexpr double kMaxBuckets = 4096;
	bool wide(const Box2D& b) const;
	template <class F>
	void forBuckets(const Box2D& b, F&& f) const;

	double cell_;
	std::unordered_map<uint64_t, std::vector<uint32_t>> buckets_;
	std::vector<uint32_t> wide_;  //!< slots whose boxes are too large (or not finite) for the buckets
	std::vector<Box2D> boxes_;
	std::vector<uint8_t> present_;
	size_t live_ = 0;
};

}  // namespace gridvector
