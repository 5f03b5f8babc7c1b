#include "estep/EStep.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace gridvector
{
using mrpt::math::TPoint2D;

EStep::EStep(const EStepOptions& opts, const GridOptions& grid) : opts_(opts), grid_(grid) {}

// Fig. 4: split where the profile meets the threshold, then merge the shortest
// piece into its neighbours until every piece has at least minColumns.
std::vector<ProfilePiece> EStep::pieces(const std::vector<double>& profile, double threshold, int minColumns)
{
	std::vector<ProfilePiece> out;
	for (int c = 0; c < int(profile.size()); ++c)
	{
		const bool st = profile[size_t(c)] >= threshold;
		if (out.empty() || out.back().isStatic != st)
			out.push_back({c, c + 1, st});
		else
			out.back().last = c + 1;
	}
	while (out.size() > 1)
	{
		auto shortest = std::min_element(out.begin(), out.end(),
										 [](const auto& a, const auto& b) { return a.columns() < b.columns(); });
		if (shortest->columns() >= minColumns) break;
		// the short piece takes its neighbours' state and joins them
		const size_t k = size_t(shortest - out.begin());
		const size_t lo = k > 0 ? k - 1 : k, hi = k + 1 < out.size() ? k + 1 : k;
		ProfilePiece m{out[lo].first, out[hi].last, !out[k].isStatic};
		out.erase(out.begin() + long(lo), out.begin() + long(hi) + 1);
		out.insert(out.begin() + long(lo), m);
	}
	return out;
}

// Fig. 4 profile: per column the largest probability across the width among the
// cells with n_visit >= min_visits (the prior's n_visit = 1 of Sec. 3.1 included;
// robust to the wall falling in a neighbouring row; a column nobody has looked
// through again stays static), or the mean across the width (GridVector::occupancyProfile).
std::vector<double> EStep::profile(const GridVector& v) const
{
	if (!opts_.usePeakRow) return v.occupancyProfile();
	std::vector<double> prof(size_t(v.cols()), 0.0);
	for (int c = 0; c < v.cols(); ++c)
	{
		bool seen = false;
		for (int r = 0; r < v.rows(); ++r)
		{
			const GridCell& cell = v.cell(r, c);
			const bool counts = cell.n_visit > 0;  // else a merged grid's uncovered cell: it reads the prior
			const double occ = counts ? cell.n_occupy : v.priorOccupy(), visit = counts ? cell.n_visit : v.priorVisit();
			if (visit < opts_.minVisits) continue;
			seen = true;
			// free observations (beams through the cell) weigh free_weight times an occupied one
			const double freeObs = std::max(0.0, visit - occ);
			const double p = occ / std::max(1e-9, occ + opts_.freeWeight * freeObs);
			prof[size_t(c)] = std::max(prof[size_t(c)], p);
		}
		if (!seen) prof[size_t(c)] = 1.0;
	}
	return prof;
}

// Eq. 14's child: the parent's columns [first, last) with their cells unchanged (Eq. 5's posterior kept).
GridVector EStep::subVector(const GridVector& parent, const ProfilePiece& p) const
{
	const double res = parent.resolution(), len = parent.length();
	const TPoint2D d = parent.direction(), s0 = parent.start();
	const double u0 = p.first * res, u1 = std::min(len, p.last * res);
	const TPoint2D s(s0.x + u0 * d.x, s0.y + u0 * d.y), e(s0.x + u1 * d.x, s0.y + u1 * d.y);
	std::vector<GridCell> cells;
	cells.reserve(size_t(parent.rows()) * size_t(p.columns()));
	for (int r = 0; r < parent.rows(); ++r)
		for (int c = p.first; c < p.last; ++c) cells.push_back(parent.cell(r, c));
	GridOptions g = grid_;
	g.resolution = res;
	g.halfWidth = parent.halfWidth();
	GridVector child = GridVector::fromParts(s, e, g, p.columns(), std::move(cells));
	child.scanIndex = parent.scanIndex;
	child.timestamp = parent.timestamp;
	child.mergedCount = parent.mergedCount;
	child.state = p.isStatic ? VectorState::Static : VectorState::Dynamic;  // Eq. 14
	return child;
}

// Eq. 25's M_chd bookkeeping: a child's id from its parent's and its place among the pieces.
uint64_t EStep::childId(uint64_t parentId, size_t k)
{
	constexpr uint64_t pieces = uint64_t(1) << kChildBits, parents = uint64_t(1) << (64 - kChildBits);
	if (k >= pieces || parentId >= parents)
		throw std::overflow_error("EStep::childId: piece " + std::to_string(k) + " of vector id " +
								  std::to_string(parentId) + " has no id (at most " + std::to_string(pieces) +
								  " pieces per vector, parent ids below 2^" + std::to_string(64 - kChildBits) + ")");
	return (parentId << kChildBits) | k;
}

// Eq. 14 by Fig. 4's split-and-merge of one vector's profile.
std::vector<GridVector> EStep::split(const GridVector& parent, std::vector<ProfilePiece>* piecesOut) const
{
	std::vector<GridVector> out = pieceVectors(parent, piecesOut);
	for (size_t k = 0; k < out.size(); ++k) out[k].id = childId(parent.id, k);
	return out;
}

// Fig. 4 and Eq. 14: the profile, its pieces, one child per piece.
std::vector<GridVector> EStep::pieceVectors(const GridVector& parent, std::vector<ProfilePiece>* piecesOut) const
{
	const int minCols = std::max(1, int(std::ceil(opts_.minPieceLength / parent.resolution() - 1e-9)));
	const auto prof = profile(parent);
	const auto ps = pieces(prof, opts_.staticThreshold, minCols);
	if (piecesOut) *piecesOut = ps;
	return vectorsOf(parent, ps);
}

std::vector<GridVector> EStep::childrenFrom(const GridVector& parent, const std::vector<ProfilePiece>& ps) const
{
	std::vector<GridVector> out = vectorsOf(parent, ps);
	for (size_t k = 0; k < out.size(); ++k) out[k].id = childId(parent.id, k);
	return out;
}

std::vector<GridVector> EStep::vectorsOf(const GridVector& parent, const std::vector<ProfilePiece>& ps) const
{
	std::vector<GridVector> out;
	for (size_t k = 0; k < ps.size(); ++k)
	{
		if (ps.size() == 1)
		{
			out.push_back(parent);  // the whole vector: geometry and grid unchanged
			out.back().state = ps[0].isStatic ? VectorState::Static : VectorState::Dynamic;
		}
		else
			out.push_back(subVector(parent, ps[k]));
	}
	return out;
}

// Sec. 4.1, Eq. 14-15: every m_{i,t} split into static and dynamic children.
EStepResult EStep::run(const std::vector<GridVector>& parents) const
{
	EStepResult r;
	r.childrenOf.resize(parents.size());
	std::vector<ProfilePiece> ps;
	for (size_t k = 0; k < parents.size(); ++k)
	{
		auto kids = split(parents[k], &ps);
		for (size_t q = 0; q < kids.size(); ++q) r.pieces.push_back(ps[q]);
		for (auto& c : kids)
		{
			const bool st = c.state == VectorState::Static;
			(st ? r.staticCount : r.dynamicCount)++;
			(st ? r.staticLength : r.dynamicLength) += c.length();
			r.childrenOf[k].push_back(uint32_t(r.children.size()));
			r.children.push_back(std::move(c));
		}
	}
	return r;
}

// Eq. 25: M_chd of each parent against the last E-step's (ids, Eq. 14 states, Fig. 4 column ranges).
std::vector<bool> EStep::changedChildren(const EStepResult& now, const EStepResult* before)
{
	std::vector<bool> out(now.childrenOf.size(), false);
	const auto sameChild = [&](uint32_t a, uint32_t b) {
		const ProfilePiece &p = now.pieces[a], &q = before->pieces[b];
		return now.children[a].id == before->children[b].id && now.children[a].state == before->children[b].state &&
			   p.first == q.first && p.last == q.last;
	};
	const std::vector<uint32_t> none;
	for (size_t k = 0; k < now.childrenOf.size(); ++k)
	{
		const std::vector<uint32_t>& kids = now.childrenOf[k];
		if (!before)  // before the first E-step: one static child, the vector itself
		{
			out[k] = kids.size() != 1 || now.children[kids[0]].state != VectorState::Static;
			continue;
		}
		const std::vector<uint32_t>& old = k < before->childrenOf.size() ? before->childrenOf[k] : none;
		out[k] = kids.size() != old.size() || !std::equal(kids.begin(), kids.end(), old.begin(), sameChild);
	}
	return out;
}

// Eq. 14 on the converged map: static children must be occupied in nearly every observation,
// and a stretch reading clearly less than the rest of its vector is a place that changed.
std::vector<GridVector> EStep::finalSplit(const std::vector<GridVector>& children,
										  std::vector<uint64_t>* parentIds) const
{
	std::vector<GridVector> out;
	out.reserve(children.size());
	if (parentIds) parentIds->clear();
	uint64_t maxId = 0;
	for (const GridVector& c : children) maxId = std::max(maxId, c.id);
	uint64_t nextId = maxId + 1;  // 0 once every id is taken
	for (const GridVector& c : children)
	{
		if (c.state == VectorState::Dynamic)
		{
			out.push_back(c);
			if (parentIds) parentIds->push_back(c.id);
			continue;
		}
		EStepOptions o = opts_;
		o.staticThreshold = opts_.finalStaticThreshold;
		if (opts_.finalRelativeDrop > 0)
		{
			std::vector<double> prof = profile(c);
			std::nth_element(prof.begin(), prof.begin() + long(prof.size() / 2), prof.end());
			o.staticThreshold = std::max(o.staticThreshold, prof[prof.size() / 2] - opts_.finalRelativeDrop);
		}
		auto kids = EStep(o, grid_).pieceVectors(c, nullptr);
		for (auto& k : kids)
		{
			if (kids.size() > 1 && nextId == 0) throw std::overflow_error("EStep::finalSplit: no id left for a piece");
			k.id = kids.size() == 1 ? c.id : nextId++;
			out.push_back(std::move(k));
			if (parentIds) parentIds->push_back(c.id);
		}
	}
	return out;
}

// Sec. 4.1's minimum vector length for the pieces a door's states cut from a wall: a static run
// shorter than estep.min_piece_length between or beside dynamic stretches (a wall's last partial
// column past a closed state's end, a stub between two states) joins its dynamic neighbours.
std::vector<ProfilePiece> EStep::joinShortStatic(const GridVector& v, std::vector<double>& staticCols) const
{
	std::vector<ProfilePiece> ps = pieces(staticCols, 0.5, 1);  // runs, none merged away
	if (ps.size() <= 1) return ps;
	bool joined = false;
	for (const ProfilePiece& p : ps)
	{
		const double len = std::min(v.length(), p.last * v.resolution()) - p.first * v.resolution();
		if (!p.isStatic || len >= opts_.minPieceLength) continue;
		std::fill(staticCols.begin() + p.first, staticCols.begin() + p.last, 0.0);
		joined = true;
	}
	return joined ? pieces(staticCols, 0.5, 1) : ps;
}

// Sec. 5.4 on Eq. 14's children: the given stretches of a vector are dynamic.
std::vector<GridVector> EStep::splitSpans(const GridVector& v,
										  const std::vector<std::pair<double, double>>& dynamicSpans) const
{
	const bool vStatic = v.state != VectorState::Dynamic;
	std::vector<double> staticCols(size_t(v.cols()));  // 1: static column, 0: dynamic
	for (int c = 0; c < v.cols(); ++c)
	{
		const double u = (c + 0.5) * v.resolution();
		const bool inSpan = std::any_of(dynamicSpans.begin(), dynamicSpans.end(),
										[&](const auto& s) { return u >= s.first && u <= s.second; });
		staticCols[size_t(c)] = vStatic && !inSpan ? 1.0 : 0.0;
	}
	const std::vector<ProfilePiece> ps = joinShortStatic(v, staticCols);
	if (ps.size() <= 1)
	{
		GridVector one = v;
		if (!ps.empty()) one.state = ps[0].isStatic ? VectorState::Static : VectorState::Dynamic;
		return {one};
	}
	std::vector<GridVector> out;
	for (const ProfilePiece& p : ps)
	{
		out.push_back(subVector(v, p));
		out.back().id = out.size() == 1 ? v.id : 0;
	}
	return out;
}

// Runs of columns with observations; gaps of >= minGapColumns empty columns separate them.
std::vector<ProfilePiece> EStep::observedRuns(const GridVector& v, int minGapColumns)
{
	std::vector<ProfilePiece> out;
	int gap = 0;
	for (int c = 0; c < v.cols(); ++c)
	{
		bool seen = false;
		for (int r = 0; r < v.rows() && !seen; ++r) seen = v.cell(r, c).n_visit > 0;
		if (!seen)
		{
			++gap;
			continue;
		}
		if (out.empty() || gap >= minGapColumns)
			out.push_back({c, c + 1, true});
		else
			out.back().last = c + 1;  // a short gap stays inside the run
		gap = 0;
	}
	return out;
}

// Eq. 4 map without stretches no per-scan vector observed (Eq. 6 undefined there).
MergeResult EStep::cutUnobserved(const MergeResult& merged, const std::vector<GridVector>& inputs) const
{
	std::unordered_map<uint64_t, size_t> byId;
	for (size_t i = 0; i < inputs.size(); ++i) byId.emplace(inputs[i].id, i);
	uint64_t nextId = 1;
	for (const auto& v : merged.vectors) nextId = std::max(nextId, v.id + 1);
	for (const auto& v : inputs) nextId = std::max(nextId, v.id + 1);
	const int minGap = std::max(1, int(std::ceil(opts_.minPieceLength / grid_.resolution - 1e-9)));
	MergeResult out;
	for (size_t k = 0; k < merged.vectors.size(); ++k)
	{
		const GridVector& v = merged.vectors[k];
		auto runs = observedRuns(v, minGap);
		if (runs.size() == 1 && runs[0].first == 0 && runs[0].last == v.cols())
		{
			out.vectors.push_back(v);
			out.sources.push_back(k < merged.sources.size() ? merged.sources[k] : std::vector<uint64_t>{});
			continue;
		}
		if (runs.empty()) continue;
		// each source goes to the run its centre projects into (or the nearest)
		std::vector<std::vector<uint64_t>> src(runs.size());
		const TPoint2D d = v.direction();
		for (uint64_t id : k < merged.sources.size() ? merged.sources[k] : std::vector<uint64_t>{})
		{
			const auto it = byId.find(id);
			double col = 0;
			if (it != byId.end())
			{
				const TPoint2D c = inputs[it->second].centre();
				col = ((c.x - v.start().x) * d.x + (c.y - v.start().y) * d.y) / v.resolution();
			}
			size_t best = 0;
			double bestDist = 1e300;
			for (size_t q = 0; q < runs.size(); ++q)
			{
				const double dist = std::max({0.0, runs[q].first - col, col - runs[q].last});
				if (dist < bestDist) bestDist = dist, best = q;
			}
			src[best].push_back(id);
		}
		for (size_t q = 0; q < runs.size(); ++q)
		{
			runs[q].isStatic = v.state != VectorState::Dynamic;
			GridVector piece = subVector(v, runs[q]);
			piece.state = v.state;
			piece.id = runs.size() == 1 ? v.id : nextId++;
			out.vectors.push_back(std::move(piece));
			out.sources.push_back(std::move(src[q]));
		}
	}
	return out;
}

}  // namespace gridvector
