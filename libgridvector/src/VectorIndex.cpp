#include <gridvector/VectorIndex.h>

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
	stamp_.clear();
	live_ = 0;
}

bool VectorIndex::wide(const Box2D& b) const
{
	if (!(std::isfinite(b.minX) && std::isfinite(b.minY) && std::isfinite(b.maxX) && std::isfinite(b.maxY))) return true;
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
		for (int64_t iy = y0; iy <= y1; ++iy) f(key(ix, iy));
}

void VectorIndex::insert(uint32_t slot, const Box2D& box)
{
	if (contains(slot)) remove(slot);
	if (slot >= boxes_.size())
	{
		boxes_.resize(slot + 1);
		present_.resize(slot + 1, 0);
		stamp_.resize(slot + 1, 0);
	}
	boxes_[slot] = box;
	present_[slot] = 1;
	++live_;
	if (wide(box)) wide_.push_back(slot);
	else forBuckets(box, [&](uint64_t k) { buckets_[k].push_back(slot); });
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

void VectorIndex::query(const Box2D& box, std::vector<uint32_t>& out) const
{
	if (++query_ == 0)  // stamp wrapped: reset
	{
		std::fill(stamp_.begin(), stamp_.end(), 0);
		query_ = 1;
	}
	auto scan = [&](const std::vector<uint32_t>& slots) {
		for (uint32_t s : slots)
		{
			if (stamp_[s] == query_) continue;
			stamp_[s] = query_;
			if (boxes_[s].intersects(box)) out.push_back(s);
		}
	};
	const double nx = std::floor(box.maxX / cell_) - std::floor(box.minX / cell_) + 1;
	const double ny = std::floor(box.maxY / cell_) - std::floor(box.minY / cell_) + 1;
	if (!(nx * ny <= double(buckets_.size())))  // a query wider than the map (or not finite): walk the buckets
		for (const auto& kv : buckets_) scan(kv.second);
	else
		forBuckets(box, [&](uint64_t k) {
			auto it = buckets_.find(k);
			if (it != buckets_.end()) scan(it->second);
		});
	scan(wide_);
}

}  // namespace gridvector
