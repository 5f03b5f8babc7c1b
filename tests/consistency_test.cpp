// Consistency (verifyOverlaps): the pairwise check of an M-step's new overlap and loop edges.
#include "mstep/Consistency.h"
#include <mrpt/math/TPose2D.h>

#include <gtest/gtest.h>

using namespace gridvector;
using mrpt::math::TPose2D;

namespace
{
// 50 poses 0.5 m apart along x, the second half back along y = 1 (a second pass through the same places).
Poses trajectory()
{
	Poses p;
	for (int k = 0; k < 25; ++k) p.emplace_back(0.5 * k, 0, 0);
	for (int k = 0; k < 25; ++k) p.emplace_back(12 - 0.5 * k, 1, M_PI);
	return p;
}

Constraint edgeOf(const Poses& poses, uint32_t from, uint32_t to, double errorX = 0, size_t pairs = 6)
{
	Constraint c;
	c.from = from;
	c.to = to;
	c.kind = EdgeKind::Overlap;
	c.z = poses[to] - poses[from];
	c.z.x += errorX;
	c.information = Eigen::Vector3d(400, 400, 4000).asDiagonal();
	for (size_t k = 0; k < pairs; ++k) c.correspondences.push_back({k, 100 + k});
	c.matchedShare = 0.6;
	c.degeneracy = 0.5;
	return c;
}

struct World
{
	Poses poses = trajectory();
	ConstraintSet book{MatcherOptions{}};
	MStepOptions opts;
	MStepReport rep;
	World()
	{
		book.beginStep(Scans(poses.size()), nullptr);
		for (uint32_t j : {10u, 11u, 13u}) book.edges[{j, 48 - j}] = edgeOf(poses, j, 48 - j);  // agreeing edges
	}
	void add(const Constraint& c)
	{
		book.edges[{c.from, c.to}] = c;
		++rep.added;
	}
};
}  // namespace

TEST(Consistency, AnEdgeTheEdgesNearItAgreeWithIsKept)
{
	World w;
	w.add(edgeOf(w.poses, 12, 36));
	const Support s = supportOf(w.book.edges.at({12, 36}), w.book.edges, w.poses, w.opts);
	EXPECT_EQ(s.support, 3);
	EXPECT_EQ(s.against, 0);
	verifyOverlaps(w.book, w.opts, w.poses, {{12, 36}}, w.rep);
	EXPECT_EQ(w.rep.unverified, 0u);
	EXPECT_EQ(w.book.edges.count({12, 36}), 1u);
}

TEST(Consistency, AnEdgeTheEdgesNearItContradictIsDroppedAndFailed)
{
	World w;
	w.add(edgeOf(w.poses, 12, 36, 1.0));  // 1 m off along the passes: an alias
	EXPECT_EQ(supportOf(w.book.edges.at({12, 36}), w.book.edges, w.poses, w.opts).against, 3);
	verifyOverlaps(w.book, w.opts, w.poses, {{12, 36}}, w.rep);
	EXPECT_EQ(w.rep.unverified, 1u);
	EXPECT_EQ(w.rep.added, 0u);
	EXPECT_EQ(w.book.edges.count({12, 36}), 0u);
	EXPECT_FALSE(w.book.retry({12, 36}, w.poses[36] - w.poses[12]));  // not tried again as it is
}

TEST(Consistency, SequentialAndRejectedEdgesNeitherSupportNorContradict)
{
	World w;
	for (auto& [key, c] : w.book.edges) c.rejected = true;
	Constraint seq = edgeOf(w.poses, 11, 12, 1.0);
	seq.kind = EdgeKind::Sequential;
	w.book.edges[{11, 12}] = seq;
	const Support s = supportOf(edgeOf(w.poses, 12, 36), w.book.edges, w.poses, w.opts);
	EXPECT_EQ(s.support + s.against, 0);
}

TEST(Consistency, AnEdgeAloneIsKeptOnlyWhenStrong)
{
	World w;
	w.add(edgeOf(w.poses, 0, 49));  // nothing within overlap_run_gap of both ends
	w.add(edgeOf(w.poses, 24, 25, 0, 2));  // two correspondences: not strong
	EXPECT_TRUE(strong(w.book.edges.at({0, 49})));
	EXPECT_FALSE(strong(w.book.edges.at({24, 25})));
	verifyOverlaps(w.book, w.opts, w.poses, {{0, 49}, {24, 25}}, w.rep);
	EXPECT_EQ(w.book.edges.count({0, 49}), 1u);
	EXPECT_EQ(w.book.edges.count({24, 25}), 0u);
	EXPECT_EQ(w.rep.unverified, 1u);
}

TEST(Consistency, ADroppedLoopEdgeRestoresTheWeakEdgeItReplaced)
{
	World w;
	Constraint weak = edgeOf(w.poses, 12, 36);
	weak.degeneracy = 0.01;
	w.book.replaced[{12, 36}] = weak;
	Constraint loop = edgeOf(w.poses, 12, 36, 1.0);
	loop.kind = EdgeKind::Loop;
	w.book.edges[{12, 36}] = loop;
	w.rep.recomputed = 1;
	verifyOverlaps(w.book, w.opts, w.poses, {{12, 36}}, w.rep);
	EXPECT_EQ(w.rep.recomputed, 0u);
	ASSERT_EQ(w.book.edges.count({12, 36}), 1u);
	EXPECT_EQ(w.book.edges.at({12, 36}).kind, EdgeKind::Overlap);
	EXPECT_EQ(w.book.edges.at({12, 36}).degeneracy, 0.01);
	EXPECT_TRUE(w.book.replaced.empty());
}
