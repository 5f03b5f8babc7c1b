#include "online/ClassifiedMap.h"
#include "map/GlobalMap.h"

#include <algorithm>

namespace gridvector
{
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

ClassifiedMap::ClassifiedMap(const GridVectorConfig& cfg)
	: cfg_(cfg), estep_(cfg.estep, cfg.grid), index_(VectorIndex::kCellSize), triIndex_(VectorIndex::kCellSize)
{}

// WipeProduct's loop for one vector: the candidate triangles scan by scan, a scan's triangles marked
// together (per cell a scan counts once), a lone one added directly.
bool ClassifiedMap::applyTriangles(GridVector& m, const std::vector<uint32_t>& cand)
{
	constexpr bool beams = GlobalMap::kBatchWipeCountsBeams;
	ScanWipe::Stats st;
	bool changed = false;
	for (size_t a = 0, b = 0; a < cand.size(); a = b)
	{
		while (b < cand.size() && scanOf_[cand[b]] == scanOf_[cand[a]]) ++b;
		if (b == a + 1)
		{
			changed = ScanWipe::addAlone(tris_[cand[a]], m, beams, st) || changed;
			continue;
		}
		if (marks_.size() < m.cells().size()) marks_.resize(m.cells().size());  // zeroed again by add()
		ScanWipe::Span span;
		for (size_t k = a; k < b; ++k)
			ScanWipe::mark(
				tris_[cand[k]], m, WipePart::Hit, beams, [&] { return marks_.data(); }, span);
		if (span.first < span.last) changed = ScanWipe::add(marks_.data(), span, m.cells(), beams, st) || changed;
	}
	return changed;
}

// Eq. 4 (unmerged) and Eq. 8 both ways for scan t; the vectors whose cells changed are due for Eq. 14-15.
size_t ClassifiedMap::insert(const TPose2D& pose, const LocalScan& scan)
{
	const uint32_t t = uint32_t(scans_++);
	const TPoint2D sensor = GlobalMap::sensorPosition(pose, scan);
	const size_t first = vectors_.size();
	std::vector<GridVector> fresh;
	std::vector<WipeTriangle> freshTris;
	const double band = ScanWipe::hitBandFor(cfg_, scan);
	fresh.reserve(scan.vectors.size());
	for (const auto& v : scan.vectors)
	{
		GridVector m = v.compose(pose);  // m_{i,t} = x_t (+) v_{i,t}
		m.scanIndex = scan.scanIndex >= 0 ? scan.scanIndex : int64_t(t);
		m.timestamp = scan.timestamp;
		m.id = first + fresh.size() + 1;
		const ScanWipe::Segment s = ScanWipe::segmentOf(m);
		freshTris.emplace_back(sensor, s.start, s.end, band, 0.0);  // the per-cell unit: density 0
		fresh.push_back(std::move(m));
	}
	// the new scan's triangles over the earlier vectors they reach (each vector: this scan comes last so far)
	auto& byVector = byVector_;  // earlier vector -> this scan's triangles (local numbers), emptied below
	std::vector<uint32_t> touched;
	for (uint32_t k = 0; k < freshTris.size(); ++k)
	{
		const WipeTriangle& tri = freshTris[k];
		if (tri.degenerate()) continue;
		cand_.clear();
		index_.query({tri.minX(), tri.minY(), tri.maxX(), tri.maxY()}, cand_);
		for (uint32_t slot : cand_)
		{
			if (byVector[slot].empty()) touched.push_back(slot);
			byVector[slot].push_back(k);
		}
	}
	// the earlier vectors' slots first in tris_/scanOf_ order: append this scan's triangles now
	const uint32_t triBase = uint32_t(tris_.size());
	for (size_t k = 0; k < fresh.size(); ++k) tris_.push_back(freshTris[k]), scanOf_.push_back(t);
	std::sort(touched.begin(), touched.end());
	std::vector<uint32_t> changed;
	std::vector<uint32_t> cand;
	for (uint32_t slot : touched)
	{
		GridVector& m = vectors_[slot];
		const Box2D box = Box2D::of(m);
		cand.clear();
		for (uint32_t k : byVector[slot])
			if (!freshTris[k].misses(box.minX, box.minY, box.maxX, box.maxY)) cand.push_back(triBase + k);
		if (!cand.empty() && applyTriangles(m, cand)) changed.push_back(slot);
		byVector[slot].clear();
	}
	// the earlier scans' triangles over the new vectors, ascending (this scan's own: Algorithm 1 counted)
	for (auto& m : fresh)
	{
		const Box2D box = Box2D::of(m);
		cand.clear();
		triIndex_.query(box, cand);
		cand.erase(std::remove_if(cand.begin(), cand.end(),
								  [&](uint32_t j) { return tris_[j].misses(box.minX, box.minY, box.maxX, box.maxY); }),
				   cand.end());
		std::sort(cand.begin(), cand.end());
		applyTriangles(m, cand);
	}
	for (size_t k = 0; k < fresh.size(); ++k)
	{
		const uint32_t slot = uint32_t(vectors_.size());
		index_.insert(slot, Box2D::of(fresh[k]));
		const WipeTriangle& tri = tris_[triBase + k];
		if (!tri.degenerate()) triIndex_.insert(triBase + uint32_t(k), {tri.minX(), tri.minY(), tri.maxX(), tri.maxY()});
		vectors_.push_back(std::move(fresh[k]));
		pieces_.emplace_back();
		stale_.push_back(true);
		byVector_.emplace_back();
		changed.push_back(slot);
	}
	for (uint32_t slot : changed) stale_[slot] = true;  // Fig. 4 when asked (piecesOf, children)
	return changed.size();
}

const std::vector<ProfilePiece>& ClassifiedMap::fresh(size_t slot) const
{
	if (stale_[slot]) estep_.split(vectors_[slot], &pieces_[slot]), stale_[slot] = false;
	return pieces_[slot];
}

const std::vector<ProfilePiece>* ClassifiedMap::piecesOf(uint64_t id) const
{
	if (id == 0 || id > vectors_.size() || vectors_[id - 1].id != id) return nullptr;
	return &fresh(id - 1);
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

// EStep::run's children, from the pieces cached when each vector last changed (no profile recomputed).
std::vector<GridVector> ClassifiedMap::children() const
{
	std::vector<GridVector> out;
	out.reserve(vectors_.size());
	for (size_t k = 0; k < vectors_.size(); ++k)
		for (auto& c : estep_.childrenFrom(vectors_[k], fresh(k))) out.push_back(std::move(c));
	return out;
}

}  // namespace gridvector
