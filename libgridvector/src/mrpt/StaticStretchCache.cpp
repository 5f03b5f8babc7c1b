// The static stretches of a map's vectors kept between matching calls (StaticStretchCache.h).
#include "mrpt/StaticStretchCache.h"

namespace gridvector
{
StaticStretchTable::StaticStretchTable(size_t slots, uint64_t revision)
	: entries_(new Entry[slots]), size_(slots), revision_(revision)
{}

StaticStretchCache& StaticStretchCache::operator=(const StaticStretchCache&)
{
	std::lock_guard<std::mutex> lock(mutex_);
	table_.reset();
	return *this;
}

std::shared_ptr<const StaticStretchTable> StaticStretchCache::tableFor(const GlobalMap& map) const
{
	std::lock_guard<std::mutex> lock(mutex_);
	if (!table_ || table_->revision() != map.revision() || table_->size() != map.size())  // size: a moved-from map
		table_ = std::make_shared<const StaticStretchTable>(map.size(), map.revision());
	return table_;
}

}  // namespace gridvector
