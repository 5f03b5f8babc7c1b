#include "map/Correspondence.h"
#include "map/GlobalMap.h"
#include "map/MergeCascade.h"

#include <algorithm>
#include <cmath>

namespace gridvector
{
using mrpt::math::TPoint2D;

GlobalMap::GlobalMap(const GridVectorConfig& cfg, bool wipeCountsBeams)
	: cfg_(cfg),
	  wipeCountsBeams_(wipeCountsBeams),
	  index_(VectorIndex::kCellSize),
	  wiper_(cfg.map.hitBand, wipeCountsBeams),
	  merger_(cfg)
{
	modified();
}

void GlobalMap::clear()
{
	modified();
	vectors_.clear();
	index_.clear();
	nextId_ = 1;
	stats_ = {};
}

void GlobalMap::setConfig(const GridVectorConfig& cfg)
{
	modified();
	cfg_ = cfg;
	wiper_ = ScanWipe(cfg.map.hitBand, wipeCountsBeams_);
	merger_ = VectorMerger(cfg);
}

void GlobalMap::setVectors(std::vector<GridVector> v)
{
	modified();
	vectors_ = std::move(v);
	nextId_ = 1;
	for (const auto& g : vectors_) nextId_ = std::max(nextId_, g.id + 1);
	rebuildIndex();
}

void GlobalMap::rebuildIndex()
{
	index_.clear();
	for (size_t i = 0; i < vectors_.size(); ++i) index_.insert(uint32_t(i), Box2D::of(vectors_[i]));
}

void GlobalMap::addSlot(GridVector m)
{
	vectors_.push_back(std::move(m));
	index_.insert(uint32_t(vectors_.size() - 1), Box2D::of(vectors_.back()));
}

// Removes slots by moving the last vector into each hole (largest slot first).
void GlobalMap::removeSlots(std::vector<size_t> slots)
{
	std::sort(slots.rbegin(), slots.rend());
	for (size_t i : slots)
	{
		const size_t last = vectors_.size() - 1;
		index_.remove(uint32_t(i));
		if (i != last)
		{
			index_.remove(uint32_t(last));
			vectors_[i] = std::move(vectors_[last]);
			index_.insert(uint32_t(i), Box2D::of(vectors_[i]));
		}
		vectors_.pop_back();
	}
}

TPoint2D GlobalMap::sensorPosition(const mrpt::math::TPose2D& x, const LocalScan& scan)
{
	const double c = std::cos(x.phi), s = std::sin(x.phi);
	const TPoint2D& o = scan.sensorOrigin;
	return {x.x + c * o.x - s * o.y, x.y + s * o.x + c * o.y};
}

std::vector<size_t> GlobalMap::correspondents(const GridVector& v) const
{
	std::vector<uint32_t> cand;
	index_.query(Box2D::of(v).expanded(correspondenceSearchMargin(v.length(), cfg_.map)), cand);
	std::vector<size_t> out;
	for (uint32_t s : cand)
		if (corresponds(v, vectors_[s], cfg_.map)) out.push_back(s);
	std::sort(out.begin(), out.end());
	return out;
}

// Eq. 8: the triangles of V_t over the vectors already in the map (not over the scan's own).
ScanWipe::Stats GlobalMap::wipe(const mrpt::math::TPose2D& robotPose, const LocalScan& scan)
{
	modified();
	HeldBack none;
	return wipeHolding(robotPose, scan, false, none);
}

// Eq. 8 before the scan's vectors go in. With `holdBack`, a new vector's own beams reach the vectors it
// merges into through Algorithm 1, so its correspondents get part b only until completeRefused() knows
// the merges; `held` records what was held back.
ScanWipe::Stats GlobalMap::wipeHolding(const mrpt::math::TPose2D& robotPose, const LocalScan& scan, bool holdBack,
									   HeldBack& held)
{
	held = HeldBack{};
	held.sensor = sensorPosition(robotPose, scan);
	held.scanIndex = scan.scanIndex;
	held.hitBand = ScanWipe::hitBandFor(cfg_, scan);
	wiper_.setHitBand(held.hitBand);
	std::vector<std::vector<size_t>> mergeTargets(scan.vectors.size());
	held.targets.resize(scan.vectors.size());
	for (size_t j = 0; j < scan.vectors.size(); ++j)
	{
		const GridVector m = scan.vectors[j].compose(robotPose);
		held.segs.push_back(ScanWipe::segmentOf(m));
		if (!holdBack) continue;
		mergeTargets[j] = correspondents(m);
		for (size_t slot : mergeTargets[j])
		{
			held.targets[j].push_back(vectors_[slot].id);
			held.boxes.push_back({vectors_[slot].id, index_.box(uint32_t(slot))});
		}
		std::sort(held.targets[j].begin(), held.targets[j].end());
	}
	const int64_t own = scan.scanIndex;
	auto limit = [&](size_t seg, uint32_t slot) {
		if (own >= 0 && vectors_[slot].scanIndex == own) return WipePart::Outside;
		const auto& t = mergeTargets[seg];
		return std::binary_search(t.begin(), t.end(), size_t(slot)) ? WipePart::Visited : WipePart::Hit;
	};
	return wiper_.apply(held.sensor, held.segs, vectors_, index_, limit);
}

// Eq. 8 completed for the correspondents that absorbed no new vector: the parts c held back.
void GlobalMap::completeRefused(HeldBack& held)
{
	auto& boxes = held.boxes;
	std::sort(boxes.begin(), boxes.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
	boxes.erase(
		std::unique(boxes.begin(), boxes.end(), [](const auto& a, const auto& b) { return a.first == b.first; }),
		boxes.end());
	std::vector<WipeTriangle> tris;
	std::vector<uint32_t> cand;
	for (const auto& [id, box] : boxes)
	{
		cand.clear();
		index_.query(box, cand);
		const auto slot = std::find_if(cand.begin(), cand.end(), [&](uint32_t s) { return vectors_[s].id == id; });
		if (slot == cand.end()) continue;  // merged: it holds the new vectors' endpoints
		if (held.scanIndex >= 0 && vectors_[*slot].scanIndex == held.scanIndex) continue;  // not wiped by its scan
		if (tris.empty())
		{
			wiper_.setHitBand(held.hitBand);
			for (const auto& seg : held.segs) tris.push_back(wiper_.triangleOf(held.sensor, seg));
		}
		std::vector<WipePart> applied(tris.size(), WipePart::Hit), wanted(tris.size(), WipePart::Hit);
		for (size_t k = 0; k < tris.size(); ++k)
			if (std::binary_search(held.targets[k].begin(), held.targets[k].end(), id)) applied[k] = WipePart::Visited;
		ScanWipe::complete(tris, applied, wanted, vectors_[*slot], wipeCountsBeams_, stats_.wipe);
	}
}

// Algorithm 2 with every correspondent the guard allows, repeated while the merged vector finds new ones.
void GlobalMap::insertVector(GridVector m)
{
	modified();
	m.id = nextId_++;
	if (cfg_.map.mergeOnInsert)
	{
		auto mapCorresponding = [&](const GridVector& v) {  // keyed by id: merges move the slots
			std::vector<MergeCandidate> out;
			for (size_t s : correspondents(v)) out.push_back({vectors_[s].id, &vectors_[s]});
			return out;
		};
		auto absorb = [&](const std::vector<MergeCandidate>& taken) {
			std::vector<size_t> slots;
			for (const MergeCandidate& c : taken) slots.push_back(size_t(c.vector - vectors_.data()));
			removeSlots(slots);
		};
		const MergeCascadeStats st = mergeCascade(merger_, m, {mapCorresponding, absorb});
		stats_.merges += st.merges;
		stats_.absorbed += st.absorbed;
		stats_.refused += st.refused;
		if (st.merges > 0)  // each merge numbered in turn: the last one's id
		{
			nextId_ += st.merges;
			m.id = nextId_ - 1;
		}
	}
	addSlot(std::move(m));
}

// m_{i,t} = x_t (+) v_{i,t} (Sec. 3.2), after the Eq. 8 update by the same scan.
void GlobalMap::insertScan(const mrpt::math::TPose2D& robotPose, const LocalScan& scan)
{
	modified();
	stats_ = {};
	HeldBack held;
	stats_.wipe = wipeHolding(robotPose, scan, cfg_.map.mergeOnInsert, held);
	insertVectors(robotPose, scan);
	completeRefused(held);
}

void GlobalMap::insertVectors(const mrpt::math::TPose2D& robotPose, const LocalScan& scan)
{
	for (const auto& v : scan.vectors)
	{
		GridVector m = v.compose(robotPose);
		m.scanIndex = scan.scanIndex;
		m.timestamp = scan.timestamp;
		insertVector(std::move(m));
		++stats_.inserted;
	}
}

}  // namespace gridvector
