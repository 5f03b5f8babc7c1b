#include "mstep/MStep.h"
#include "mstep/Incidence.h"
#include "core/SE2.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace gridvector
{
using Eigen::Matrix3d;
using Eigen::Vector3d;
using mrpt::math::TPose2D;

namespace
{
double secondsSince(std::chrono::steady_clock::time_point t0)
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Information of a relative measurement expressed in the frame of `frame` (rotated to the world).
Matrix3d toWorld(const Matrix3d& info, double framePhi)
{
	Matrix3d R = Matrix3d::Identity();
	R.topLeftCorner<2, 2>() << std::cos(framePhi), -std::sin(framePhi), std::sin(framePhi),
		std::cos(framePhi);
	return R * info * R.transpose();
}

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
	/** `headingWeight` [m/rad]: a pass's candidate is the pose nearest in position + weight x heading. */
	PassFinder(double cell, double headingWeight) : cell_(cell), headingWeight_(headingWeight) {}

	/** Passes of poses j + gap < i with within(j) true; then adds pose i. */
	template <class Within>
	const std::vector<Pass>& next(uint32_t i, const std::vector<TPose2D>& poses, uint32_t gap,
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
				return se2::distance(poses[i], poses[j]) +
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
	Key keyOf(const TPose2D& p) const { return {long(std::floor(p.x / cell_)), long(std::floor(p.y / cell_))}; }
	double cell_, headingWeight_;
	std::map<Key, std::vector<uint32_t>> grid_;
	std::vector<uint32_t> near_;
	std::vector<Pass> passes_;
};
}  // namespace

MStep::MStep(const GridVectorConfig& cfg)
	: cfg_(cfg), matcher_(cfg.matcher), loops_(cfg.matcher, cfg.mstep), graph_(cfg.posegraph)
{
}

void MStep::setOdometry(std::vector<TPose2D> odometry)
{
	odometry_ = std::move(odometry);
	path_.assign(odometry_.size(), 0.0);
	for (size_t t = 1; t < odometry_.size(); ++t)
		path_[t] = path_[t - 1] + se2::distance(odometry_[t - 1], odometry_[t]);
}

// mstep.register_min_incidence_deg: a vector seen along its line can lie elsewhere than where a scan facing it puts
// it, so registrations between viewpoints (overlap, loop) leave such vectors out; a sequential pair sees them alike.
const MStep::Scans& MStep::registered(EdgeKind kind, const Scans& scans) const
{
	return cfg_.mstep.registerMinIncidenceDeg > 0 && kind != EdgeKind::Sequential ? facing_ : scans;
}

// Sec. 4.2: one constraint <j, i> of Eq. 21 by vector matching (Sohn & Kim 2008) of the two scans' static vectors.
bool MStep::registerPair(uint32_t from, uint32_t to, EdgeKind kind, const Scans& scans,
						 const TPose2D& guess, Constraint& out, MStepReport& rep) const
{
	++rep.registrations;
	const Scans& v = registered(kind, scans);
	const MatchResult r = matcher_.match(v[from], v[to], guess);
	bool ok = r.ok();
	if (ok && kind != EdgeKind::Sequential) ok = r.matchedShare >= cfg_.mstep.overlapMinShare;
	if (!ok)
	{
		++rep.failedRegistrations;
		return false;
	}
	out = constraintOf({from, to}, kind, r, guess);
	return true;
}

Constraint MStep::constraintOf(const EdgeKey& key, EdgeKind kind, const MatchResult& r,
							   const TPose2D& checkedAt) const
{
	Constraint c;
	c.from = key.first;
	c.to = key.second;
	c.kind = kind;
	c.z = r.pose;
	c.information = r.information;
	c.correspondences = r.pairs;
	c.rms = r.rms;
	c.matchedLength = r.matchedLength;
	c.matchedShare = r.matchedShare;
	c.degeneracy = r.translationDegeneracy;
	c.dof = r.dof;
	c.sigFrom = sigs_[key.first];
	c.sigTo = sigs_[key.second];
	c.checkedAt = checkedAt;
	return c;
}

// Sec. 4.3: how far two scans' ranges "cover each other": their static vectors' corresponding length at the estimate.
double MStep::overlapLength(uint32_t from, uint32_t to, const Scans& scans, const Poses& poses) const
{
	MatchGates g;
	g.psi = cfg_.matcher.gatePsiInitialDeg * M_PI / 180;
	g.rho = cfg_.matcher.gateRhoInitial;
	g.minOverlap = cfg_.matcher.minOverlap;
	const Scans& v = registered(EdgeKind::Overlap, scans);
	return matcher_.correspondences(v[from], v[to], se2::relative(poses[from], poses[to]),
									g, nullptr);
}

// Eq. 24-25 with hysteresis: a stored pair lost even under widened gates, or a
// new pair inside the final gates, means the data association changed.
bool MStep::correspondencesChanged(const Constraint& c, const Scans& scans, const Poses& poses) const
{
	const TPose2D rel = se2::relative(poses[c.from], poses[c.to]);
	const Scans& v = registered(c.kind, scans);
	std::vector<VectorPair> wide, tight;
	matcher_.correspondences(v[c.from], v[c.to], rel, matcher_.finalGates(cfg_.mstep.recheckGateFactor), &wide);
	if (!std::includes(wide.begin(), wide.end(), c.correspondences.begin(), c.correspondences.end()))
		return true;
	matcher_.correspondences(v[c.from], v[c.to], rel, matcher_.finalGates(), &tight);
	return !std::includes(c.correspondences.begin(), c.correspondences.end(), tight.begin(),
						  tight.end());
}

// First M-step: register each scan against its predecessors, chaining the fused poses.
void MStep::chainSequential(const Scans& scans, Poses& poses, MStepReport& rep)
{
	const size_t n = scans.size();
	poses.assign(n, TPose2D(0, 0, 0));
	if (n == 0) return;
	poses[0] = odometry_[0];
	for (size_t i = 1; i < n; ++i)
	{
		report("sequential registration", i, n);
		const TPose2D odo = se2::relative(odometry_[i - 1], odometry_[i]);
		const TPose2D guess0 = se2::compose(poses[i - 1], odo);
		// information-weighted fusion of the predictions, linearised at the odometry guess
		Matrix3d sumI = toWorld(PoseGraph::odometryInformation(odo, cfg_.posegraph), poses[i - 1].phi);
		Vector3d sumIx = Vector3d::Zero();
		TPose2D guess = guess0;
		const size_t lo = i > size_t(cfg_.mstep.sequentialWindow) ? i - cfg_.mstep.sequentialWindow : 0;
		for (size_t j = i; j-- > lo;)
		{
			Constraint c;
			if (!registerChained(uint32_t(j), uint32_t(i), scans, se2::relative(poses[j], guess), c, rep)) continue;
			const TPose2D est = se2::compose(poses[j], c.z);
			const Matrix3d Iw = toWorld(c.information, poses[j].phi);
			const Vector3d d(est.x - guess0.x, est.y - guess0.y,
							 mrpt::math::wrapToPi(est.phi - guess0.phi));
			sumI += Iw;
			sumIx += Iw * d;
			const Vector3d x = sumI.ldlt().solve(sumIx);
			guess = TPose2D(guess0.x + x.x(), guess0.y + x.y(), mrpt::math::wrapToPi(guess0.phi + x.z()));
			constraints_[{uint32_t(j), uint32_t(i)}] = std::move(c);
			++rep.added;
		}
		poses[i] = guess;
	}
}

// A sequential pair of the first M-step from the chained guess, else (mstep.sequential_odometry_guess) from the
// odometry between its scans: a guess that does not pass through the predecessors' registered poses.
bool MStep::registerChained(uint32_t j, uint32_t i, const Scans& scans, const TPose2D& chained, Constraint& c,
							MStepReport& rep) const
{
	if (registerPair(j, i, EdgeKind::Sequential, scans, chained, c, rep)) return true;
	if (!cfg_.mstep.sequentialOdometryGuess) return false;
	const TPose2D odo = se2::relative(odometry_[j], odometry_[i]);
	return movedSince(chained, odo) && registerPair(j, i, EdgeKind::Sequential, scans, odo, c, rep);
}

// Eq. 25: the static children of both scans (their ids) as when the edge was registered.
bool MStep::sameScans(const Constraint& c) const
{
	return c.sigFrom == sigs_[c.from] && c.sigTo == sigs_[c.to];
}

// Eq. 25, Fig. 5: from M_cor (the edge's correspondences) the pairs affected by a vector whose
// children M_chd the last E-step changed, ids kept or not.
bool MStep::childrenChanged(const Constraint& c) const
{
	const auto in = [](const std::vector<uint64_t>& ids, uint64_t id) {
		return std::binary_search(ids.begin(), ids.end(), id);
	};
	const auto& a = changed_[c.from];
	const auto& b = changed_[c.to];
	if (a.empty() && b.empty()) return false;
	return std::any_of(c.correspondences.begin(), c.correspondences.end(),
					   [&](const VectorPair& p) { return in(a, p.a) || in(b, p.b); });
}

// Eq. 24-25: an edge is recomputed only if its data association changed.
void MStep::updateExisting(const Scans& scans, const Poses& poses, MStepReport& rep)
{
	const double far = cfg_.mstep.dropDistanceFactor * cfg_.mstep.overlapDistance;
	for (auto it = constraints_.begin(); it != constraints_.end();)
	{
		Constraint& c = it->second;
		const TPose2D rel = se2::relative(poses[c.from], poses[c.to]);
		const bool nonSeq = c.kind != EdgeKind::Sequential;
		// (a loop-search edge was accepted on its own criteria, not on the overlap length)
		if (nonSeq && (se2::distance(poses[c.from], poses[c.to]) > far ||
					   (c.kind == EdgeKind::Overlap &&
						overlapLength(c.from, c.to, scans, poses) < cfg_.mstep.dropLengthShare * cfg_.mstep.overlapMinLength)))
		{
			it = constraints_.erase(it);  // no longer overlapping: drop (Sec. 4.3)
			++rep.removed;
			continue;
		}
		const bool same = sameScans(c);
		// Eq. 24-25: re-register when a matched vector's children changed, else only when the
		// correspondences changed (a rejected edge: only when the vectors of its scans changed)
		const bool keep = !childrenChanged(c) &&
						  (c.rejected ? same
									  : (same && !movedSince(c.checkedAt, rel)) ||
											!correspondencesChanged(c, scans, poses));
		if (keep)
		{
			c.checkedAt = rel;
			c.sigFrom = sigs_[c.from], c.sigTo = sigs_[c.to];
			++it;
			continue;
		}
		Constraint fresh;
		if (!registerPair(c.from, c.to, c.kind, scans, rel, fresh, rep))
		{
			it = constraints_.erase(it);
			++rep.removed;
			continue;
		}
		const bool changed = fresh.correspondences != c.correspondences ||
							 se2::distance(fresh.z, c.z) > cfg_.mstep.changedTranslation ||
							 std::abs(mrpt::math::wrapToPi(fresh.z.phi - c.z.phi)) > cfg_.mstep.changedRotation;
		if (changed) ++rep.recomputed;
		else fresh.rejected = c.rejected;
		c = std::move(fresh);
		++it;
	}
}

// Later M-steps: sequential pairs not (or no longer) in the graph are retried.
void MStep::addSequential(const Scans& scans, const Poses& poses, MStepReport& rep)
{
	const size_t w = size_t(std::max(1, cfg_.mstep.sequentialWindow));
	for (size_t i = 1; i < scans.size(); ++i)
		for (size_t j = i > w ? i - w : 0; j < i; ++j)
		{
			const EdgeKey key{uint32_t(j), uint32_t(i)};
			if (constraints_.count(key)) continue;
			const TPose2D rel = se2::relative(poses[j], poses[i]);
			if (!retry(key, rel)) continue;
			Constraint c;
			if (registerPair(key.first, key.second, EdgeKind::Sequential, scans, rel, c, rep))
				keepEdge(key, std::move(c), rep);
			else
				failEdge(key, rel);
		}
}

// Eq. 24-25: a scan's signature covers what its registrations depend on, its static children M_chd:
// their ids and, since a child keeps its id when a split point moves (EStep::childId), a count of the
// E-steps that changed one of them (changed_, compared on the exact column ranges).
void MStep::signScans(const Scans& scans)
{
	childChanges_.resize(scans.size(), 0);
	sigs_.assign(scans.size(), 1469598103934665603ULL);
	for (size_t t = 0; t < scans.size(); ++t)
	{
		if (!changed_[t].empty()) ++childChanges_[t];
		for (const auto& s : scans[t]) sigs_[t] = (sigs_[t] ^ s.id) * 1099511628211ULL;  // FNV-1a
		sigs_[t] = (sigs_[t] ^ childChanges_[t]) * 1099511628211ULL;
	}
}

bool MStep::retry(const EdgeKey& key, const TPose2D& rel) const
{
	auto f = failed_.find(key);
	return f == failed_.end() || movedSince(f->second.rel, rel) ||
		   f->second.sigFrom != sigs_[key.first] || f->second.sigTo != sigs_[key.second];
}

bool MStep::movedSince(const TPose2D& before, const TPose2D& now) const
{
	return se2::distance(before, now) > cfg_.mstep.movedGateShare * cfg_.matcher.gateRhoFinal ||
		   std::abs(mrpt::math::wrapToPi(before.phi - now.phi)) >
			   cfg_.mstep.movedGateShare * cfg_.matcher.gatePsiFinalDeg * M_PI / 180;
}

bool MStep::hasEdgeNear(uint32_t i, uint32_t jlo, uint32_t jhi) const
{
	auto it = constraints_.lower_bound({jlo, 0});
	for (; it != constraints_.end() && it->first.first <= jhi; ++it)
		if (it->first.second == i) return true;
	return false;
}

// The pass's pose nearest in view if it overlaps pose i, else, with mstep.overlap_most_overlapping,
// the members that share at least overlap_min_length with it, the most overlapping first.
std::vector<uint32_t> MStep::overlapPartners(uint32_t i, uint32_t nearest, const std::vector<uint32_t>& members,
											 const Scans& scans, const Poses& poses) const
{
	const double need = cfg_.mstep.overlapMinLength;
	if (!retry({nearest, i}, se2::relative(poses[nearest], poses[i]))) return {};  // failed, nothing changed since
	if (overlapLength(nearest, i, scans, poses) >= need) return {nearest};
	if (!cfg_.mstep.overlapMostOverlapping) return {};
	std::vector<std::pair<double, uint32_t>> ranked;
	for (uint32_t j : members)
	{
		if (j == nearest || scans[j].empty() || !retry({j, i}, se2::relative(poses[j], poses[i]))) continue;
		const double len = overlapLength(j, i, scans, poses);
		if (len >= need) ranked.emplace_back(-len, j);
	}
	std::sort(ranked.begin(), ranked.end());
	std::vector<uint32_t> out;
	for (const auto& r : ranked) out.push_back(r.second);
	return out;
}

void MStep::keepEdge(const EdgeKey& key, Constraint c, MStepReport& rep)
{
	constraints_[key] = std::move(c);
	failed_.erase(key);
	++rep.added;
}

void MStep::failEdge(const EdgeKey& key, const TPose2D& rel)
{
	failed_[key] = {rel, sigs_[key.first], sigs_[key.second]};
}

// An overlap registration from another pose of the pass than the nearest (which did not see the place)
// is kept only if it cannot slide along a corridor (one whose weak direction is marginalised out cannot).
bool MStep::registerOverlap(const EdgeKey& key, bool nearest, const Scans& scans, const TPose2D& rel, Constraint& c,
							MStepReport& rep)
{
	return registerPair(key.first, key.second, EdgeKind::Overlap, scans, rel, c, rep) &&
		   (nearest || c.degeneracy >= cfg_.matcher.degenerateRatio || c.dof < 3);
}

// Sec. 4.3, the topology change: scans whose ranges cover each other get an edge.
// Overlap edges: for each pose, one edge into every earlier pass through its place.
std::vector<EdgeKey> MStep::addOverlaps(const Scans& scans, const Poses& poses, MStepReport& rep,
										std::vector<MovedPair>* moved)
{
	std::vector<EdgeKey> fresh;
	const double d = cfg_.mstep.overlapDistance;
	if (d <= 0) return fresh;
	const uint32_t gap = uint32_t(std::max(1, cfg_.mstep.sequentialWindow));
	PassFinder finder(d, cfg_.mstep.passHeadingWeight);
	for (uint32_t i = 0; i < scans.size(); ++i)
	{
		report("overlap registration", i, scans.size());
		const auto& passes = finder.next(i, poses, gap, uint32_t(cfg_.mstep.overlapRunGap),
										 [&](uint32_t j) { return se2::distance(poses[i], poses[j]) < d; });
		if (scans[i].empty()) continue;
		for (const auto& p : passes)
		{
			if (hasEdgeNear(i, p.lo, p.hi)) continue;
			for (uint32_t from : overlapPartners(i, p.nearest, p.members, scans, poses))
			{
				const EdgeKey key{from, i};
				const TPose2D rel = se2::relative(poses[from], poses[i]);
				Constraint c;
				if (registerOverlap(key, from == p.nearest, scans, rel, c, rep))
				{
					if (moved && beyondInitialGates(rel, c.z))
						moved->push_back({key, from == p.nearest});  // registered again once the rest is optimised
					else
					{
						keepEdge(key, std::move(c), rep);
						fresh.push_back(key);
					}
					break;
				}
				failEdge(key, rel);
			}
		}
	}
	return fresh;
}

// Was pose i searched against a pose j of [jlo, jhi] from (nearly) the same relative pose?
bool MStep::searchedNear(uint32_t i, uint32_t jlo, uint32_t jhi, const Poses& poses) const
{
	for (auto it = searched_.lower_bound({jlo, 0}); it != searched_.end() && it->first.first <= jhi; ++it)
	{
		if (it->first.second != i) continue;
		const TPose2D rel = se2::relative(poses[it->first.first], poses[i]);
		if (se2::distance(it->second, rel) < cfg_.mstep.searchedNearDistance &&
			std::abs(mrpt::math::wrapToPi(it->second.phi - rel.phi)) < cfg_.mstep.searchedNearDeg * M_PI / 180)
			return true;
	}
	return false;
}

// Beyond the paper (Sec. 5.1: no loop detection): the loop-search window from the odometry model along the path.
LoopWindow MStep::windowOf(uint32_t from, uint32_t to) const
{
	const auto& o = cfg_.posegraph;
	const double len = path_[to] - path_[from];
	const double k = cfg_.mstep.loopSearchSigmas;
	LoopWindow w;
	w.translation = std::clamp(k * o.odometrySigmaXYPerM * len, cfg_.mstep.loopWindowMinTranslation,
							   cfg_.mstep.loopSearchMaxRadius);
	const double sr = o.odometrySigmaPhiPerM * len + o.odometrySigmaPhi * std::sqrt(double(to - from));
	w.rotation = std::clamp(k * sr, cfg_.mstep.loopWindowMinRotationDeg * M_PI / 180, M_PI);
	return w;
}

// An overlap edge of this M-step not verified yet links the places only provisionally: verifyOverlaps may
// still drop it, and then no edge would join the passes whose loop search it spared.
MStep::Link MStep::linked(uint32_t jlo, uint32_t jhi, uint32_t ilo, uint32_t ihi,
						  const std::vector<EdgeKey>& unverified) const
{
	Link link = Link::None;
	auto it = constraints_.lower_bound({jlo, 0});
	for (; it != constraints_.end() && it->first.first <= jhi; ++it)
	{
		if (it->first.second < ilo || it->first.second > ihi || !fixesPlace(it->second)) continue;
		if (std::find(unverified.begin(), unverified.end(), it->first) == unverified.end()) return Link::Verified;
		link = Link::Unverified;
	}
	return link;
}

// A corridor-degenerate edge leaves the position along the corridor open, a rejected one
// says nothing: with loop_search_weak_links such links do not spare a pair the loop search.
bool MStep::fixesPlace(const Constraint& c) const
{
	return !cfg_.mstep.loopSearchWeakLinks ||
		   (!c.rejected && c.degeneracy >= cfg_.matcher.degenerateRatio);
}

// Beyond the paper: the pass's pose nearest in view, then every pose of the pass at least
// loop_search_candidate_spacing along the path from those already taken.
std::vector<uint32_t> MStep::loopCandidates(uint32_t nearest, const std::vector<uint32_t>& members) const
{
	std::vector<uint32_t> out{nearest};
	const double spacing = cfg_.mstep.loopSearchCandidateSpacing;
	if (spacing <= 0) return out;
	for (uint32_t j : members)
		if (std::all_of(out.begin(), out.end(), [&](uint32_t k) { return std::abs(path_[j] - path_[k]) >= spacing; }))
			out.push_back(j);
	return out;
}

MatchResult MStep::bestLoop(const Scans& vectors, uint32_t i, const std::vector<uint32_t>& candidates,
							const Poses& poses, uint32_t& from, MStepReport& rep) const
{
	MatchResult best;
	for (uint32_t j : candidates)
	{
		if (j != candidates.front() && vectors[j].empty()) continue;
		++rep.registrations;
		MatchResult r = loops_.search(vectors[j], vectors[i], se2::relative(poses[j], poses[i]), windowOf(j, i));
		if (!r.ok()) ++rep.failedRegistrations;
		else if (!best.ok() || r.matchedLength > best.matchedLength) best = std::move(r), from = j;
	}
	return best;
}

bool MStep::relabelled(uint32_t t, const Scans& scans) const
{
	auto length = [](const std::vector<MatchSegment>& s) {
		double l = 0;
		for (const auto& m : s) l += m.length;
		return l;
	};
	return length(scans[t]) < length(all_[t]) - 1e-6;
}

// Loop search: for each pose, every earlier pass within the window (its nearest
// pose and the other candidates) that no edge links to the pose's neighbourhood yet.
std::vector<EdgeKey> MStep::searchLoops(const Scans& scans, const Poses& poses, const std::vector<EdgeKey>& added,
										MStepReport& rep, std::vector<EdgeKey>* deferred, const std::vector<EdgeKey>* only)
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
		report("loop search", i, scans.size());
		const auto& passes = finder.next(i, poses, gap, K, [&](uint32_t j) {
			return se2::distance(poses[i], poses[j]) < windowOf(j, i).translation;
		});
		if (scans[i].empty()) continue;
		for (const auto& p : passes)
		{
			if (only && std::find(only->begin(), only->end(), EdgeKey{p.nearest, i}) == only->end()) continue;
			const Link link = linked(p.lo > K ? p.lo - K : 0, p.hi + K, i > K ? i - K : 0, i, added);
			if (link == Link::Verified || (link == Link::Unverified && !deferred)) continue;
			if (searchedNear(i, p.lo, p.hi, poses)) continue;
			if (link == Link::Unverified)
			{
				deferred->push_back({p.nearest, i});  // searched if verifyOverlaps drops the edge
				continue;
			}
			searched_[{p.nearest, i}] = se2::relative(poses[p.nearest], poses[i]);
			++rep.loopSearches;
			// the best registration against the pass's candidates (the most matched length)
			uint32_t from = p.nearest;
			const auto candidates = loopCandidates(p.nearest, p.members);
			MatchResult best = bestLoop(registered(EdgeKind::Loop, scans), i, candidates, poses, from, rep);
			if (!best.ok() && cfg_.mstep.loopSearchAllVectors && all_.size() == scans.size() &&
				(relabelled(i, scans) ||
				 std::any_of(candidates.begin(), candidates.end(), [&](uint32_t j) { return relabelled(j, scans); })))
				best = bestLoop(all_, i, candidates, poses, from, rep);  // what the E-step made dynamic too
			if (best.ok()) found.push_back(constraintOf({from, i}, EdgeKind::Loop, best, se2::relative(poses[from], poses[i])));
		}
	}
	return keepLoops(found, added, rep);
}

