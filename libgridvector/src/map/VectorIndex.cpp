#include "map/VectorIndex.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridvector
{
Box2D Box2D::of(const GridVector& v)
{
	const auto d = v.direction(), n = v.leftNormal();
	const double res = v.resolution();
	const double u1 = v.cols() * res, w = (v.halfWidth() + 0.5) * res;
	Box2D b{1e300, 1e300, -1e300, -1e300};
	for (double u : {0.0, u1})
		for (double s : {-w, w})
		{
			const double x = v.start().x + u * d.x + s * n.x, y = v.start().y + u * d.y + s * n.y;
			b.minX = std::min(b.minX, x), b.maxX = std::max(b.maxX, x);
			b.minY = std::min(b.minY, y), b.maxY = std::max(b.maxY, y);
		}
	return b;
}

VectorIndex::VectorIndex(double cellSize) : cell_(cellSize)
{
	if (!(cellSize > 0)) throw std::invalid_argument("VectorIndex: cell size must be > 0");
}

void VectorIndex::clear()
{
	buckets_.clear();
	wide_.clear();
	boxes_.clear();
	present_.clear();
	live_ = 0;
}

bool VectorIndex::wide(const Box2D& b) const
{
	if (!(std::isfinite(b.minX) && std::isfinite(b.minY) && std::isfinite(b.maxX) && std::isfinite(b.maxY)))
		return true;
	const double nx = std::floor(b.maxX / cell_) - std::floor(b.minX / cell_) + 1;
	const double ny = std::floor(b.maxY / cell_) - std::floor(b.minY / cell_) + 1;
	return nx * ny > kMaxBuckets;
}

template <class F>
void VectorIndex::forBuckets(const Box2D& b, F&& f) const
{
	const int64_t x0 = int64_t(std::floor(b.minX / cell_)), x1 = int64_t(std::floor(b.maxX / cell_));
	const int64_t y0 = int64_t(std::floor(b.minY / cell_)), y1 = int64_t(std::floor(b.maxY / cell_));
	for (int64_t ix = x0; ix <= x1; ++ix)
		for (int64_t iy = y0; iy <= y1; ++iy) f(bucketKey(ix, iy));
}

void VectorIndex::insert(uint32_t slot, const Box2D& box)
{
	if (contains(slot)) remove(slot);
	if (slot >= boxes_.size())
	{
		boxes_.resize(slot + 1);
		present_.resize(slot + 1, 0);
	}
	boxes_[slot] = box;
	present_[slot] = 1;
	++live_;
	if (wide(box))
		wide_.push_back(slot);
	else
		forBuckets(box, [&](uint64_t k) { buckets_[k].push_back(slot); });
}

void VectorIndex::remove(uint32_t slot)
{
	if (!contains(slot)) return;
	present_[slot] = 0;
	--live_;
	if (wide(boxes_[slot]))
	{
		wide_.erase(std::find(wide_.begin(), wide_.end(), slot));
		return;
	}
	forBuckets(boxes_[slot], [&](uint64_t k) {
		auto it = buckets_.find(k);
		if (it == buckets_.end()) return;
		auto& v = it->second;
		auto p = std::find(v.begin(), v.end(), slot);
		if (p != v.end())
		{
			*p = v.back();
			v.pop_back();
		}
		if (v.empty()) buckets_.erase(it);
	});
}

namespace
{
using Buckets = std::unordered_map<uint64_t, std::vector<uint32_t>>;

/** Bucket index of coordinate v (as insert() and forBuckets() compute it). */
int64_t bucketOf(double v, double cell) { return int64_t(std::floor(v / cell)); }

// The buckets x0..x1 times y0..y1 in order (x, then y); a slot listed in several of them is reported
// in the first one the query visits, (max(its lowest x, x0), max(its lowest y, y0)): in a bucket past
// the query's first column (row) only if the slot's box starts in that column (row). Free functions
// (not members) so that the compiler inlines them into query().
template <class Key>
void queryRange(const Buckets& buckets, const std::vector<Box2D>& boxes, double cell, const Box2D& box,
				const int64_t x0, const int64_t x1, const int64_t y0, const int64_t y1, Key&& key,
				std::vector<uint32_t>& out)
{
	for (int64_t ix = x0; ix <= x1; ++ix)
		for (int64_t iy = y0; iy <= y1; ++iy)
		{
			const auto it = buckets.find(key(ix, iy));
			if (it == buckets.end()) continue;
			for (uint32_t s : it->second)
			{
				const Box2D& b = boxes[s];
				if (!b.intersects(box)) continue;
				if (ix != x0 && bucketOf(b.minX, cell) != ix) continue;  // reported before
				if (iy != y0 && bucketOf(b.minY, cell) != iy) continue;
				out.push_back(s);
			}
		}
}

// Every bucket in the map's order (a query wider than the map); the slots seen are marked in a set
// of this call's own.
void queryAll(const Buckets& buckets, const std::vector<Box2D>& boxes, const Box2D& box, std::vector<uint32_t>& out)
{
	std::vector<uint8_t> seen(boxes.size(), 0);
	for (const auto& kv : buckets)
		for (uint32_t s : kv.second)
		{
			if (seen[s]) continue;
			seen[s] = 1;
			if (boxes[s].intersects(box)) out.push_back(s);
		}
}
}  // namespace

// Writes nothing in the index: any number of threads may query at once.
void VectorIndex::query(const Box2D& box, std::vector<uint32_t>& out) const
{
	const double x0 = std::floor(box.minX / cell_), x1 = std::floor(box.maxX / cell_);
	const double y0 = std::floor(box.minY / cell_), y1 = std::floor(box.maxY / cell_);
	if (!((x1 - x0 + 1) * (y1 - y0 + 1) <= double(buckets_.size())))  // wider than the map (or not finite)
		queryAll(buckets_, boxes_, box, out);
	else
		queryRange(buckets_, boxes_, cell_, box, int64_t(x0), int64_t(x1), int64_t(y0), int64_t(y1), bucketKey, out);
	for (uint32_t s : wide_)  // listed once each
		if (boxes_[s].intersects(box)) out.push_back(s);
}

}  // namespace gridvector
