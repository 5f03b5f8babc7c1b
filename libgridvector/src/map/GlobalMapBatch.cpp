// Batch mode of the global map: the full Eq. 8 over per-scan vectors, and the Eq. 4 merge.
#include "map/Correspondence.h"
#include "map/GlobalMap.h"
#include "map/MergeCascade.h"
#include "map/WipeProduct.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace gridvector
{
using mrpt::math::TPoint2D;

namespace
{
/** Bucket side of Eq. 8's triangle buckets, about a short wall piece: a vector's query meets a few buckets, a
 * triangle is listed in few more than its area covers (freiburg-079: 2 m 6.0 s, 0.5 m 4.8 s; speed only). */
constexpr double kWipeBucket = 0.5;  // [m]
}  // namespace

// Eq. 4 (unmerged) and Eq. 8: every scan's triangles over every other scan's vectors.
std::vector<GridVector> GlobalMap::buildPerScan(const std::vector<mrpt::math::TPose2D>& poses,
												const std::vector<LocalScan>& scans, const GridVectorConfig& cfg)
{
	if (poses.size() != scans.size())
		throw std::invalid_argument("GlobalMap::buildPerScan: poses and scans differ in number");
	std::vector<GridVector> all;
	std::vector<size_t> first(scans.size() + 1, 0);
	for (size_t t = 0; t < scans.size(); ++t)
	{
		first[t] = all.size();
		for (const auto& v : scans[t].vectors)
		{
			GridVector m = v.compose(poses[t]);  // m_{i,t} = x_t (+) v_{i,t}
			m.scanIndex = scans[t].scanIndex >= 0 ? scans[t].scanIndex : int64_t(t);
			m.timestamp = scans[t].timestamp;
			m.id = all.size() + 1;
			all.push_back(std::move(m));
		}
	}
	first[scans.size()] = all.size();

	std::vector<TPoint2D> sensors(scans.size());
	std::vector<double> bands(scans.size());
	for (size_t t = 0; t < scans.size(); ++t)
		sensors[t] = sensorPosition(poses[t], scans[t]), bands[t] = ScanWipe::hitBandFor(cfg, scans[t]);
	WipeProduct(cfg.map.hitBand, kBatchWipeCountsBeams, kWipeBucket).apply(sensors, first, all, bands);
	return all;
}

namespace
{
/** A group of corresponding inputs with the geometry its merge would have,
 * estimated from additive sums so that groups can grow in O(1). */
struct Group
{
	std::vector<uint32_t> members;  //!< input positions
	LineMoments moments;  //!< occupied cells' gravity centres, weighted by occupancy
	TPoint2D dirRef;  //!< orientation of the first member
	TPoint2D extA, extB;  //!< endpoints lying furthest out along the line
	TPoint2D s, e;  //!< estimated merged vector
	size_t firstInput = 0;
	bool alive = true;

	void estimate()
	{
		Line2D l;
		TPoint2D d = dirRef;
		TPoint2D p0 = extA;
		if (moments.fit(l))
		{
			d = TPoint2D(-std::sin(l.theta), std::cos(l.theta));
			if (d.x * dirRef.x + d.y * dirRef.y < 0) d = TPoint2D(-d.x, -d.y);
			p0 = l.project(extA);
		}
		auto t = [&](const TPoint2D& p) { return (p.x - p0.x) * d.x + (p.y - p0.y) * d.y; };
		const double ta = t(extA), tb = t(extB);
		s = TPoint2D(p0.x + std::min(ta, tb) * d.x, p0.y + std::min(ta, tb) * d.y);
		e = TPoint2D(p0.x + std::max(ta, tb) * d.x, p0.y + std::max(ta, tb) * d.y);
	}

	void absorb(const Group& o)
	{
		members.insert(members.end(), o.members.begin(), o.members.end());
		moments.add(o.moments);
		firstInput = std::min(firstInput, o.firstInput);
		estimate();  // line from the summed moments
		const TPoint2D d(e.x - s.x, e.y - s.y);
		const TPoint2D cand[4] = {extA, extB, o.extA, o.extB};
		double tmin = 1e300, tmax = -1e300;
		for (const TPoint2D& p : cand)
		{
			const double t = (p.x - s.x) * d.x + (p.y - s.y) * d.y;
			if (t < tmin) tmin = t, extA = p;
			if (t > tmax) tmax = t, extB = p;
		}
		estimate();
	}

	Box2D box(double band) const
	{
		return Box2D{std::min(s.x, e.x), std::min(s.y, e.y), std::max(s.x, e.x), std::max(s.y, e.y)}.expanded(band);
	}
};

Group groupOf(const GridVector& v, uint32_t pos)
{
	Group g;
	g.members = {pos};
	g.firstInput = pos;
	for (int r = 0; r < v.rows(); ++r)
		for (int c = 0; c < v.cols(); ++c)
			if (v.cell(r, c).n_acc > 0)
			{
				const TPoint2D p = v.cellMeanPoint(r, c);
				g.moments.add(p.x, p.y, v.cell(r, c).occupancy(v.priorRatio()));
			}
	g.dirRef = v.direction();
	g.extA = v.start();
	g.extB = v.end();
	g.s = v.start();
	g.e = v.end();
	Line2D l;
	if (!g.moments.fit(l))  // no points: the geometry itself
	{
		g.moments = {};
		g.moments.add(v.start().x, v.start().y);
		g.moments.add(v.end().x, v.end().y);
	}
	g.estimate();
	return g;
}

/** A partial merge of a refused group: the vector and the input ids it stands for. */
struct Partial
{
	GridVector v;
	std::vector<uint64_t> ids;
	bool merged = false;
};

// A group the guard refused: its members merged one by one (longest first), each with the
// partial merges it corresponds to while the guard allows (the cascade of GlobalMap::insertVector).
std::vector<Partial> mergeMemberwise(const std::vector<GridVector>& vectors, std::vector<uint32_t> members,
									 const VectorMerger& merger, const MapOptions& opt)
{
	std::stable_sort(members.begin(), members.end(),
					 [&](uint32_t a, uint32_t b) { return vectors[a].length() > vectors[b].length(); });
	std::vector<Partial> parts;
	// the partial merges so far, keyed by position
	auto partsCorresponding = [&](const GridVector& v) {
		std::vector<MergeCandidate> out;
		for (size_t k = 0; k < parts.size(); ++k)
			if (!parts[k].ids.empty() && corresponds(v, parts[k].v, opt)) out.push_back({k, &parts[k].v});
		return out;
	};
	for (uint32_t m : members)
	{
		Partial cur{vectors[m], {vectors[m].id}, false};
		auto absorb = [&](const std::vector<MergeCandidate>& taken) {
			for (const MergeCandidate& c : taken)
			{
				cur.ids.insert(cur.ids.end(), parts[c.key].ids.begin(), parts[c.key].ids.end());
				parts[c.key].ids.clear();
			}
		};
		cur.merged = mergeCascade(merger, cur.v, {partsCorresponding, absorb}).merges > 0;
		parts.push_back(std::move(cur));
	}
	parts.erase(std::remove_if(parts.begin(), parts.end(), [](const Partial& p) { return p.ids.empty(); }),
				parts.end());
	return parts;
}

// Sec. 3.2: the inputs, longest first, grouped by the correspondence criteria; a group grows by
// the earlier groups its grown span corresponds to (at most `rounds` times). The groups alive
// at the end, in the order of their first input.
std::vector<Group> correspondingGroups(const std::vector<GridVector>& vectors, const MapOptions& opt, int rounds)
{
	std::vector<uint32_t> order(vectors.size());
	std::iota(order.begin(), order.end(), 0u);
	std::stable_sort(order.begin(), order.end(),
					 [&](uint32_t a, uint32_t b) { return vectors[a].length() > vectors[b].length(); });
	double band = 0;
	for (const auto& v : vectors) band = std::max(band, (v.halfWidth() + 0.5) * v.resolution());

	std::vector<Group> groups;
	groups.reserve(vectors.size());
	VectorIndex index(VectorIndex::kCellSize);
	std::vector<uint32_t> cand;
	for (uint32_t pos : order)
	{
		Group g = groupOf(vectors[pos], pos);
		for (int round = 0; round < rounds; ++round)  // grown span: new correspondents
		{
			cand.clear();
			const double len = std::hypot(g.e.x - g.s.x, g.e.y - g.s.y);
			index.query(g.box(band + correspondenceSearchMargin(len, opt)), cand);
			bool grew = false;
			for (uint32_t k : cand)
			{
				if (!testCorrespondence(g.s, g.e, groups[k].s, groups[k].e, opt).match) continue;
				g.absorb(groups[k]);
				groups[k].alive = false;
				index.remove(k);
				grew = true;
			}
			if (!grew) break;
		}
		groups.push_back(std::move(g));
		index.insert(uint32_t(groups.size() - 1), groups.back().box(band));
	}
	groups.erase(std::remove_if(groups.begin(), groups.end(), [](const Group& g) { return !g.alive; }), groups.end());
	std::sort(groups.begin(), groups.end(), [](const Group& a, const Group& b) { return a.firstInput < b.firstInput; });
	return groups;
}

// Algorithm 2 once over a group; a group the guard refuses merges member by member.
std::vector<Partial> mergeGroup(const std::vector<GridVector>& vectors, const Group& g, const VectorMerger& merger,
								const MapOptions& opt)
{
	std::vector<const GridVector*> parts;
	for (uint32_t m : g.members) parts.push_back(&vectors[m]);
	std::vector<Partial> done(1);
	if (parts.size() == 1)
		done[0] = {*parts.front(), {parts.front()->id}, false};
	else if (merger.tryMerge(parts, done[0].v))
	{
		for (const GridVector* p : parts) done[0].ids.push_back(p->id);
		done[0].merged = true;
	}
	else
		done = mergeMemberwise(vectors, g.members, merger, opt);
	return done;
}
}  // namespace

// Eq. 4: {m_{i,t}} -> {m_j}; groups by the Sec. 3.2 criteria, each merged once by Algorithm 2.
MergeResult GlobalMap::mergeAll(const std::vector<GridVector>& vectors, const GridVectorConfig& cfg, int groupRounds)
{
	const std::vector<Group> groups = correspondingGroups(vectors, cfg.map, groupRounds);
	uint64_t nextId = 1;
	for (const auto& v : vectors) nextId = std::max(nextId, v.id + 1);
	const VectorMerger merger(cfg);
	MergeResult out;
	out.vectors.reserve(groups.size());
	for (const Group& g : groups)
		for (Partial& p : mergeGroup(vectors, g, merger, cfg.map))
		{
			if (p.merged) p.v.id = nextId++;
			std::sort(p.ids.begin(), p.ids.end());
			out.vectors.push_back(std::move(p.v));
			out.sources.push_back(std::move(p.ids));
		}
	return out;
}

}  // namespace gridvector