std::vector<EdgeKey> MStep::keepLoops(std::vector<Constraint>& found, const std::vector<EdgeKey>& added,
									  MStepReport& rep)
{
	std::vector<EdgeKey> fresh;
	// added after the search, so that every pose near a found loop is searched too
	// (its neighbours' edges then support it in verifyOverlaps)
	for (Constraint& c : found)
	{
		const EdgeKey key{c.from, c.to};
		auto old = constraints_.find(key);
		if (old != constraints_.end())  // a weak edge of the same pair: replaced unless unverified
		{
			if (std::find(added.begin(), added.end(), key) == added.end())
			{
				replaced_[key] = std::move(old->second);
				++rep.recomputed;
				fresh.push_back(key);
			}  // (else an overlap edge added in this step, already to be verified)
			old->second = std::move(c);
			continue;
		}
		fresh.push_back(key);
		constraints_[key] = std::move(c);
		++rep.added;
	}
	return fresh;
}

// The order of the M-step: overlap edges, loop search, verifyOverlaps; a loop search that an overlap edge of
// this step deferred runs now, where verifyOverlaps dropped the edge, and its edges are verified in turn.
void MStep::searchDeferred(const Scans& scans, const Poses& poses, const std::vector<EdgeKey>& deferred,
						   MStepReport& rep)
{
	if (deferred.empty()) return;
	const auto found = searchLoops(scans, poses, {}, rep, nullptr, &deferred);
	verifyOverlaps(poses, found, rep);
}

