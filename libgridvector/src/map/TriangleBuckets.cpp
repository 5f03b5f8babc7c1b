#include "map/TriangleBuckets.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridvector
{
namespace
{
/** Bucket coordinates beyond this (a box not finite, or absurdly far) do not fit the 32-bit keys: such a
 * triangle is kept in the list every query scans. */
constexpr double kMaxIndex = 1e9;
}  // namespace

TriangleBuckets::TriangleBuckets(double cellSize) : cell_(cellSize)
{
	if (!(cellSize > 0)) throw std::invalid_argument("TriangleBuckets: cell size must be > 0");
}

void TriangleBuckets::insert(uint32_t id, const WipeTriangle& tri)
{
	if (tri.degenerate()) return;
	if (id >= seen_.size()) seen_.resize(size_t(id) + 1, 0);
	const double fx0 = std::floor(tri.minX() / cell_), fx1 = std::floor(tri.maxX() / cell_);
	const double fy0 = std::floor(tri.minY() / cell_), fy1 = std::floor(tri.maxY() / cell_);
	if (!(std::abs(fx0) < kMaxIndex && std::abs(fx1) < kMaxIndex && std::abs(fy0) < kMaxIndex &&
		  std::abs(fy1) < kMaxIndex))
	{
		wide_.push_back(id);
		return;
	}
	insertRange(id, tri, int64_t(fx0), int64_t(fx1), int64_t(fy0), int64_t(fy1));
}

// Halving the range: a block the triangle misses is left with all its buckets, so the work follows the
// triangle's area and outline, not its box.
void TriangleBuckets::insertRange(uint32_t id, const WipeTriangle& tri, int64_t x0, int64_t x1, int64_t y0,
								  int64_t y1)
{
	if (tri.misses(double(x0) * cell_, double(y0) * cell_, double(x1 + 1) * cell_, double(y1 + 1) * cell_)) return;
	if (x0 == x1 && y0 == y1)
	{
		buckets_[bucketKey(x0, y0)].push_back(id);
		return;
	}
	if (x1 - x0 >= y1 - y0)
	{
		const int64_t xm = x0 + (x1 - x0) / 2;
		insertRange(id, tri, x0, xm, y0, y1);
		insertRange(id, tri, xm + 1, x1, y0, y1);
	}
	else
	{
		const int64_t ym = y0 + (y1 - y0) / 2;
		insertRange(id, tri, x0, x1, y0, ym);
		insertRange(id, tri, x0, x1, ym + 1, y1);
	}
}

void TriangleBuckets::query(const Box2D& box, std::vector<uint32_t>& out) const
{
	const size_t begin = out.size();
	if (++stamp_ == 0)  // wrapped: no stamp of an earlier query may match
	{
		std::fill(seen_.begin(), seen_.end(), 0);
		stamp_ = 1;
	}
	auto add = [&](uint32_t id) {
		if (seen_[id] == stamp_) return;
		seen_[id] = stamp_;
		out.push_back(id);
	};
	const double fx0 = std::floor(box.minX / cell_), fx1 = std::floor(box.maxX / cell_);
	const double fy0 = std::floor(box.minY / cell_), fy1 = std::floor(box.maxY / cell_);
	if ((fx1 - fx0 + 1) * (fy1 - fy0 + 1) <= double(buckets_.size()))
	{
		for (int64_t ix = int64_t(fx0); ix <= int64_t(fx1); ++ix)
			for (int64_t iy = int64_t(fy0); iy <= int64_t(fy1); ++iy)
			{
				const auto it = buckets_.find(bucketKey(ix, iy));
				if (it != buckets_.end())
					for (uint32_t id : it->second) add(id);
			}
	}
	else  // wider than the listed buckets (or not finite): every bucket meeting the box
		for (const auto& [k, ids] : buckets_)
		{
			const double x = double(int32_t(uint32_t(k >> 32))) * cell_, y = double(int32_t(uint32_t(k))) * cell_;
			if (Box2D{x, y, x + cell_, y + cell_}.intersects(box))
				for (uint32_t id : ids) add(id);
		}
	for (uint32_t id : wide_) add(id);
	std::sort(out.begin() + long(begin), out.end());
}

}  // namespace gridvector
