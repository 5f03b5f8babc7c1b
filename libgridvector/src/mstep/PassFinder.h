// Sec. 4.3, the topology change: earlier poses near the current one, grouped into passes through the place.
#pragma once

#include <mrpt/math/TPose2D.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace gridvector
{
/** Beyond the paper (Sec. 4.3 adds an edge into every earlier pass): a pose is registered into the first pass
 * through its place and the kRecentPasses most recent ones only. The first anchors the place (every later pass
 * registers into it, so registration errors do not chain from pass to pass); the most recent have drifted
 * least since (the registration starts nearest its solution; the latest is usually the pose's own traverse).
 * A pass beyond them adds a registration into a pass that the kept ones already link to by their own edges;
 * without the bound the edges per pose, and the M-step's time per scan, grow with the passes through the place. */
constexpr size_t kRecentPasses = 3;

/** Earlier poses near the current one, grouped into passes (runs of poses at
 * most `runGap` apart in time), poses added one by one in time order. */
class PassFinder
{
   public:
	struct Pass
	{
		uint32_t lo = 0, hi = 0, nearest = 0;
		std::vector<uint32_t> members;  //!< the pass's poses near pose i, in time order
	};
	/** `cell`: the grid the poses are binned in (the search reaches the 3 x 3 cells around a pose);
	 * `headingWeight` [m/rad]: a pass's candidate is the pose nearest in position + weight x heading. */
	PassFinder(double cell, double headingWeight) : cell_(cell), headingWeight_(headingWeight) {}

	/** Is the k-th of `count` passes (time order) one a pose is registered into (kRecentPasses)? */
	static bool registeredPass(size_t k, size_t count) { return k == 0 || k + kRecentPasses >= count; }

	/** Passes of poses j + gap < i with within(j) true; then adds pose i. */
	template <class Within>
	const std::vector<Pass>& next(uint32_t i, const std::vector<mrpt::math::TPose2D>& poses, uint32_t gap,
								  uint32_t runGap, Within within)
	{
		const Key c = keyOf(poses[i]);
		near_.clear();
		for (long dx = -1; dx <= 1; ++dx)
			for (long dy = -1; dy <= 1; ++dy)
			{
				auto g = grid_.find({c.first + dx, c.second + dy});
				if (g == grid_.end()) continue;
				for (uint32_t j : g->second)
					if (j + gap < i && within(j)) near_.push_back(j);
			}
		grid_[c].push_back(i);
		std::sort(near_.begin(), near_.end());
		passes_.clear();
		for (size_t a = 0; a < near_.size();)
		{
			size_t b = a + 1;
			while (b < near_.size() && near_[b] - near_[b - 1] <= runGap) ++b;
			Pass p{near_[a], near_[b - 1], near_[a], {near_.begin() + long(a), near_.begin() + long(b)}};
			// nearest in view: a scan sees what lies ahead of it, so heading counts too
			auto view = [&](uint32_t j) {
				return std::hypot(poses[i].x - poses[j].x, poses[i].y - poses[j].y) +
					   headingWeight_ * std::abs(mrpt::math::wrapToPi(poses[i].phi - poses[j].phi));
			};
			for (size_t k = a; k < b; ++k)
				if (view(near_[k]) < view(p.nearest)) p.nearest = near_[k];
			passes_.push_back(p);
			a = b;
		}
		return passes_;
	}

   private:
	using Key = std::pair<long, long>;
	Key keyOf(const mrpt::math::TPose2D& p) const
	{
		return {long(std::floor(p.x / cell_)), long(std::floor(p.y / cell_))};
	}
	double cell_, headingWeight_;
	std::map<Key, std::vector<uint32_t>> grid_;
	std::vector<uint32_t> near_;
	std::vector<Pass> passes_;
};

}  // namespace gridvector