// Pairwise consistency of loop closures: a new overlap edge (j, i) is supported by
// another edge (j', i') near both of its ends when the cycle j -> i -> i' -> j' -> j
// closes within the edges' and the local chains' uncertainty (Mahalanobis gate).
void MStep::verifyOverlaps(const Poses& poses, const std::vector<EdgeKey>& fresh, MStepReport& rep)
{
	const uint32_t K = uint32_t(std::max(1, cfg_.mstep.overlapRunGap));
	const auto& m = cfg_.mstep;
	const Matrix3d reg = Vector3d(m.consistencyInfoXY, m.consistencyInfoXY, m.consistencyInfoPhi).asDiagonal();
	std::vector<EdgeKey> drop;
	for (const EdgeKey& key : fresh)
	{
		const Constraint& c = constraints_.at(key);
		const Matrix3d covC = (graphInformation(c) + reg).inverse();
		int support = 0, against = 0;
		auto it = constraints_.lower_bound({c.from > K ? c.from - K : 0, 0});
		for (; it != constraints_.end() && it->first.first <= c.from + K; ++it)
		{
			const Constraint& o = it->second;
			if (&o == &c || o.kind == EdgeKind::Sequential || o.rejected) continue;
			if (o.to + K < c.to || o.to > c.to + K) continue;
			// z' predicted from z through the local chains of the current trajectory
			const TPose2D pred = se2::compose(
				se2::compose(se2::relative(poses[o.from], poses[c.from]), c.z),
				se2::relative(poses[c.to], poses[o.to]));
			const Vector3d d = PoseGraph::error(TPose2D(0, 0, 0), pred, o.z);
			const double steps = std::abs(double(o.from) - c.from) + std::abs(double(o.to) - c.to);
			const Matrix3d chain = Vector3d(m.consistencyChainVarXY, m.consistencyChainVarXY, m.consistencyChainVarPhi).asDiagonal() *
								 (1.0 + steps);
			const Matrix3d cov = covC + (graphInformation(o) + reg).inverse() + chain;
			(d.dot(cov.ldlt().solve(d)) < cfg_.mstep.consistencyChi2 ? support : against)++;
		}
		const bool strong = c.correspondences.size() >= size_t(m.strongMinCorrespondences) &&
							c.matchedShare >= m.strongMinShare && c.degeneracy >= m.strongMinDegeneracy;
		if (support > against || (support == 0 && against == 0 && strong)) continue;
		drop.push_back(key);
	}
	for (const EdgeKey& k : drop)
	{
		failEdge(k, se2::relative(poses[k.first], poses[k.second]));
		++rep.unverified;
		auto r = replaced_.find(k);
		if (r != replaced_.end())
		{
			constraints_[k] = std::move(r->second);  // the weak edge it replaced stays
			--rep.recomputed;
			continue;
		}
		constraints_.erase(k);
		--rep.added;
	}
	replaced_.clear();
}

