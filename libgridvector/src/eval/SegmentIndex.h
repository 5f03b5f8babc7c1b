// Uniform-grid index over segments for "is anything within r of this point" queries.
#pragma once

#include "sim/Geometry.h"

#include <unordered_map>
#include <vector>

namespace gridvector::eval
{
class SegmentIndex
{
   public:
	explicit SegmentIndex(std::vector<sim::Segment> segs, double cell = 1.0);
	/** Distance from p to the nearest segment if it is <= maxDist, else +inf. */
	double nearest(const sim::Vec2& p, double maxDist) const;
	bool within(const sim::Vec2& p, double r) const { return nearest(p, r) <= r; }
	bool empty() const { return segs_.empty(); }

   private:
	long key(long i, long j) const { return i * 1000003L + j; }
	std::vector<sim::Segment> segs_;
	double cell_;
	std::unordered_map<long, std::vector<size_t>> grid_;
};

}  // namespace gridvector::eval
