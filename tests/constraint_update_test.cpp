// ConstraintUpdate (Sec. 4.3, Eq. 24-25): which stored edges an M-step keeps, drops and recomputes; Fig. 11's share.
#include "match_world.h"

#include "mstep/ConstraintUpdate.h"
#include <mrpt/math/TPose2D.h>

#include <gtest/gtest.h>

using namespace gridvector;
using mrpt::math::TPose2D;

namespace
{
const std::vector<matchtest::WorldSeg> kRoom{{0, 0, 6, 0}, {6, 0, 6, 2}, {6, 2, 4, 2}, {4, 2, 4, 5},
											 {4, 5, 0, 5}, {0, 5, 0, 0}, {1, 3, 2, 3}};

// Three poses: two in the room, 0.3 m apart, the third 20 m away (another room).
struct Room
{
	Poses poses{TPose2D(1, 1, 0), TPose2D(1.3, 1.1, 0.05), TPose2D(21, 1, 0)};
	Scans scans;
	GridVectorConfig cfg;
	ConstraintSet book{cfg.matcher};
	PairRegistration reg{cfg, book};
	Room()
	{
		for (size_t t = 0; t < poses.size(); ++t)
			scans.push_back(
				matchtest::observe(kRoom, t < 2 ? poses[t] : TPose2D(1, 1, 0), 0.002, unsigned(t), 1000 * (t + 1)));
		book.beginStep(scans, nullptr);
	}
	Constraint registered(uint32_t from, uint32_t to, EdgeKind kind)
	{
		Constraint c;
		MStepReport rep;
		EXPECT_TRUE(reg.registerPair(from, to, kind, scans, poses[to] - poses[from], c, rep));
		return c;
	}
};
}  // namespace

TEST(ConstraintUpdate, AnUnchangedEdgeIsKeptWithoutRegistration)
{
	Room r;
	r.book.edges[{0, 1}] = r.registered(0, 1, EdgeKind::Sequential);
	r.book.beginStep(r.scans, nullptr);
	MStepReport rep;
	updateConstraints(r.book, r.reg, r.cfg.mstep, r.scans, r.poses, rep);
	EXPECT_EQ(rep.registrations, 0u);
	EXPECT_EQ(rep.removed + rep.recomputed, 0u);
	EXPECT_EQ(r.book.edges.size(), 1u);
}

// Eq. 25, Fig. 5: an edge matching a vector whose children changed is registered again; with the same
// correspondences and pose it does not count as changed.
TEST(ConstraintUpdate, AnEdgeOfAVectorWhoseChildrenChangedIsRegisteredAgain)
{
	Room r;
	const Constraint c = r.registered(0, 1, EdgeKind::Sequential);
	ASSERT_FALSE(c.correspondences.empty());
	r.book.edges[{0, 1}] = c;
	const std::vector<std::vector<uint64_t>> changed{{c.correspondences.front().a}, {}, {}};
	r.book.beginStep(r.scans, &changed);
	MStepReport rep;
	updateConstraints(r.book, r.reg, r.cfg.mstep, r.scans, r.poses, rep);
	EXPECT_EQ(rep.registrations, 1u);
	EXPECT_EQ(rep.recomputed, 0u);
	ASSERT_EQ(r.book.edges.count({0, 1}), 1u);
	EXPECT_TRUE(r.book.sameScans(r.book.edges.at({0, 1})));
}

// Sec. 4.3: "if two nodes are far apart now, but there is an edge between them at the last step, the edge will
// be destroyed"; so is an overlap edge whose scans no longer share static vectors.
TEST(ConstraintUpdate, EdgesThatNoLongerOverlapAreDropped)
{
	Room r;
	Constraint far = r.registered(0, 1, EdgeKind::Overlap);
	far.from = 0, far.to = 2;
	r.book.edges[{0, 2}] = far;
	r.book.edges[{1, 2}] = far;
	r.book.edges.at({1, 2}).from = 1;
	r.book.edges[{0, 1}] = r.registered(0, 1, EdgeKind::Overlap);
	r.scans[1].clear();  // the E-step made all of scan 1 dynamic
	r.book.beginStep(r.scans, nullptr);
	MStepReport rep;
	updateConstraints(r.book, r.reg, r.cfg.mstep, r.scans, r.poses, rep);
	EXPECT_EQ(rep.removed, 3u);
	EXPECT_TRUE(r.book.edges.empty());
	EXPECT_EQ(rep.registrations, 0u);  // two too far apart, (0, 1) sharing no static length any more
}

// A sequential pair the E-step left too few static vectors to register keeps its last measurement: an E-step on a
// trajectory still off at its loops calls misaligned walls dynamic, and dropping the pair would leave its scans
// to the odometry (acapulco: EM went from 1.6 m to 39.8 m loop error that way).
TEST(ConstraintUpdate, ASequentialEdgeWhoseVectorsWentDynamicKeepsItsMeasurement)
{
	Room r;
	const Constraint c = r.registered(0, 1, EdgeKind::Sequential);
	r.book.edges[{0, 1}] = c;
	r.scans[1].clear();  // the E-step made all of scan 1 dynamic
	r.book.beginStep(r.scans, nullptr);
	MStepReport rep;
	updateConstraints(r.book, r.reg, r.cfg.mstep, r.scans, r.poses, rep);
	EXPECT_EQ(rep.registrations, 1u);
	EXPECT_EQ(rep.failedRegistrations, 1u);
	EXPECT_EQ(rep.removed + rep.recomputed, 0u);
	ASSERT_EQ(r.book.edges.count({0, 1}), 1u);
	const Constraint& kept = r.book.edges.at({0, 1});
	EXPECT_DOUBLE_EQ(kept.z.x, c.z.x);
	EXPECT_DOUBLE_EQ(kept.z.phi, c.z.phi);
	EXPECT_EQ(kept.correspondences, c.correspondences);
	// confirmed at the current scans: the next M-step with nothing changed does not try it again
	MStepReport again;
	updateConstraints(r.book, r.reg, r.cfg.mstep, r.scans, r.poses, again);
	EXPECT_EQ(again.registrations, 0u);
}

TEST(ConstraintUpdate, TheChangedShareOfFig11)
{
	ConstraintSet book{MatcherOptions{}};
	Constraint c;
	c.kind = EdgeKind::Sequential;
	book.edges[{0, 1}] = c;
	c.kind = EdgeKind::Overlap;
	book.edges[{0, 5}] = c;
	c.rejected = true;
	book.edges[{0, 6}] = c;
	c.kind = EdgeKind::Loop;
	c.rejected = false;
	book.edges[{0, 9}] = c;
	MStepReport rep;
	rep.added = 1, rep.recomputed = 1, rep.removed = 1;
	summarise(book, 5, rep);
	EXPECT_EQ(rep.constraints, 4u);
	EXPECT_EQ(rep.active, 3u);
	EXPECT_EQ(rep.sequential + rep.overlap + rep.loop, 3u);
	EXPECT_EQ(rep.overlap, 1u);
	EXPECT_DOUBLE_EQ(rep.changedShare, 3.0 / 5.0);  // of the larger of before and after
}