// Eq. 24-25 for rejections: a pair rejected reconsider_limit times with the same
// correspondences stays out, also when re-registered with the same correspondences
// (else the edges flip in and out and EM never converges); other correspondences
// (a changed data association) start the count again. Rejections of the first
// reconsider_free_steps M-steps (raw chain, first loop closures) do not count.
bool MStep::rejectionStands(const EdgeKey& key, const Constraint& c) const
{
	if (cfg_.mstep.reconsiderLimit <= 0) return false;
	auto r = rejections_.find(key);
	return r != rejections_.end() && r->second.count >= cfg_.mstep.reconsiderLimit &&
		   r->second.correspondences == c.correspondences;
}

void MStep::countRejection(const EdgeKey& key, const Constraint& c)
{
	Rejections& r = rejections_[key];
	if (r.correspondences != c.correspondences) r = {0, c.correspondences};
	++r.count;
}

// The matcher's information is over z in the earlier scan's frame; Eq. 21's error has its
// translation in z's frame (PoseGraph::errorFrameInformation).
Matrix3d MStep::graphInformation(const Constraint& c) const
{
	return cfg_.mstep.informationInEdgeFrame ? PoseGraph::errorFrameInformation(c.information, c.z) : c.information;
}

// Eq. 20-22: the odometry edges (u^t) and the active registrations of static vectors, Eq. 22 minimised.
std::vector<EdgeKey> MStep::optimise(Poses& poses, MStepReport& rep, bool count)
{
	graph_.setNodes(poses);
	graph_.clearEdges();
	for (uint32_t i = 1; i < poses.size(); ++i)
	{
		PoseEdge e;
		e.from = i - 1;
		e.to = i;
		e.z = se2::relative(odometry_[i - 1], odometry_[i]);
		e.information = PoseGraph::odometryInformation(e.z, cfg_.posegraph);
		e.kind = EdgeKind::Odometry;
		graph_.addEdge(e);
	}
	std::vector<Constraint*> byEdge(graph_.edges().size(), nullptr);
	for (auto& [key, c] : constraints_)
	{
		// switchable behaviour: an edge rejected against an earlier estimate gets another
		// chance, unless it was rejected reconsider_limit times with these correspondences
		if (cfg_.mstep.reconsiderRejected) c.rejected = rejectionStands(key, c);
		if (c.rejected) continue;
		PoseEdge e;
		e.from = c.from;
		e.to = c.to;
		e.z = c.z;
		e.information = graphInformation(c);
		e.dof = c.dof;
		e.kind = c.kind;
		graph_.addEdge(e);
		byEdge.push_back(&c);
	}
	rep.optimisation = graph_.optimize();
	std::vector<EdgeKey> rejected;
	for (size_t k = 0; k < byEdge.size(); ++k)
		if (byEdge[k] && !graph_.edges()[k].active)
		{
			byEdge[k]->rejected = true;
			rejected.push_back({byEdge[k]->from, byEdge[k]->to});
		}
	poses = graph_.nodes();
	if (count) countRejections(rejected);
	return rejected;
}

