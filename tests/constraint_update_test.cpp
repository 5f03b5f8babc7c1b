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
// be destroyed"; an edge whose vectors are gone fails its re-registration and goes too.
TEST(ConstraintUpdate, EdgesThatNoLongerOverlapAreDropped)
{
	Room r;
	Constraint far = r.registered(0, 1, EdgeKind::Overlap);
	far.from = 0, far.to = 2;
	r.book.edges[{0, 2}] = far;
	r.book.edges[{1, 2}] = far;
	r.book.edges.at({1, 2}).from = 1;
	r.book.edges[{0, 1}] = r.registered(0, 1, EdgeKind::Sequential);
	r.scans[1].clear();  // the E-step made all of scan 1 dynamic
	r.book.beginStep(r.scans, nullptr);
	MStepReport rep;
	updateConstraints(r.book, r.reg, r.cfg.mstep, r.scans, r.poses, rep);
	EXPECT_EQ(rep.removed, 3u);
	EXPECT_TRUE(r.book.edges.empty());
	EXPECT_EQ(rep.registrations, 1u);  // only the sequential edge was tried (the others are too far apart)
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
