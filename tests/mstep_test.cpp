// MStep (Sec. 4.2-4.3, Eq. 16-25): drift removal, loop closure, constraint selection.
#include "em_world.h"

#include <gridvector/EStep.h>
#include <gridvector/MStep.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace gridvector;
using emtest::TPose2D;

namespace
{
struct Fixture
{
	std::vector<TPose2D> truth, odo;
	std::vector<std::vector<MatchSegment>> scans;
};

Fixture ring(int laps = 2)
{
	Fixture f;
	f.truth = emtest::ringPath(laps, 0.5);
	f.odo = emtest::odometryOf(f.truth, 7);
	const auto walls = emtest::corridorWorld();
	uint64_t id = 1;
	for (size_t t = 0; t < f.truth.size(); ++t)
	{
		auto segs = MatchSegment::fromVectors(emtest::observe(walls, f.truth[t], 6.0, unsigned(t)).vectors);
		for (auto& s : segs) s.id = EStep::childId(id++, 0);
		f.scans.push_back(segs);
	}
	return f;
}
}  // namespace

TEST(MStep, FirstStepChainsAndClosesTheLoop)
{
	Fixture f = ring();
	EXPECT_GT(emtest::ate(f.odo, f.truth), 1.0);  // the odometry has drifted
	MStep m;
	m.setOdometry(f.odo);
	std::vector<TPose2D> poses;
	const MStepReport r = m.run(f.scans, poses);
	ASSERT_EQ(poses.size(), f.truth.size());
	EXPECT_LT(emtest::ate(poses, f.truth), 0.05);
	EXPECT_GT(r.sequential, f.truth.size());  // several predecessors per scan
	EXPECT_GT(r.overlap, 20u);  // the second lap overlaps the first
	EXPECT_EQ(r.changedShare, 1.0);
	// overlap edges join poses of different laps
	const size_t lap = f.truth.size() / 2;
	size_t crossLap = 0;
	for (const auto& [k, c] : m.constraints())
		if (c.kind == EdgeKind::Overlap && c.to >= lap && c.from < lap) ++crossLap;
	EXPECT_GT(crossLap, 10u);
}

TEST(MStep, UnchangedInputChangesNoConstraint)
{
	Fixture f = ring();
	MStep m;
	m.setOdometry(f.odo);
	std::vector<TPose2D> poses;
	m.run(f.scans, poses);
	m.run(f.scans, poses);  // settles newly visible overlaps
	auto before = poses;
	MStepReport r = m.run(f.scans, poses);
	EXPECT_EQ(r.added + r.removed + r.recomputed, 0u);
	EXPECT_EQ(r.changedShare, 0.0);
	EXPECT_EQ(r.registrations, r.loopSearches);  // Eq. 24: nothing to recompute
	EXPECT_LT(emtest::ate(poses, before), 1e-9);  // and nothing to optimise
	// loop searches are retried only where the poses moved since the last try
	before = poses;
	r = m.run(f.scans, poses);
	EXPECT_EQ(r.registrations, 0u);
	EXPECT_EQ(r.changedShare, 0.0);
	EXPECT_LT(emtest::ate(poses, before), 1e-9);
}

TEST(MStep, StateChangeRecomputesOnlyAffectedEdges)
{
	Fixture f = ring();
	MStep m;
	m.setOdometry(f.odo);
	std::vector<TPose2D> poses;
	m.run(f.scans, poses);
	m.run(f.scans, poses);
	const size_t total = m.constraints().size();
	// an E-step turns the longest vector of scan 30 dynamic: it leaves the static set
	auto& s = f.scans[30];
	const auto longest = std::max_element(s.begin(), s.end(), [](auto& a, auto& b) { return a.length < b.length; });
	const uint64_t gone = longest->id;
	s.erase(longest);
	size_t touching = 0;
	for (const auto& [k, c] : m.constraints())
		touching += std::any_of(c.correspondences.begin(), c.correspondences.end(),
								[&](const VectorPair& p) { return p.a == gone || p.b == gone; });
	const MStepReport r = m.run(f.scans, poses);
	EXPECT_GT(touching, 0u);
	EXPECT_LE(r.registrations, touching + 2 * size_t(MStepOptions{}.sequentialWindow) + 2);
	EXPECT_GT(r.registrations, 0u);
	EXPECT_LT(double(r.registrations), 0.05 * total);
	for (const auto& [k, c] : m.constraints())
		for (const auto& p : c.correspondences) EXPECT_TRUE(p.a != gone && p.b != gone);
	EXPECT_LT(emtest::ate(poses, f.truth), 0.05);
}

