// The static stretches of a map's vectors (Fig. 4 profile against matching.static_threshold),
// kept between matching calls while the map does not change, shared by any number of threads.
#pragma once

#include "map/GlobalMap.h"

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace gridvector
{
/** Per vector of one map state (GlobalMap::revision()), its static stretches, each computed on
 * first use: one thread computes a vector's stretches, threads asking for it meanwhile wait for
 * them, later lookups are one atomic load. */
class StaticStretchTable
{
   public:
	using Stretches = std::vector<std::pair<double, double>>;

	StaticStretchTable(size_t slots, uint64_t revision);
	uint64_t revision() const { return revision_; }
	size_t size() const { return size_; }

	/** The stretches of `slot`, `compute()` on the first call for it. */
	template <class F>
	const Stretches& get(uint32_t slot, F&& compute) const
	{
		Entry& e = entries_[slot];
		if (!e.ready.load(std::memory_order_acquire))
			std::call_once(e.once, [&] {
				e.value = compute();
				e.ready.store(true, std::memory_order_release);
			});
		return e.value;
	}

   private:
	struct Entry
	{
		std::atomic<bool> ready{false};
		std::once_flag once;
		Stretches value;
	};
	std::unique_ptr<Entry[]> entries_;  //!< the pointer is const, the entries are filled in
	size_t size_;
	uint64_t revision_;
};

/** The table of a map's current state: tableFor() hands out the table of the map's revision,
 * replacing a table of an older one (a mutex around that check only). A copy starts empty. */
class StaticStretchCache
{
   public:
	StaticStretchCache() = default;
	StaticStretchCache(const StaticStretchCache&) {}
	StaticStretchCache& operator=(const StaticStretchCache&);

	std::shared_ptr<const StaticStretchTable> tableFor(const GlobalMap& map) const;

   private:
	mutable std::mutex mutex_;
	mutable std::shared_ptr<const StaticStretchTable> table_;
};

}  // namespace gridvector
