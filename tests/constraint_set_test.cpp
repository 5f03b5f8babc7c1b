// ConstraintSet (Sec. 4.3, Eq. 24-25): the edges, the scans' signatures of their static children, failed pairs.
#include "mstep/ConstraintSet.h"

#include <gtest/gtest.h>

using namespace gridvector;
using mrpt::math::TPose2D;

namespace
{
MatchSegment seg(uint64_t id)
{
	MatchSegment m;
	m.s = {0, 0};
	m.e = {1, 0};
	m.length = 1;
	m.id = id;
	return m;
}

Scans threeScans() { return {{seg(1), seg(2)}, {seg(3)}, {seg(4), seg(5)}}; }

Constraint edge(ConstraintSet& book, uint32_t from, uint32_t to, std::vector<VectorPair> pairs)
{
	MatchResult r;
	r.status = MatchStatus::Ok;
	r.pairs = std::move(pairs);
	return book.make({from, to}, EdgeKind::Overlap, r, TPose2D(1, 0, 0));
}
}  // namespace

TEST(ConstraintSet, ASignatureChangesWithTheStaticChildren)
{
	ConstraintSet book{MatcherOptions{}};
	Scans scans = threeScans();
	book.beginStep(scans, nullptr);
	const Constraint c = edge(book, 0, 2, {{1, 4}});
	EXPECT_TRUE(book.sameScans(c));
	EXPECT_EQ(c.sigFrom, book.signatures()[0]);
	book.beginStep(scans, nullptr);  // the same children: the same signatures
	EXPECT_TRUE(book.sameScans(c));
	scans[2].pop_back();  // an E-step made vector 5 of scan 2 dynamic
	book.beginStep(scans, nullptr);
	EXPECT_FALSE(book.sameScans(c));
	// a child whose children M_chd changed under the same id (a moved split point) changes it too
	scans = threeScans();
	book.beginStep(scans, nullptr);
	Constraint d = edge(book, 0, 1, {{2, 3}});
	const std::vector<std::vector<uint64_t>> changed{{}, {3}, {}};
	book.beginStep(scans, &changed);
	EXPECT_FALSE(book.sameScans(d));
	EXPECT_TRUE(book.childrenChanged(d));
	book.confirm(d, TPose2D(1, 0, 0));  // checked again: re-stamped
	EXPECT_TRUE(book.sameScans(d));
}

// Eq. 25, Fig. 5: only the edges whose correspondences involve a changed vector are affected.
TEST(ConstraintSet, ChildrenChangedOnlyForTheEdgesOfTheChangedVector)
{
	ConstraintSet book{MatcherOptions{}};
	const Scans scans = threeScans();
	const std::vector<std::vector<uint64_t>> changed{{2}, {}, {}};
	book.beginStep(scans, &changed);
	EXPECT_TRUE(book.childrenChanged(edge(book, 0, 2, {{1, 4}, {2, 5}})));
	EXPECT_FALSE(book.childrenChanged(edge(book, 0, 2, {{1, 4}})));
	EXPECT_FALSE(book.childrenChanged(edge(book, 1, 2, {{3, 4}})));
}

TEST(ConstraintSet, AFailedPairIsRetriedOnlyWhenSomethingChanged)
{
	const MatcherOptions m;
	ConstraintSet book{m};
	Scans scans = threeScans();
	book.beginStep(scans, nullptr);
	const TPose2D rel(1, 0, 0);
	EXPECT_TRUE(book.retry({0, 1}, rel));  // never tried
	book.fail({0, 1}, rel);
	EXPECT_FALSE(book.retry({0, 1}, rel));
	const double step = kMovedGateShare * m.gateRhoFinal;
	EXPECT_FALSE(book.retry({0, 1}, TPose2D(1 + 0.9 * step, 0, 0)));
	EXPECT_TRUE(book.retry({0, 1}, TPose2D(1 + 1.1 * step, 0, 0)));
	EXPECT_TRUE(book.retry({0, 1}, TPose2D(1, 0, 1.1 * kMovedGateShare * m.gatePsiFinalDeg * M_PI / 180)));
	scans[1].push_back(seg(6));  // scan 1's static vectors changed
	book.beginStep(scans, nullptr);
	EXPECT_TRUE(book.retry({0, 1}, rel));
	// a kept edge is no longer failed
	MStepReport rep;
	book.fail({0, 2}, rel);
	book.keep({0, 2}, edge(book, 0, 2, {{1, 4}}), rep);
	EXPECT_EQ(rep.added, 1u);
	EXPECT_TRUE(book.retry({0, 2}, rel));
}

// OverlapEdges::partners measures a pair's overlap once per change, as a failed registration is retried.
TEST(ConstraintSet, AShortOverlapIsMeasuredAgainOnlyWhenSomethingChanged)
{
	const MatcherOptions m;
	ConstraintSet book{m};
	Scans scans = threeScans();
	book.beginStep(scans, nullptr);
	const TPose2D rel(1, 0, 0);
	EXPECT_FALSE(book.stillShort({0, 1}, rel));  // never measured
	book.shortOverlap({0, 1}, rel);
	EXPECT_TRUE(book.stillShort({0, 1}, rel));
	EXPECT_FALSE(book.stillShort({1, 0}, rel));  // another pair
	EXPECT_TRUE(book.retry({0, 1}, rel));  // a short overlap is no failed registration
	const double step = kMovedGateShare * m.gateRhoFinal;
	EXPECT_TRUE(book.stillShort({0, 1}, TPose2D(1 + 0.9 * step, 0, 0)));
	EXPECT_FALSE(book.stillShort({0, 1}, TPose2D(1 + 1.1 * step, 0, 0)));
	scans[0].push_back(seg(6));  // scan 0's static vectors changed
	book.beginStep(scans, nullptr);
	EXPECT_FALSE(book.stillShort({0, 1}, rel));
}

TEST(ConstraintSet, HasEdgeNearLooksAtTheEdgesIntoThePose)
{
	ConstraintSet book{MatcherOptions{}};
	book.beginStep(Scans(20), nullptr);
	book.edges[{5, 15}] = Constraint{};
	EXPECT_TRUE(book.hasEdgeNear(15, 3, 7));
	EXPECT_TRUE(book.hasEdgeNear(15, 5, 5));
	EXPECT_FALSE(book.hasEdgeNear(15, 6, 9));
	EXPECT_FALSE(book.hasEdgeNear(14, 0, 10));
}
