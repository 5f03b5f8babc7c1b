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