void MStep::countRejections(const std::vector<EdgeKey>& keys)
{
	if (steps_ <= cfg_.mstep.reconsiderFreeSteps) return;
	for (const EdgeKey& k : keys) countRejection(k, constraints_.at(k));
}

bool MStep::beyondInitialGates(const TPose2D& guess, const TPose2D& z) const
{
	return se2::distance(guess, z) > cfg_.matcher.gateRhoInitial ||
		   std::abs(mrpt::math::wrapToPi(guess.phi - z.phi)) > cfg_.matcher.gatePsiInitialDeg * M_PI / 180;
}

// mstep.overlap_reregister_moved: a registration that had to move beyond the initial gates started
// from an estimate that did not show the overlap; from the estimate the other edges give, the
// matcher starts inside its gates (or, where nothing moved the pair, repeats the first registration).
bool MStep::reregisterMoved(const Scans& scans, Poses& poses, const std::vector<MovedPair>& moved, MStepReport& rep)
{
	std::vector<EdgeKey> again;
	for (const MovedPair& m : moved)
	{
		if (constraints_.count(m.key)) continue;  // the loop search registered the pair
		const TPose2D rel = se2::relative(poses[m.key.first], poses[m.key.second]);
		Constraint c;
		if (registerOverlap(m.key, m.nearest, scans, rel, c, rep))
		{
			keepEdge(m.key, std::move(c), rep);
			again.push_back(m.key);
		}
		else
			failEdge(m.key, rel);
	}
	verifyOverlaps(poses, again, rep);
	if (std::none_of(again.begin(), again.end(), [&](const EdgeKey& k) { return constraints_.count(k) > 0; })) return false;
	const OptimizeStats first = rep.optimisation;
	optimise(poses, rep);
	rep.optimisation.iterations += first.iterations;
	rep.optimisation.seconds += first.seconds;
	rep.optimisation.initialError = first.initialError;
	return true;
}

