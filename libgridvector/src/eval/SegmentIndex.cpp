#include "eval/SegmentIndex.h"

#include <algorithm>
#include <cmath>

namespace gridvector::eval
{
SegmentIndex::SegmentIndex(std::vector<sim::Segment> segs, double cell) : segs_(std::move(segs)), cell_(cell)
{
	for (size_t k = 0; k < segs_.size(); k++)
	{
		const auto& s = segs_[k];
		const double len = s.length();
		const int samples = int(std::ceil(len / (0.5 * cell_))) + 1;
		std::vector<long> keys;  // every cell the segment passes through (sampled finer than a cell)
		for (int q = 0; q <= samples; q++)
		{
			const sim::Vec2 p = s.at(double(q) / samples);
			keys.push_back(key(long(std::floor(p.x / cell_)), long(std::floor(p.y / cell_))));
		}
		std::sort(keys.begin(), keys.end());
		keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
		for (long kk : keys) grid_[kk].push_back(k);
	}
}

double SegmentIndex::nearest(const sim::Vec2& p, double maxDist) const
{
	// a segment crossing a cell is within cell*sqrt(2) of any point in it: widen the search by one cell
	const long i0 = long(std::floor((p.x - maxDist) / cell_)) - 1, i1 = long(std::floor((p.x + maxDist) / cell_)) + 1;
	const long j0 = long(std::floor((p.y - maxDist) / cell_)) - 1, j1 = long(std::floor((p.y + maxDist) / cell_)) + 1;
	double best = sim::kNoHit;
	for (long i = i0; i <= i1; i++)
		for (long j = j0; j <= j1; j++)
		{
			const auto it = grid_.find(key(i, j));
			if (it == grid_.end()) continue;
			for (size_t k : it->second) best = std::min(best, sim::distanceToSegment(p, segs_[k]));
		}
	return best <= maxDist ? best : sim::kNoHit;
}

}  // namespace gridvector::eval
