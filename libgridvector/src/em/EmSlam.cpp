#include "doors/DoorDetector.h"
#include "doors/DoorExclusion.h"
#include "em/EmSlam.h"
#include <mrpt/math/TPose2D.h>

#include <cmath>

#include <chrono>
#include <algorithm>
#include <type_traits>
#include <stdexcept>

namespace gridvector
{
using mrpt::math::TPose2D;

namespace
{
double since(std::chrono::steady_clock::time_point t0)
{
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Before the first E-step every vector is its own single static child (Eq. 14 not yet applied).
std::vector<std::vector<MatchSegment>> initialSegments(const std::vector<LocalScan>& scans)
{
	std::vector<std::vector<MatchSegment>> out(scans.size());
	uint64_t id = 1;  // the id buildPerScan gives: position + 1
	for (size_t t = 0; t < scans.size(); ++t)
		for (const auto& v : scans[t].vectors)
		{
			MatchSegment m = MatchSegment::from(v, scans[t].rangeSigma);
			m.id = EStep::childId(id++, 0);
			out[t].push_back(m);
		}
	return out;
}

// m_{i,t} follows its pose: x_new (+) x_old^-1 (+) m.
void rebase(std::vector<GridVector>& vs, const std::vector<TPose2D>& from, const std::vector<TPose2D>& to)
{
	for (auto& v : vs)
	{
		if (v.scanIndex < 0 || size_t(v.scanIndex) >= from.size() || size_t(v.scanIndex) >= to.size()) continue;
		const TPose2D& a = from[size_t(v.scanIndex)];
		const TPose2D& b = to[size_t(v.scanIndex)];
		const TPose2D d = b + (TPose2D(0, 0, 0) - a);
		const auto id = v.id;
		const auto st = v.state;
		v = v.compose(d);
		v.id = id, v.state = st;
	}
}
}  // namespace

EmSlam::EmSlam(const GridVectorConfig& cfg) : cfg_(cfg) {}

// Beyond the paper: the E-step is re-run only when the M-step moved a pose by more than this:
// half a grid cell, a degree (below them the map, and so the E-step, barely changes).
constexpr double kRerunTranslation = 0.05;  // [m]
constexpr double kRerunRotationDeg = 1.0;  // [deg]

bool EmSlam::movedEnough(const std::vector<TPose2D>& a, const std::vector<TPose2D>& b)
{
	for (size_t t = 0; t < a.size() && t < b.size(); ++t)
		if (std::hypot(a[t].x - b[t].x, a[t].y - b[t].y) > kRerunTranslation ||
			std::abs(mrpt::math::wrapToPi(a[t].phi - b[t].phi)) > kRerunRotationDeg * M_PI / 180)
			return true;
	return a.size() != b.size();
}

// Eq. 19-20: the M-step registers the static vectors only; dynamic ones are outliers.
std::vector<std::vector<MatchSegment>> EmSlam::staticSegments(const std::vector<GridVector>& children,
															  const std::vector<TPose2D>& poses,
															  const std::vector<LocalScan>* scans)
{
	std::vector<std::vector<MatchSegment>> out(poses.size());
	for (const auto& c : children)
	{
		if (c.state != VectorState::Static || c.scanIndex < 0 || size_t(c.scanIndex) >= poses.size()) continue;
		const size_t t = size_t(c.scanIndex);
		const double sigma = scans && t < scans->size() ? (*scans)[t].rangeSigma : 0.0;
		out[t].push_back(MatchSegment::from(c.compose(TPose2D(0, 0, 0) - poses[t]), sigma));  // back to the scan's frame
	}
	return out;
}

// Beyond the paper (Sec. 4 runs over every scan): the scans EM works on.
std::vector<size_t> EmSlam::keyframes(const std::vector<TPose2D>& odometry, const MStepOptions& o)
{
	std::vector<size_t> k;
	for (size_t t = 0; t < odometry.size(); ++t)
		if (k.empty() || t + 1 == odometry.size() || isKeyframe(odometry[k.back()], odometry[t], o)) k.push_back(t);
	return k;
}

bool EmSlam::isKeyframe(const TPose2D& lastKeyOdometry, const TPose2D& odometry, const MStepOptions& o)
{
	return std::hypot(lastKeyOdometry.x - odometry.x, lastKeyOdometry.y - odometry.y) >= o.keyframeDistance ||
		   std::abs(mrpt::math::wrapToPi(odometry.phi - lastKeyOdometry.phi)) >= o.keyframeRotationDeg * M_PI / 180;
}

// EM on the keyframes; every other scan is placed by the odometry from the
// keyframes before and after it, the two predictions blended by time.
EmResult EmSlam::run(const std::vector<LocalScan>& scans, const std::vector<TPose2D>& odometry,
					 const IterationCallback& onIteration, const ProgressCallback& progress) const
{
	return run(scans, odometry, odometry, onIteration, progress);
}

EmResult EmSlam::run(const std::vector<LocalScan>& scans, const std::vector<TPose2D>& odometry,
					 const std::vector<TPose2D>& initial, const IterationCallback& onIteration,
					 const ProgressCallback& progress) const
{
	return runOn(scans, odometry, initial, onIteration, progress);
}

EmResult EmSlam::run(std::vector<LocalScan>&& scans, const std::vector<TPose2D>& odometry,
					 const std::vector<TPose2D>& initial, const IterationCallback& onIteration,
					 const ProgressCallback& progress) const
{
	return runOn(std::move(scans), odometry, initial, onIteration, progress);
}

template <class Scans>
EmResult EmSlam::runOn(Scans&& scans, const std::vector<TPose2D>& odometry, const std::vector<TPose2D>& initial,
					   const IterationCallback& onIteration, const ProgressCallback& progress) const
{
	if (scans.size() != odometry.size()) throw std::invalid_argument("EmSlam: scans and odometry differ in length");
	if (initial.size() != odometry.size())
		throw std::invalid_argument("EmSlam: initial trajectory and odometry differ in length");
	const auto key = keyframes(odometry, cfg_.mstep);
	std::vector<LocalScan> ks;
	std::vector<TPose2D> ko, ki;
	for (size_t k = 0; k < key.size(); ++k)
	{
		if constexpr (std::is_lvalue_reference_v<Scans>)
			ks.push_back(scans[key[k]]);
		else
			ks.push_back(std::move(scans[key[k]]));  // the caller gave them up
		ks.back().scanIndex = int64_t(k);
		ko.push_back(odometry[key[k]]);
		ki.push_back(initial[key[k]]);
	}
	EmResult res = runKeyframes(
		ks, ko, ki,
		[&](const EmIteration& it, const std::vector<TPose2D>& kp) {
			if (onIteration) onIteration(it, expand(kp, key, odometry));
		},
		progress, key);
	res.poses = expand(res.poses, key, odometry);
	for (auto& v : res.perScan)
		if (v.scanIndex >= 0) v.scanIndex = int64_t(key[size_t(v.scanIndex)]);
	res.keyframes = key.size();
	return res;
}

// Beyond the paper: a scan between two keyframes from the odometry of both, blended by time.
std::vector<TPose2D> EmSlam::expand(const std::vector<TPose2D>& kp, const std::vector<size_t>& key,
									const std::vector<TPose2D>& odometry)
{
	std::vector<TPose2D> out(odometry.size());
	for (size_t k = 0; k < key.size(); ++k)
	{
		out[key[k]] = kp[k];
		if (k + 1 == key.size()) break;
		const size_t a = key[k], b = key[k + 1];
		for (size_t t = a + 1; t < b; ++t)
		{
			const TPose2D pa = kp[k] + (odometry[t] - odometry[a]);
			const TPose2D pb = kp[k + 1] + (odometry[t] - odometry[b]);
			const double w = double(t - a) / double(b - a);
			out[t] = TPose2D(pa.x + w * (pb.x - pa.x), pa.y + w * (pb.y - pa.y),
							 mrpt::math::wrapToPi(pa.phi + w * mrpt::math::wrapToPi(pb.phi - pa.phi)));
		}
	}
	return out;
}

namespace
{
// An iteration whose E-step did not run (converged, or skipped) reports the last E-step's split.
void keepLastSplit(EmIteration& it, const EmIteration& last)
{
	it.staticVectors = last.staticVectors, it.dynamicVectors = last.dynamicVectors;
	it.staticLength = last.staticLength, it.dynamicLength = last.dynamicLength;
	it.doors = last.doors;  // Sec. 5.3: the doors and exclusion of that E-step stand
	it.doors.seconds = 0;
}

// Sec. 4.1: the E-step (Eq. 14-15) on the map of the trajectory (Eq. 4 unmerged, Eq. 8), its
// figures in `it` and its parents' changed M_chd (Eq. 25) against `previous` (null: first E-step),
// per scan the ids of the static children of those parents in `changedIds` (for the next M-step).
EStepResult expectation(const EStep& estep, const std::vector<LocalScan>& scans, const std::vector<TPose2D>& poses,
						const GridVectorConfig& cfg, const EStepResult* previous, EmIteration& it,
						std::chrono::steady_clock::time_point t0, std::vector<std::vector<uint64_t>>& changedIds)
{
	const auto perScan = GlobalMap::buildPerScan(poses, scans, cfg);
	it.wipeSeconds = since(t0);
	const auto tc = std::chrono::steady_clock::now();
	EStepResult e = estep.run(perScan);
	it.classifySeconds = since(tc);
	const auto changed = EStep::changedChildren(e, previous);
	it.changedVectors = size_t(std::count(changed.begin(), changed.end(), true));
	changedIds.assign(poses.size(), {});
	for (size_t k = 0; k < changed.size(); ++k)
		for (uint32_t c = 0; changed[k] && c < e.childrenOf[k].size(); ++c)
		{
			const GridVector& v = e.children[e.childrenOf[k][c]];
			if (v.state == VectorState::Static && v.scanIndex >= 0 && size_t(v.scanIndex) < poses.size())
				changedIds[size_t(v.scanIndex)].push_back(v.id);
		}
	it.staticVectors = e.staticCount;
	it.dynamicVectors = e.dynamicCount;
	it.staticLength = e.staticLength;
	it.dynamicLength = e.dynamicLength;
	return e;
}

// Final map: the last E-step's children at the converged trajectory, split by Eq. 14 once more,
// static and dynamic merged separately (Eq. 4, Algorithm 2); then finalVectors, ids unique
// across both maps.
void finalMap(EmResult& res, const EStep& estep, const std::vector<TPose2D>& ePoses, const GridVectorConfig& cfg)
{
	const auto t0 = std::chrono::steady_clock::now();
	rebase(res.perScan, ePoses, res.poses);
	SplitMap m = SplitMap::of(std::move(res.perScan), estep, cfg);  // Eq. 14 on the converged map, Eq. 4 per state
	res.perScan = std::move(m.perScan);
	res.staticMap = std::move(m.staticMap);
	res.dynamicMap = std::move(m.dynamicMap);
	res.finalMergeSeconds = since(t0);
	res.finalVectors = std::move(m.vectors);  // static then dynamic, their states set
	for (size_t k = 0; k < res.finalVectors.size(); ++k) res.finalVectors[k].id = k + 1;  // unique across both maps
}

}  // namespace

// Sec. 4: M-step (Eq. 16-25) and E-step (Eq. 14-15) alternated until an M-step changes no
// constraint after an E-step that changed no vector's children (Fig. 11), then the final map.
EmResult EmSlam::runKeyframes(const std::vector<LocalScan>& scans, const std::vector<TPose2D>& odometry,
							  const std::vector<TPose2D>& initial, const IterationCallback& onIteration,
							  const ProgressCallback& progress, const std::vector<size_t>& key) const
{
	EmResult res;
	MStep mstep(cfg_);
	mstep.setOdometry(odometry);
	if (initial != odometry) mstep.startFromPoses();
	const EStep estep(cfg_.estep, cfg_.grid);
	DoorExclusion doorExclusion(cfg_, estep);  // Sec. 5.3 (doors.during_em)
	auto segs = initialSegments(scans);
	mstep.setAllVectors(segs);  // the loop search's fallback (mstep.loop_search_all_vectors)
	EStepResult prevE;
	std::vector<std::vector<uint64_t>> changedIds;  // Eq. 25: per scan, vectors whose children changed
	std::vector<TPose2D> ePoses;  // trajectory of the last E-step
	res.poses = initial;
	int current = 0;
	if (progress) mstep.setProgress([&](const char* stage, double f) { progress(stage, current, f); });
	for (int k = 1; k <= cfg_.mstep.maxIterations; ++k)
	{
		current = k;
		EmIteration it;
		it.index = k;
		auto t0 = std::chrono::steady_clock::now();
		it.mstep = mstep.run(segs, res.poses, changedIds.empty() ? nullptr : &changedIds);  // M-step (Eq. 16-25)
		changedIds.clear();  // consumed: an M-step after a skipped E-step sees no change
		if (observer_) observer_(k, mstep, segs, key);
		it.mSeconds = since(t0);
		it.changedShare = it.mstep.changedShare;
		// No constraint changed after an E-step that changed no vector: the trajectory did not
		// move, so the E-step would repeat itself (converged). A trajectory that moved too little
		// since the last E-step has that E-step's map: nothing to re-evaluate (skipped).
		const bool converged = k > 1 && it.changedShare <= cfg_.mstep.minChangedShare && !res.iterations.empty() &&
							   res.iterations.back().changedVectors == 0;
		t0 = std::chrono::steady_clock::now();
		if (converged || (k > 1 && !movedEnough(ePoses, res.poses)))
		{
			keepLastSplit(it, res.iterations.back());
			it.eSkipped = !converged;
			res.iterations.push_back(it);
			if (onIteration) onIteration(it, res.poses);
			if (!converged) continue;
			res.converged = true;
			break;
		}
		ePoses = res.poses;
		if (progress) progress("E-step", k, 0.0);
		EStepResult e = expectation(estep, scans, res.poses, cfg_, k > 1 ? &prevE : nullptr, it, t0, changedIds);
		if (cfg_.doors.duringEm)
		{
			if (progress) progress("doors", k, 0.0);
			segs = staticSegments(doorExclusion.apply(e.children, changedIds, it.doors), res.poses, &scans);
		}
		else
			segs = staticSegments(e.children, res.poses, &scans);
		it.eSeconds = since(t0);
		prevE = std::move(e);  // its children become res.perScan after the loop (one copy of the map, not two)
		res.iterations.push_back(it);
		if (onIteration) onIteration(it, res.poses);
	}
	res.perScan = std::move(prevE.children);  // the last E-step's children
	res.finalGraph = poseGraphFit(mstep.graph());
	const auto t0 = std::chrono::steady_clock::now();
	finalMap(res, estep, ePoses, cfg_);
	const auto td = std::chrono::steady_clock::now();
	res.doors = doorStates(res.finalVectors, estep, cfg_.doors);
	res.doorSeconds = since(td);
	res.finalMapSeconds = since(t0);
	return res;
}

// Sec. 5.4: doors in the final map; a leaf state Eq. 6 kept static is a door state, so dynamic,
// and so is the stretch of a static wall that runs across a state (merged over the doorway):
// the wall is cut there (EStep::splitSpans) and keeps its index for its first piece.
std::vector<Door> EmSlam::doorStates(std::vector<GridVector>& vectors, const EStep& estep, const DoorOptions& opts)
{
	const DoorDetector doorDetector(opts);
	std::vector<Door> doors = doorDetector.detect(vectors);
	for (const Door& d : doors)
		for (size_t leaf : d.leaves) vectors[leaf].state = VectorState::Dynamic;
	for (size_t i = 0, n = vectors.size(); i < n; ++i)
	{
		if (vectors[i].state != VectorState::Static) continue;
		const auto spans = doorDetector.stateSpans(doors, vectors[i]);
		if (spans.empty()) continue;
		auto parts = estep.splitSpans(vectors[i], spans);
		vectors[i] = std::move(parts[0]);
		for (size_t k = 1; k < parts.size(); ++k)
		{
			parts[k].id = vectors.size() + 1;
			vectors.push_back(std::move(parts[k]));
		}
	}
	return doors;
}

}  // namespace gridvector