// Sec. 4.2-4.3: one M-step: the changed constraints of Eq. 24 (re-)registered, Eq. 22 re-optimised if any; Fig. 11's share.
MStepReport MStep::run(const Scans& scans, Poses& poses, const std::vector<std::vector<uint64_t>>* changedChildren)
{
	const auto t0 = std::chrono::steady_clock::now();
	MStepReport rep;
	++steps_;
	if (odometry_.size() != scans.size())
		throw std::invalid_argument("MStep: odometry and scans differ in length");
	const size_t before = constraints_.size();
	if (cfg_.mstep.registerMinIncidenceDeg > 0) facing_ = facingVectors(scans, cfg_.mstep.registerMinIncidenceDeg);
	changed_.assign(scans.size(), {});
	if (changedChildren)
		for (size_t t = 0; t < scans.size() && t < changedChildren->size(); ++t)
		{
			changed_[t] = (*changedChildren)[t];
			std::sort(changed_[t].begin(), changed_[t].end());
		}
	signScans(scans);
	if (!started_)
	{
		chainSequential(scans, poses, rep);
		started_ = true;
	}
	else
	{
		updateExisting(scans, poses, rep);
		addSequential(scans, poses, rep);
	}
	std::vector<MovedPair> moved;
	auto fresh = addOverlaps(scans, poses, rep, cfg_.mstep.overlapReregisterMoved ? &moved : nullptr);
	std::vector<EdgeKey> deferred;
	const auto found = searchLoops(scans, poses, fresh, rep, &deferred);
	fresh.insert(fresh.end(), found.begin(), found.end());
	verifyOverlaps(poses, fresh, rep);
	searchDeferred(scans, poses, deferred, rep);
	rep.registrationSeconds = secondsSince(t0);
	if (!moved.empty())
	{
		const auto rejected = optimise(poses, rep, false);  // without the moved pairs
		if (!reregisterMoved(scans, poses, moved, rep)) countRejections(rejected);  // it was the last
	}
	else if (rep.added + rep.removed + rep.recomputed > 0)
		optimise(poses, rep);  // else: still optimal
	rep.constraints = constraints_.size();
	for (const auto& [key, c] : constraints_)
	{
		if (c.rejected) continue;
		++rep.active;
		if (c.kind == EdgeKind::Sequential) ++rep.sequential;
		else if (c.kind == EdgeKind::Overlap) ++rep.overlap;
		else if (c.kind == EdgeKind::Loop) ++rep.loop;
	}
	const size_t denom = std::max<size_t>(1, std::max(before, rep.constraints));
	rep.changedShare = double(rep.added + rep.removed + rep.recomputed) / denom;
	rep.seconds = secondsSince(t0);
	return rep;
}

}  // namespace gridvector
