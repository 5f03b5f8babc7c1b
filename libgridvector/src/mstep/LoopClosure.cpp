#include "mstep/LoopClosure.h"
#include "mstep/Consistency.h"
#include "mstep/PassFinder.h"
#include <mrpt/math/TPose2D.h>

#include <algorithm>
#include <cmath>

namespace gridvector
{
using mrpt::math::TPose2D;

LoopClosure::LoopClosure(const GridVectorConfig& cfg, ConstraintSet& book, const ProgressFn& progress)
	: cfg_(cfg), book_(book), progress_(progress), loops_(cfg.matcher, cfg.mstep)
{}

void LoopClosure::setOdometry(const Poses& odometry)
{
	path_.assign(odometry.size(), 0.0);
	for (size_t t = 1; t < odometry.size(); ++t)
		path_[t] = path_[t - 1] + std::hypot(odometry[t - 1].x - odometry[t].x, odometry[t - 1].y - odometry[t].y);
}

// Was pose i searched against a pose j of [jlo, jhi] from (nearly) the same relative pose?
bool LoopClosure::searchedNear(uint32_t i, uint32_t jlo, uint32_t jhi, const Poses& poses) const
{
	return anyEdgeIn(searched_, jlo, jhi, i, i, [&](const EdgeKey& key, const TPose2D& at) {
		const TPose2D rel = poses[i] - poses[key.first];
		return std::hypot(at.x - rel.x, at.y - rel.y) < kSearchedNearDistance &&
			   std::abs(mrpt::math::wrapToPi(at.phi - rel.phi)) < kSearchedNearDeg * M_PI / 180;
	});
}

// Beyond the paper (Sec. 5.1: no loop detection): the loop-search window from the odometry model along the path.
LoopWindow LoopClosure::windowOf(uint32_t from, uint32_t to) const
{
	const auto& o = cfg_.posegraph;
	const double len = path_[to] - path_[from];
	const double k = cfg_.mstep.loopSearchSigmas;
	const double R = cfg_.mstep.loopSearchMaxRadius;
	LoopWindow w;
	w.translation = std::clamp(k * o.odometrySigmaXYPerM * len, std::min(kLoopWindowMinTranslation, R), R);
	const double sr = o.odometrySigmaPhiPerM * len + o.odometrySigmaPhi * std::sqrt(double(to - from));
	w.rotation = std::clamp(k * sr, kLoopWindowMinRotationDeg * M_PI / 180, M_PI);
	return w;
}

double LoopClosure::coveredPath() const
{
	const double growth = cfg_.mstep.loopSearchSigmas * cfg_.posegraph.odometrySigmaXYPerM;
	return growth > 0 ? cfg_.mstep.loopSearchMaxRadius / growth : std::numeric_limits<double>::infinity();
}

// An overlap edge of this M-step not verified yet links the places only provisionally: verifyOverlaps may
// still drop it, and then no edge would join the passes whose loop search it spared.
LoopClosure::Link LoopClosure::linked(uint32_t jlo, uint32_t jhi, uint32_t ilo, uint32_t ihi,
									  const std::vector<EdgeKey>& unverified) const
{
	Link link = Link::None;
	const bool verified = anyEdgeIn(book_.edges, jlo, jhi, ilo, ihi, [&](const EdgeKey& key, const Constraint& c) {
		if (!fixesPlace(c)) return false;
		if (std::find(unverified.begin(), unverified.end(), key) == unverified.end()) return true;
		link = Link::Unverified;
		return false;
	});
	return verified ? Link::Verified : link;
}

// A corridor-degenerate edge leaves the position along the corridor open, a rejected one
// says nothing: with loop_search_weak_links such links do not spare a pair the loop search.
bool LoopClosure::fixesPlace(const Constraint& c) const
{
	return !cfg_.mstep.loopSearchWeakLinks || (!c.rejected && c.degeneracy >= cfg_.matcher.degenerateRatio);
}

MatchResult LoopClosure::searchPair(const Scans& vectors, uint32_t j, uint32_t i, const Poses& poses,
									MStepReport& rep) const
{
	++rep.registrations;
	MatchResult r = loops_.search(vectors[j], vectors[i], poses[i] - poses[j], windowOf(j, i));
	if (!r.ok()) ++rep.failedRegistrations;
	return r;
}

bool LoopClosure::relabelled(uint32_t t, const Scans& scans) const
{
	auto length = [](const std::vector<MatchSegment>& s) {
		double l = 0;
		for (const auto& m : s) l += m.length;
		return l;
	};
	return length(scans[t]) < length(all_[t]) - 1e-6;
}

// Loop search: for each pose, each earlier pass within the window (its pose nearest in view) that it is
// registered into (PassFinder::registeredPass)
// that no edge links to the pose's neighbourhood yet.
std::vector<EdgeKey> LoopClosure::search(const Scans& scans, const Poses& poses, const std::vector<EdgeKey>& added,
										 MStepReport& rep, std::vector<EdgeKey>* deferred,
										 const std::vector<EdgeKey>* only)
{
	std::vector<EdgeKey> fresh;
	const double R = cfg_.mstep.loopSearchMaxRadius;
	if (!cfg_.mstep.loopSearch || R <= 0) return fresh;
	const uint32_t gap = uint32_t(std::max(1, cfg_.mstep.sequentialWindow));
	const uint32_t K = uint32_t(std::max(1, cfg_.mstep.overlapRunGap));
	PassFinder finder(R, cfg_.mstep.passHeadingWeight);
	std::vector<Constraint> found;
	for (uint32_t i = 0; i < scans.size(); ++i)
	{
		reportProgress(progress_, "loop search", i, scans.size());
		const auto& passes = finder.next(i, poses, gap, K, [&](uint32_t j) {
			return std::hypot(poses[i].x - poses[j].x, poses[i].y - poses[j].y) < windowOf(j, i).translation;
		});
		if (scans[i].empty()) continue;
		for (size_t k = 0; k < passes.size(); ++k)
		{
			const auto& p = passes[k];
			if (!PassFinder::registeredPass(k, passes.size()))
			{
				if (!only) ++rep.passesBeyondBound;
				continue;
			}
			if (only && std::find(only->begin(), only->end(), EdgeKey{p.nearest, i}) == only->end()) continue;
			if (path_[i] - path_[p.nearest] > maxPath_) continue;  // a later round's (MStep::closeLoopsByReach)
			const Link link = linked(p.lo > K ? p.lo - K : 0, p.hi + K, i > K ? i - K : 0, i, added);
			if (link == Link::Verified || (link == Link::Unverified && !deferred)) continue;
			if (searchedNear(i, p.lo, p.hi, poses)) continue;
			if (link == Link::Unverified)
			{
				deferred->push_back({p.nearest, i});  // searched if verifyOverlaps drops the edge
				continue;
			}
			const uint32_t j = p.nearest;
			searched_[{j, i}] = poses[i] - poses[j];
			++rep.loopSearches;
			MatchResult best = searchPair(scans, j, i, poses, rep);
			if (!best.ok() && cfg_.mstep.loopSearchAllVectors && all_.size() == scans.size() &&
				(relabelled(i, scans) || relabelled(j, scans)))
				best = searchPair(all_, j, i, poses, rep);  // what the E-step made dynamic too
			if (best.ok()) found.push_back(book_.make({j, i}, EdgeKind::Loop, best, poses[i] - poses[j]));
		}
	}
	return keep(found, added, rep);
}

std::vector<EdgeKey> LoopClosure::keep(std::vector<Constraint>& found, const std::vector<EdgeKey>& added,
									   MStepReport& rep)
{
	std::vector<EdgeKey> fresh;
	// added after the search, so that every pose near a found loop is searched too
	// (its neighbours' edges then support it in verifyOverlaps)
	for (Constraint& c : found)
	{
		const EdgeKey key{c.from, c.to};
		auto old = book_.edges.find(key);
		if (old != book_.edges.end())  // a weak edge of the same pair: replaced unless unverified
		{
			if (std::find(added.begin(), added.end(), key) == added.end())
			{
				book_.replaced[key] = std::move(old->second);
				++rep.recomputed;
				fresh.push_back(key);
			}  // (else an overlap edge added in this step, already to be verified)
			old->second = std::move(c);
			continue;
		}
		fresh.push_back(key);
		book_.edges[key] = std::move(c);
		++rep.added;
	}
	return fresh;
}

bool LoopClosure::closeLoops(const Scans& scans, const Poses& poses, std::vector<EdgeKey>& fresh, MStepReport& rep)
{
	std::vector<EdgeKey> deferred;
	const auto found = search(scans, poses, fresh, rep, &deferred);
	fresh.insert(fresh.end(), found.begin(), found.end());
	verifyOverlaps(book_, cfg_.mstep, poses, fresh, rep);
	const auto later = searchDeferred(scans, poses, deferred, rep);
	fresh.insert(fresh.end(), later.begin(), later.end());
	return !deferred.empty();
}

// The order of the M-step: overlap edges, loop search, verifyOverlaps; a loop search that an overlap edge of
// this step deferred runs now, where verifyOverlaps dropped the edge, and its edges are verified in turn.
std::vector<EdgeKey> LoopClosure::searchDeferred(const Scans& scans, const Poses& poses,
												 const std::vector<EdgeKey>& deferred, MStepReport& rep)
{
	if (deferred.empty()) return {};
	const auto found = search(scans, poses, {}, rep, nullptr, &deferred);
	verifyOverlaps(book_, cfg_.mstep, poses, found, rep);
	return found;
}

}  // namespace gridvector
