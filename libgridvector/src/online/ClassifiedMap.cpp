#include "online/ClassifiedMap.h"
#include "map/VectorIndex.h"

#include <algorithm>
#include <unordered_set>

namespace gridvector
{
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

ClassifiedMap::ClassifiedMap(const GridVectorConfig& cfg)
	: cfg_(cfg), map_(cfg, GlobalMap::kSequentialWipeCountsBeams), estep_(cfg.estep, cfg.grid)
{}

// Eq. 8 + Eq. 4 (GlobalMap::insertScan), then Eq. 14-15 on the vectors the scan can have changed.
size_t ClassifiedMap::insert(const TPose2D& pose, const LocalScan& scan)
{
	map_.insertScan(pose, scan);
	// the wipe triangles span the sensor and the scan's vectors; merges happen where the vectors lie
	const TPoint2D o = GlobalMap::sensorPosition(pose, scan);
	Box2D box{o.x, o.y, o.x, o.y};
	for (const auto& v : scan.vectors)
		for (const TPoint2D& p : {v.start(), v.end()})
		{
			const TPoint2D w = pose.composePoint(p);
			box.minX = std::min(box.minX, w.x), box.maxX = std::max(box.maxX, w.x);
			box.minY = std::min(box.minY, w.y), box.maxY = std::max(box.maxY, w.y);
		}
	touched_.clear();
	map_.index().query(box, touched_);
	for (uint32_t slot : touched_)
	{
		const GridVector& v = map_.vectors()[slot];
		std::vector<ProfilePiece> pieces;
		estep_.split(v, &pieces);
		pieces_[v.id] = std::move(pieces);
	}
	prune();
	return touched_.size();
}

void ClassifiedMap::prune()
{
	if (pieces_.size() <= 2 * map_.size()) return;
	std::unordered_set<uint64_t> live;
	live.reserve(map_.size());
	for (const auto& v : map_.vectors()) live.insert(v.id);
	for (auto it = pieces_.begin(); it != pieces_.end();)
		it = live.count(it->first) ? std::next(it) : pieces_.erase(it);
}

const std::vector<ProfilePiece>* ClassifiedMap::piecesOf(uint64_t id) const
{
	auto it = pieces_.find(id);
	return it == pieces_.end() ? nullptr : &it->second;
}

VectorState ClassifiedMap::stateOf(const GridVector& v) const
{
	const auto* p = piecesOf(v.id);
	if (!p || p->empty()) return VectorState::Unknown;
	const bool first = p->front().isStatic;
	for (const auto& q : *p)
		if (q.isStatic != first) return VectorState::Unknown;
	return first ? VectorState::Static : VectorState::Dynamic;
}

// A vector's children as its last touching scan classified it: the map vector has not changed since.
std::vector<GridVector> ClassifiedMap::children() const
{
	std::vector<GridVector> out;
	out.reserve(map_.size());
	for (const auto& v : map_.vectors())
		for (auto& c : estep_.split(v)) out.push_back(std::move(c));
	return out;
}

}  // namespace gridvector