TEST(MStep, RejectsMismatchedInput)
{
	MStep m;
	m.setOdometry({TPose2D(0, 0, 0)});
	std::vector<TPose2D> poses;
	EXPECT_THROW(m.run({{}, {}}, poses), std::invalid_argument);
}

// An aliased scan's wrong edges are rejected while the trajectory stays accurate; with
// mstep.reconsider_rejected (rejections re-decided at every M-step against the current
// estimate) every edge still rejected after the steps disagrees with the final estimate.
TEST(MStep, EveryRejectedEdgeDisagreesWithTheFinalEstimate)
{
	Fixture f = ring();
	// scan 60 sees the walls of scan 20's place: its registrations against the second
	// lap's neighbours are wrong (an aliasing the odometry contradicts)
	const size_t bad = 60, source = 20;
	ASSERT_LT(source + 10, bad);
	f.scans[bad] = f.scans[source];
	for (auto& s : f.scans[bad]) s.id += 1000000;
	GridVectorConfig cfg;
	ASSERT_TRUE(cfg.mstep.reconsiderRejected);
	MStep m(cfg);
	m.setOdometry(f.odo);
	std::vector<TPose2D> poses;
	for (int k = 0; k < 4; ++k) m.run(f.scans, poses);
	size_t rejected = 0;
	for (const auto& [k, c] : m.constraints())
	{
		const Eigen::Vector3d e = PoseGraph::error(poses[c.from], poses[c.to], c.z);
		const double chi2 = e.dot(c.information * e);
		if (c.rejected)
		{
			++rejected;
			EXPECT_GT(chi2, cfg.posegraph.rejectChi2) << c.from << "-" << c.to;
		}
	}
	EXPECT_GT(rejected, 0u);
	EXPECT_LT(emtest::ate(poses, f.truth), 0.05);
}

// mstep.reconsider_limit (Eq. 24-25 for rejections): a pair the chi2 test rejected that
// many times with the same correspondences stays out, so the edges of an aliased scan do
// not flip in and out at every M-step while other edges change (the E-step re-deciding
// some vector elsewhere); without the limit they are retried and rejected every time.
TEST(MStep, ARejectionRepeatedWithTheSameCorrespondencesStands)
{
	auto rejectedPerStep = [](int limit) {
		Fixture f = ring();
		f.scans[60] = f.scans[20];  // aliased: scan 60 sees scan 20's place
		for (auto& s : f.scans[60]) s.id += 1000000;
		GridVectorConfig cfg;
		cfg.mstep.reconsiderLimit = limit;
		MStep m(cfg);
		m.setOdometry(f.odo);
		std::vector<TPose2D> poses;
		auto& toggled = f.scans[5];  // one vector of scan 5 leaves and rejoins the static set
		const MatchSegment longest =
			*std::max_element(toggled.begin(), toggled.end(), [](auto& a, auto& b) { return a.length < b.length; });
		std::vector<size_t> rejected;
		for (int k = 0; k < 9; ++k)
		{
			if (k > 0 && k % 2 == 1)
				toggled.erase(std::find_if(toggled.begin(), toggled.end(), [&](auto& s) { return s.id == longest.id; }));
			else if (k > 0)
				toggled.push_back(longest);
			const MStepReport r = m.run(f.scans, poses);
			EXPECT_GT(r.added + r.removed + r.recomputed, 0u) << k;  // the optimiser ran
			rejected.push_back(r.optimisation.rejected);
		}
		EXPECT_LT(emtest::ate(poses, f.truth), 0.05) << limit;
		size_t stillRejected = 0;
		for (const auto& [key, c] : m.constraints()) stillRejected += c.rejected;
		EXPECT_GT(stillRejected, 0u) << limit;  // the aliased scan's wrong edges stay out either way
		return rejected;
	};
	const auto limited = rejectedPerStep(2), unlimited = rejectedPerStep(0);
	ASSERT_GT(limited[0], 0u);
	// with the limit: after two counted rejections (those of the first
	// reconsider_free_steps M-steps do not count) the aliased edges are no longer retried
	const size_t settled = size_t(GridVectorConfig{}.mstep.reconsiderFreeSteps) + 2;
	ASSERT_LT(settled + 2, limited.size());
	for (size_t k = 0; k < settled; ++k) EXPECT_GT(limited[k], 0u) << k;
	for (size_t k = settled; k < limited.size(); ++k) EXPECT_EQ(limited[k], 0u) << k;
	// without: they are re-tried and rejected again at every M-step
	for (size_t k = 0; k < unlimited.size(); ++k) EXPECT_GT(unlimited[k], 0u) << k;
}

