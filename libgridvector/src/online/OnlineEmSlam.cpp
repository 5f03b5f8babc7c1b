#include "online/OnlineEmSlam.h"
#include "doors/DoorDetector.h"
#include "doors/DoorExclusion.h"
#include "em/EmSlam.h"
#include "map/OccupancyConversion.h"
#include "mstep/AliasSweep.h"
#include "mstep/Consistency.h"
#include "mstep/ConstraintUpdate.h"
#include "mstep/PoseFusion.h"

#include <mrpt/math/wrap2pi.h>

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

namespace gridvector::online
{
using mrpt::math::TPose2D;

OnlineEmSlam::OnlineEmSlam(const GridVectorConfig& cfg)
	: cfg_(cfg),
	  book_(cfg_.matcher),
	  reg_(cfg_, book_),
	  overlaps_(cfg_, book_, reg_, progress_),
	  loopClosure_(cfg_, book_, progress_),
	  loopSearch_(cfg_.matcher, cfg_.mstep),
	  passes_(std::max({cfg_.mstep.loopSearchMaxRadius, cfg_.mstep.overlapDistance, kLoopWindowMinTranslation}),
			  cfg_.mstep.passHeadingWeight),
	  optimiser_(cfg_),
	  live_(std::make_unique<ClassifiedMap>(cfg_))
{}

namespace
{
/** Does a registration `z` (information `info`, singular along a corridor's axis) agree with Eq. 20's odometry
 * prediction `odo` of the same relative pose? Not when the chi2 of their difference (its information
 * I_o (I_o + I_z)^-1 I_z) exceeds posegraph.reject_chi2, the level at which the pose graph removes an edge: a
 * registration the motion model cannot have produced. */
bool agreesWithOdometry(const TPose2D& odo, const TPose2D& z, const Eigen::Matrix3d& info, const PoseGraphOptions& o)
{
	const Eigen::Matrix3d odoInfo = PoseGraph::odometryInformation(odo, o);
	const Eigen::Vector3d d(z.x - odo.x, z.y - odo.y, mrpt::math::wrapToPi(z.phi - odo.phi));
	return d.dot(odoInfo * (odoInfo + info).ldlt().solve(info * d)) <= o.rejectChi2;
}
}  // namespace

// Sec. 4.2: the scan registered against the last keyframe from the odometry since it and fused with that odometry
// (PoseFusion), as the batch's SequentialChain does: a corridor's axis, which the match leaves free, and a match
// the motion model rules out (agreesWithOdometry) come from the odometry.
TPose2D OnlineEmSlam::poseNow(const std::vector<MatchSegment>& segs, const TPose2D& odometry, bool& registered) const
{
	const TPose2D guess = odometry - keyOdo_.back();
	const MatchResult r = reg_.matcher().match(segs_.back(), segs, guess);
	registered = r.ok() && agreesWithOdometry(guess, r.pose, r.information, cfg_.posegraph);
	PoseFusion fusion(guess, PoseGraph::odometryInformation(guess, cfg_.posegraph));
	if (registered) fusion.add(r.pose, r.information);
	return keyPose_.back() + fusion.pose();
}

OnlineStep OnlineEmSlam::addScan(const LocalScan& scan, const TPose2D& odometry)
{
	OnlineStep st;
	const size_t t = odometry_.size();
	std::vector<MatchSegment> segs = MatchSegment::fromVectors(scan.vectors, scan.rangeSigma);
	for (auto& s : segs) s.id = nextSegmentId_++;
	TPose2D pose = odometry;  // the first scan fixes the frame, as the batch's first pose
	st.keyframe = keyPose_.empty();
	if (!st.keyframe)
	{
		pose = poseNow(segs, odometry, st.registered);
		st.keyframe = EmSlam::isKeyframe(keyOdo_.back(), odometry, cfg_.mstep);
	}
	odometry_.push_back(odometry);
	if (st.keyframe)
	{
		const uint32_t i = uint32_t(keyPose_.size());
		segs_.push_back(std::move(segs));
		keyScans_.push_back(scan);
		if (keyScans_.back().scanIndex < 0) keyScans_.back().scanIndex = int64_t(t);
		keyOdo_.push_back(odometry);
		keyPose_.push_back(pose);
		keyScan_.push_back(t);
		book_.beginStep(segs_, nullptr);  // the new keyframe's signature (its vectors never change)
		loopClosure_.setOdometry(keyOdo_);  // the loop-search windows grow along the path
		addEdges(i, st);
		pose = keyPose_[i];  // fused from its sequential edges
		st.optimised = st.loops > 0;
		due_ = due_ || st.optimised;
		st.classified = live_->insert(pose, keyScans_.back());
		liveAt_.push_back(pose);
	}
	st.reanchored = reanchor(kReanchorPerScan);
	st.pose = lastPose_ = pose;
	return st;
}

// Sec. 4.2-4.3 for one new keyframe: its sequential edges, then per earlier pass near it an overlap edge
// where the estimate links the passes already, else a loop search; the new edges' consistency checked.
void OnlineEmSlam::addEdges(uint32_t i, OnlineStep& st)
{
	const auto& m = cfg_.mstep;
	const uint32_t w = uint32_t(std::max(1, m.sequentialWindow));
	if (i > 0) keyPose_[i] = sequentialPose(i, w);
	const uint32_t K = uint32_t(std::max(1, m.overlapRunGap));
	const auto& passes = passes_.next(i, keyPose_, w, K, [&](uint32_t j) {
		return std::hypot(keyPose_[i].x - keyPose_[j].x, keyPose_[i].y - keyPose_[j].y) <
			   std::max(loopClosure_.windowOf(j, i).translation, m.overlapDistance);
	});
	std::vector<EdgeKey> fresh, loops;
	for (size_t k = 0; k < passes.size(); ++k)
	{
		if (segs_[i].empty()) break;
		if (!PassFinder::registeredPass(k, passes.size())) continue;  // as the batch's, the work per keyframe bounded
		const auto& p = passes[k];
		const auto link = loopClosure_.linked(p.lo > K ? p.lo - K : 0, p.hi + K, i > K ? i - K : 0, i, fresh);
		const double dist = std::hypot(keyPose_[i].x - keyPose_[p.nearest].x, keyPose_[i].y - keyPose_[p.nearest].y);
		if (link != LoopClosure::Link::None)
		{
			if (dist >= m.overlapDistance || book_.hasEdgeNear(i, p.lo, p.hi)) continue;
			for (uint32_t from : overlaps_.partners(i, p.nearest, p.members, segs_, keyPose_))
			{
				const EdgeKey key{from, i};
				const TPose2D rel = keyPose_[i] - keyPose_[from];
				Constraint c;
				if (overlaps_.registerOverlap(key, from == p.nearest, segs_, rel, c, rep_) && !aliased(from, i, c))
				{
					book_.keep(key, std::move(c), rep_);
					fresh.push_back(key);
					break;
				}
				book_.fail(key, rel);
			}
			continue;
		}
		if (!m.loopSearch || dist >= loopClosure_.windowOf(p.nearest, i).translation) continue;
		const uint32_t j = p.nearest;
		const TPose2D rel = keyPose_[i] - keyPose_[j];
		++rep_.loopSearches, ++rep_.registrations;
		const MatchResult r = loopSearch_.search(segs_[j], segs_[i], rel, loopClosure_.windowOf(j, i));
		if (!r.ok())
		{
			++rep_.failedRegistrations;
			continue;
		}
		book_.edges[{j, i}] = book_.make({j, i}, EdgeKind::Loop, r, rel);
		++rep_.added;
		fresh.push_back({j, i});
		loops.push_back({j, i});
	}
	verifyOverlaps(book_, m, keyPose_, fresh, rep_);
	st.loops = size_t(std::count_if(loops.begin(), loops.end(), [&](const EdgeKey& k) { return book_.edges.count(k); }));
	for (auto it = book_.edges.lower_bound({i > w ? i - w : 0, 0}); it != book_.edges.end(); ++it)
		if (it->first.second == i) st.edges.push_back(it->first);  // the sequential ones
	for (const EdgeKey& k : fresh)
		if (k.first + w < i && book_.edges.count(k)) st.edges.push_back(k);
}

// The first M-step's chain (SequentialChain) for keyframe i: its sequential edges, nearest predecessor first, each
// registered from the pose fused so far and kept if it agrees with the odometry; the fused pose.
TPose2D OnlineEmSlam::sequentialPose(uint32_t i, uint32_t w)
{
	const TPose2D odo = keyOdo_[i] - keyOdo_[i - 1];
	PoseFusion fusion(keyPose_[i - 1] + odo,
					  PoseFusion::toWorld(PoseGraph::odometryInformation(odo, cfg_.posegraph), keyPose_[i - 1].phi));
	for (uint32_t j = i; j-- > (i > w ? i - w : 0);)
	{
		Constraint c;
		const TPose2D guess = fusion.pose() - keyPose_[j];
		if (reg_.registerPair(j, i, EdgeKind::Sequential, segs_, guess, c, rep_) &&
			agreesWithOdometry(keyOdo_[i] - keyOdo_[j], c.z, c.information, cfg_.posegraph))
		{
			fusion.add(keyPose_[j] + c.z, PoseFusion::toWorld(c.information, keyPose_[j].phi));
			book_.keep({j, i}, std::move(c), rep_);
		}
		else
			book_.fail({j, i}, guess);
	}
	return fusion.pose();
}

// An overlap edge is registered from the estimate, which can be off along a corridor by the loop-search window
// of its passes: an alias within that reach (AliasSweep) makes it no edge.
bool OnlineEmSlam::aliased(uint32_t from, uint32_t to, const Constraint& c) const
{
	return AliasSweep(reg_.matcher(), cfg_.mstep.loopSearchAmbiguity)
		.aliased(segs_[from], segs_[to], c.z, c.information, c.correspondences,
				 loopClosure_.windowOf(from, to).translation);
}

OnlineEmSlam::Optimisation OnlineEmSlam::takeOptimisation()
{
	due_ = false;
	return {keyPose_, keyOdo_, book_.edges, {}};
}

void OnlineEmSlam::runOptimisation(Optimisation& job)
{
	optimiser_.beginStep();
	optimiser_.optimise(job.poses, job.odometry, job.edges, job.report, true, job.graduate);
}

// Eq. 22's trajectory for the keyframes it had; a keyframe added since follows the last of them
// (x_k = x_n' (+) x_n^-1 (+) x_k); a trajectory that moved re-anchors the map.
void OnlineEmSlam::applyOptimisation(const Optimisation& job)
{
	const size_t n = std::min(job.poses.size(), keyPose_.size());
	if (n == 0) return;
	const TPose2D carry = job.poses[n - 1] + (TPose2D(0, 0, 0) - keyPose_[n - 1]);
	for (size_t k = n; k < keyPose_.size(); ++k) keyPose_[k] = carry + keyPose_[k];
	std::copy(job.poses.begin(), job.poses.begin() + long(n), keyPose_.begin());
	lastPose_ = carry + lastPose_;
	for (const auto& [key, c] : job.edges)
		if (auto it = book_.edges.find(key); it != book_.edges.end()) it->second.rejected = c.rejected;
	rep_.optimisation = job.report.optimisation;
	if (!next_ && EmSlam::movedEnough(liveAt_, keyPose_)) next_ = std::make_unique<ClassifiedMap>(cfg_), nextAt_.clear();
}

void OnlineEmSlam::optimise(bool graduate)
{
	Optimisation job = takeOptimisation();
	job.graduate = graduate;
	runOptimisation(job);
	applyOptimisation(job);
}

bool OnlineEmSlam::farFromEstimate(const std::vector<EdgeKey>& keys) const
{
	return gridvector::farFromEstimate(book_.edges, keyPose_, keys, cfg_);
}

size_t OnlineEmSlam::reanchor(size_t n)
{
	if (!next_) return 0;
	size_t k = 0;
	for (; k < n && nextAt_.size() < keyPose_.size(); ++k)
	{
		const size_t i = nextAt_.size();
		next_->insert(keyPose_[i], keyScans_[i]);
		nextAt_.push_back(keyPose_[i]);
	}
	if (nextAt_.size() < keyPose_.size()) return k;
	live_ = std::move(next_);
	liveAt_ = std::move(nextAt_);
	nextAt_.clear();
	if (EmSlam::movedEnough(liveAt_, keyPose_)) next_ = std::make_unique<ClassifiedMap>(cfg_);  // moved meanwhile
	return k;
}

// The end of the run, once: Eq. 22, then the batch M-step's edge search over the whole trajectory at
// its estimate (Sec. 4.3's overlap edges, the loop search, their consistency) and Eq. 22 again, for the
// pairs that a keyframe's search did not reach as it came in (the estimate was off then).
void OnlineEmSlam::finish()
{
	if (keyPose_.size() < 2) return;
	optimise();
	for (int round = 0; round < kClosingRounds; ++round)
	{
		book_.beginStep(segs_, nullptr);
		auto fresh = overlaps_.add(segs_, keyPose_, rep_);
		const bool deferred = loopClosure_.closeLoops(segs_, keyPose_, fresh, rep_);
		if (fresh.empty() && !deferred) break;
		optimise(farFromEstimate(fresh));
	}
	while (next_) reanchor(std::numeric_limits<size_t>::max());
}

MStepReport OnlineEmSlam::report() const
{
	MStepReport r = rep_;
	summarise(book_, 0, r);
	return r;
}

TPose2D OnlineEmSlam::currentPose() const { return lastPose_; }

std::vector<TPose2D> OnlineEmSlam::trajectory() const
{
	if (keyScan_.empty()) return {};
	std::vector<TPose2D> out = EmSlam::expand(keyPose_, keyScan_, odometry_);
	const size_t last = keyScan_.back();  // scans after the last keyframe follow its odometry
	for (size_t t = last + 1; t < odometry_.size(); ++t) out[t] = keyPose_.back() + (odometry_[t] - odometry_[last]);
	return out;
}

namespace
{
// Sec. 4.1 and Eq. 4 as the batch's final map from E-step children, then Sec. 5.4 as the batch's
// (EmSlam::doorStates: leaf states dynamic, walls cut across them).
std::vector<GridVector> mapOf(const std::vector<GridVector>& children, const GridVectorConfig& cfg,
							  std::vector<Door>* doorsOut)
{
	const EStep estep(cfg.estep, cfg.grid);
	std::vector<GridVector> out = SplitMap::of(children, estep, cfg).vectors;
	for (size_t k = 0; k < out.size(); ++k) out[k].id = k + 1;  // unique across both maps
	std::vector<Door> doors = EmSlam::doorStates(out, estep, cfg.doors);
	if (doorsOut) *doorsOut = std::move(doors);
	return out;
}
}  // namespace

std::vector<GridVector> OnlineEmSlam::vectors(std::vector<Door>* doors) const { return mapOf(live_->children(), cfg_, doors); }

std::vector<GridVector> OnlineEmSlam::finalMap(std::vector<Door>* doors) const
{
	if (keyScans_.empty())
	{
		if (doors) doors->clear();
		return {};
	}
	const auto same = [](const TPose2D& a, const TPose2D& b) { return a.x == b.x && a.y == b.y && a.phi == b.phi; };
	if (!next_ && std::equal(liveAt_.begin(), liveAt_.end(), keyPose_.begin(), keyPose_.end(), same))
		return vectors(doors);
	const EStep estep(cfg_.estep, cfg_.grid);
	return mapOf(estep.run(GlobalMap::buildPerScan(keyPose_, keyScans_, cfg_)).children, cfg_, doors);
}

std::vector<GridVector> OnlineEmSlam::staticMap() const
{
	std::vector<GridVector> out = vectors();
	out.erase(std::remove_if(out.begin(), out.end(), [](const GridVector& v) { return v.state != VectorState::Static; }),
			  out.end());
	return out;
}

std::vector<GridVector> OnlineEmSlam::dynamicVectors() const
{
	std::vector<GridVector> out = vectors();
	out.erase(std::remove_if(out.begin(), out.end(), [](const GridVector& v) { return v.state != VectorState::Dynamic; }),
			  out.end());
	return out;
}

mrpt::maps::COccupancyGridMap2D OnlineEmSlam::occupancyGrid() const
{
	return OccupancyConversion::toOccupancyGrid(vectors(), cfg_.occupancy, cfg_.grid);
}

}  // namespace gridvector::online