namespace
{
// What a 180 deg scanner sees: the vectors ahead of the robot (midpoint in front).
std::vector<MatchSegment> ahead(std::vector<MatchSegment> segs)
{
	segs.erase(std::remove_if(segs.begin(), segs.end(), [](const MatchSegment& s) { return s.s.x() + s.e.x() <= 0; }),
			   segs.end());
	return segs;
}
}  // namespace

// mstep.pass_heading_weight: on its first lap the robot turns round at (8, 1) and back;
// on the second it passes there facing +x. The pose of the first pass nearest in
// position faces away (a forward scanner shares little with it); with the heading
// weight the overlap edge comes from a pose of that pass facing the same way.
TEST(MStep, OverlapEdgeComesFromAPoseFacingTheSameWay)
{
	auto truth = emtest::ringPath(2, 0.5);
	const size_t lap = truth.size() / 2;
	size_t turn = 0;  // the first lap's pose at (8, 1)
	while (std::hypot(truth[turn].x - 8, truth[turn].y - 1) > 1e-9) ++turn;
	truth[turn].phi = M_PI / 2;  // turned round: (8, 1, 90 deg), (8, 1, 180 deg), (8, 1, -90 deg)
	truth.insert(truth.begin() + long(turn) + 1, {TPose2D(8, 1, M_PI), TPose2D(8, 1, -M_PI / 2)});
	size_t second = lap + 2;  // the second lap's pose at (8, 1), facing +x
	while (std::hypot(truth[second].x - 8, truth[second].y - 1) > 1e-9) ++second;
	const auto odo = emtest::odometryOf(truth, 3, 0.5);
	const auto walls = emtest::corridorWorld();
	std::vector<std::vector<MatchSegment>> scans;
	uint64_t id = 1;
	for (size_t t = 0; t < truth.size(); ++t)
	{
		auto segs = ahead(MatchSegment::fromVectors(emtest::observe(walls, truth[t], 6.0, unsigned(t)).vectors));
		for (auto& s : segs) s.id = EStep::childId(id++, 0);
		scans.push_back(segs);
	}
	auto facingEdge = [&](double weight) {
		GridVectorConfig cfg;
		cfg.mstep.passHeadingWeight = weight;
		cfg.mstep.loopSearch = false;  // the overlap search alone
		MStep m(cfg);
		m.setOdometry(odo);
		std::vector<TPose2D> poses;
		m.run(scans, poses);
		bool facing = false;
		for (const auto& [key, c] : m.constraints())
			if (c.to == second && c.kind == EdgeKind::Overlap && c.from >= turn - 10 && c.from <= turn + 12)
				facing = facing || std::abs(mrpt::math::wrapToPi(truth[c.from].phi - truth[second].phi)) < M_PI / 4;
		return facing;
	};
	EXPECT_TRUE(facingEdge(MStepOptions{}.passHeadingWeight));
	EXPECT_FALSE(facingEdge(0.0));
}
