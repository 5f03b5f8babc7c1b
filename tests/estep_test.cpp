// EStep (Sec. 4.1, Eq. 14-15, Fig. 4): profile split-and-merge into static and dynamic children.
#include "estep/EStep.h"

#include <gtest/gtest.h>

#include <set>

using namespace gridvector;
using mrpt::math::TPoint2D;

namespace
{
// A vector of occ.size() columns (3 m at the default 0.1 m) whose centre-row cells have occupancy `occ[c]`, well
// observed.
GridVector withProfile(const std::vector<double>& occ, double resolution = 0.1)
{
	GridOptions g;
	g.resolution = resolution;
	GridVector v(TPoint2D(1, 1), TPoint2D(1 + resolution * occ.size(), 1), g);
	for (int c = 0; c < v.cols(); ++c)
	{
		GridCell& cell = v.cell(v.halfWidth(), c);
		cell.n_visit = 20;
		cell.n_occupy = float(20 * occ[size_t(c)]);
		cell.n_acc = 3;
		cell.x_acc = 0.15f, cell.y_acc = 0.15f;
	}
	v.id = 7;
	v.scanIndex = 42;
	return v;
}
std::vector<double> runs(std::initializer_list<std::pair<int, double>> r)
{
	std::vector<double> p;
	for (auto [n, v] : r) p.insert(p.end(), size_t(n), v);
	return p;
}
}  // namespace

TEST(EStep, PiecesSplitAtThresholdCrossings)
{
	auto ps = EStep::pieces(runs({{10, 0.9}, {10, 0.1}, {10, 0.9}}), 0.5, 3);
	ASSERT_EQ(ps.size(), 3u);
	EXPECT_TRUE(ps[0].isStatic);
	EXPECT_FALSE(ps[1].isStatic);
	EXPECT_EQ(ps[1].first, 10);
	EXPECT_EQ(ps[1].last, 20);
	EXPECT_TRUE(ps[2].isStatic);
	// all above / all below: one piece
	EXPECT_EQ(EStep::pieces(runs({{8, 0.7}}), 0.5, 3).size(), 1u);
	EXPECT_FALSE(EStep::pieces(runs({{8, 0.2}}), 0.5, 3)[0].isStatic);
}

TEST(EStep, ShortPiecesMergeIntoTheirNeighbours)
{
	// a 1-column dip inside a static wall disappears, a 2-column blip at the end too
	auto ps = EStep::pieces(runs({{10, 0.9}, {1, 0.1}, {10, 0.9}, {2, 0.1}}), 0.5, 3);
	ASSERT_EQ(ps.size(), 1u);
	EXPECT_TRUE(ps[0].isStatic);
	EXPECT_EQ(ps[0].first, 0);
	EXPECT_EQ(ps[0].last, 23);
	// the shortest goes first: [5 S][2 D][5 S][4 D] -> [12 S][4 D]
	ps = EStep::pieces(runs({{5, 0.9}, {2, 0.1}, {5, 0.9}, {4, 0.1}}), 0.5, 3);
	ASSERT_EQ(ps.size(), 2u);
	EXPECT_EQ(ps[0].last, 12);
	EXPECT_FALSE(ps[1].isStatic);
}

TEST(EStep, ChildrenAreSubGridsOfTheParent)
{
	const GridVector parent = withProfile(runs({{10, 0.9}, {10, 0.1}, {10, 0.9}}));
	const EStep e;
	const auto kids = e.split(parent);
	ASSERT_EQ(kids.size(), 3u);
	double len = 0, occ = 0, visit = 0;
	for (size_t k = 0; k < kids.size(); ++k)
	{
		len += kids[k].length();
		occ += kids[k].totalOccupy();
		visit += kids[k].totalVisit();
		EXPECT_EQ(kids[k].id, EStep::childId(parent.id, k));
		EXPECT_EQ(EStep::parentIdOf(kids[k].id), parent.id);
		EXPECT_EQ(kids[k].scanIndex, parent.scanIndex);
		EXPECT_NEAR(kids[k].start().y, 1.0, 1e-12);  // on the parent's line
	}
	EXPECT_NEAR(len, parent.length(), 1e-9);
	EXPECT_NEAR(occ, parent.totalOccupy(), 1e-3);  // the posterior is untouched (Eq. 5)
	EXPECT_NEAR(visit, parent.totalVisit(), 1e-3);
	EXPECT_EQ(kids[0].state, VectorState::Static);
	EXPECT_EQ(kids[1].state, VectorState::Dynamic);
	EXPECT_NEAR(kids[1].start().x, 2.0, 1e-9);
	EXPECT_NEAR(kids[1].end().x, 3.0, 1e-9);
	// cell by cell: the dynamic child's first column is the parent's column 10
	for (int r = 0; r < parent.rows(); ++r) EXPECT_EQ(kids[1].cell(r, 0).n_occupy, parent.cell(r, 10).n_occupy);
	// the mean point of a cell is where it was
	const TPoint2D a = kids[1].cellMeanPoint(parent.halfWidth(), 3), b = parent.cellMeanPoint(parent.halfWidth(), 13);
	EXPECT_NEAR(a.x, b.x, 1e-6);
	EXPECT_NEAR(a.y, b.y, 1e-6);
}

TEST(EStep, UnobservedColumnsStayStatic)
{
	EStepOptions o;
	o.minVisits = 3;
	const EStep e(o);
	// never re-observed (prior only): static
	GridVector fresh(TPoint2D(0, 0), TPoint2D(2, 0), GridOptions{});
	EXPECT_EQ(e.split(fresh)[0].state, VectorState::Static);
	// a column observed at 0.45: dynamic
	EXPECT_EQ(e.split(withProfile(runs({{10, 0.45}})))[0].state, VectorState::Dynamic);
}

// Sec. 3.1's counting model starts every cell at n_occupy = 1/2, n_visit = 1: min_visits compares
// n_visit with that prior included, so min_visits 3 asks for two observations beyond the prior.
TEST(EStep, MinVisitsCountsThePriorsVisit)
{
	EStepOptions o;
	o.minVisits = 3;
	const EStep e(o);
	GridVector v(TPoint2D(0, 0), TPoint2D(0.3, 0), GridOptions{});
	ASSERT_EQ(v.cols(), 3);
	ASSERT_EQ(v.cell(v.halfWidth(), 0).n_visit, 1.f);  // the prior
	v.cell(v.halfWidth(), 1).n_visit += 1;  // one beam through: n_visit 2
	v.cell(v.halfWidth(), 2).n_visit += 2;  // two beams through: n_visit 3
	const std::vector<double> prof = e.profile(v);
	EXPECT_EQ(prof[0], 1.0);  // the prior alone does not count: static
	EXPECT_EQ(prof[1], 1.0);  // prior + one observation: below min_visits, still static
	EXPECT_NEAR(prof[2], 0.5 / 3, 1e-6);  // prior + two observations count: 1/2 over 3
}

TEST(EStep, RunRecordsChildrenPerParent)
{
	std::vector<GridVector> parents = {withProfile(runs({{10, 0.9}})), withProfile(runs({{10, 0.9}, {10, 0.1}})),
									   withProfile(runs({{10, 0.1}}))};
	parents[1].id = 8, parents[2].id = 9;
	const EStepResult r = EStep().run(parents);
	ASSERT_EQ(r.childrenOf.size(), 3u);
	EXPECT_EQ(r.childrenOf[0].size(), 1u);
	EXPECT_EQ(r.childrenOf[1].size(), 2u);
	EXPECT_EQ(r.childrenOf[2].size(), 1u);
	EXPECT_EQ(r.children.size(), r.pieces.size());
	EXPECT_EQ(r.staticCount, 2u);
	EXPECT_EQ(r.dynamicCount, 2u);
	EXPECT_NEAR(r.staticLength, 2.0, 1e-9);
	EXPECT_NEAR(r.dynamicLength, 2.0, 1e-9);
	EXPECT_EQ(r.children[r.childrenOf[2][0]].id, EStep::childId(9, 0));
}

// Eq. 25: what EmSlam counts as a changed M_chd (EmIteration::changedVectors, the convergence test).
TEST(EStep, ChangedChildrenSeesEveryChangeOfMchd)
{
	// a 4 mm grid: a split point moving by one column moves it by less than a centimetre
	GridOptions g;
	g.resolution = 0.004;
	const EStep e({}, g);
	const auto result = [&](std::vector<GridVector> parents) {
		for (size_t k = 0; k < parents.size(); ++k) parents[k].id = k + 1;
		return e.run(parents);
	};
	const GridVector wall = withProfile(runs({{200, 0.9}}), 0.004);
	const EStepResult before = result({withProfile(runs({{100, 0.9}, {100, 0.1}}), 0.004), wall});
	ASSERT_EQ(before.childrenOf[0].size(), 2u);
	EXPECT_EQ(EStep::changedChildren(before, &before), std::vector<bool>({false, false}));
	// the split point one column (4 mm) on: both children 4 mm longer / shorter, same ids and states
	const EStepResult moved = result({withProfile(runs({{101, 0.9}, {99, 0.1}}), 0.004), wall});
	EXPECT_EQ(EStep::changedChildren(moved, &before), std::vector<bool>({true, false}));
	// the two states swap places (equal lengths, same ids)
	const EStepResult swapped = result({withProfile(runs({{100, 0.1}, {100, 0.9}}), 0.004), wall});
	EXPECT_EQ(EStep::changedChildren(swapped, &before), std::vector<bool>({true, false}));
	// a whole vector flips state: same id, same length
	const EStepResult flipped =
		result({withProfile(runs({{100, 0.9}, {100, 0.1}}), 0.004), withProfile(runs({{200, 0.1}}), 0.004)});
	EXPECT_EQ(EStep::changedChildren(flipped, &before), std::vector<bool>({false, true}));
	// one child more
	const EStepResult three = result({withProfile(runs({{100, 0.9}, {100, 0.1}}), 0.004),
									  withProfile(runs({{80, 0.9}, {80, 0.1}, {40, 0.9}}), 0.004)});
	EXPECT_EQ(EStep::changedChildren(three, &before), std::vector<bool>({false, true}));
	// the same vectors carried along a moved trajectory: only float noise in their lengths, no change
	const mrpt::math::TPose2D pose(3.7, -12.1, 0.83);
	const EStepResult carried =
		result({withProfile(runs({{100, 0.9}, {100, 0.1}}), 0.004).compose(pose), wall.compose(pose)});
	ASSERT_NEAR(carried.children[0].length(), before.children[0].length(), 1e-12);
	EXPECT_EQ(EStep::changedChildren(carried, &before), std::vector<bool>({false, false}));
	// before the first E-step every vector is its own single static child
	EXPECT_EQ(EStep::changedChildren(before, nullptr), std::vector<bool>({true, false}));
	EXPECT_EQ(EStep::changedChildren(flipped, nullptr), std::vector<bool>({true, true}));
}

TEST(EStep, FinalSplitDemotesPlacesOccupiedPartOfTheTime)
{
	EStepOptions o;
	o.finalStaticThreshold = 0.7;
	const EStep e(o);
	// static at 0.5: a wall (0.95) and a door closed 60 % of the time (0.6)
	GridVector child = withProfile(runs({{10, 0.95}, {10, 0.6}}));
	child.state = VectorState::Static;
	GridVector moving = withProfile(runs({{10, 0.1}}));
	moving.state = VectorState::Dynamic;
	moving.id = 8;
	const auto out = e.finalSplit({child, moving});
	ASSERT_EQ(out.size(), 3u);
	EXPECT_EQ(out[0].state, VectorState::Static);
	EXPECT_NEAR(out[0].length(), 1.0, 1e-9);
	EXPECT_EQ(out[1].state, VectorState::Dynamic);
	EXPECT_NEAR(out[1].length(), 1.0, 1e-9);
	EXPECT_EQ(out[0].id, 9u);  // new ids above every child's
	EXPECT_EQ(out[1].id, 10u);
	EXPECT_EQ(out[2].id, moving.id);  // dynamic children stay as they are
	EXPECT_EQ(out[2].state, VectorState::Dynamic);
	std::vector<uint64_t> parents;
	e.finalSplit({child, moving}, &parents);
	EXPECT_EQ(parents, (std::vector<uint64_t>{child.id, child.id, moving.id}));
}

TEST(EStep, ChildIdsStayUniqueBeyond256Pieces)
{
	// 90 m of 0.3 m static and dynamic stretches: 300 pieces at min_piece_length 0.3
	std::vector<double> prof;
	for (int k = 0; k < 150; ++k) prof.insert(prof.end(), {0.9, 0.9, 0.9, 0.1, 0.1, 0.1});
	std::vector<GridVector> parents{withProfile(prof), withProfile(prof)};
	parents[1].id = parents[0].id + 1;  // piece 256 of the first met piece 0 of the second (id * 256 + k)
	const EStepResult r = EStep().run(parents);
	ASSERT_EQ(r.children.size(), 600u);
	std::set<uint64_t> ids;
	for (size_t p = 0; p < parents.size(); ++p)
	{
		ASSERT_EQ(r.childrenOf[p].size(), 300u);
		for (size_t k = 0; k < 300; ++k)
		{
			const uint64_t id = r.children[r.childrenOf[p][k]].id;
			EXPECT_EQ(id, EStep::childId(parents[p].id, k));
			EXPECT_EQ(EStep::parentIdOf(id), parents[p].id);
			ids.insert(id);
		}
	}
	EXPECT_EQ(ids.size(), 600u);
}

TEST(EStep, ChildIdsAreRecoverableOrRefusedOverGenerations)
{
	// generation after generation of the last piece: every parent recoverable until the id is full
	std::vector<uint64_t> chain{1000};
	while (chain.back() < (uint64_t(1) << (64 - EStep::kChildBits)))
		chain.push_back(EStep::childId(chain.back(), (size_t(1) << EStep::kChildBits) - 1));
	ASSERT_EQ(chain.size(), 4u);  // 1000 < 2^10: three generations of 16 bits fit in 64
	for (size_t g = 1; g < chain.size(); ++g) EXPECT_EQ(EStep::parentIdOf(chain[g]), chain[g - 1]);
	EXPECT_THROW(EStep::childId(chain.back(), 0), std::overflow_error);  // never wraps around
	EXPECT_THROW(EStep::childId(1, size_t(1) << EStep::kChildBits), std::overflow_error);
	EXPECT_EQ(EStep::childId(1, (size_t(1) << EStep::kChildBits) - 1) + 1, EStep::childId(2, 0));
}

TEST(EStep, FinalSplitIdsStayUniqueAcrossGenerations)
{
	// a per-scan vector whose id is another's first child's: childId(child, k) of the
	// final split would give the other's child ids again
	std::vector<GridVector> parents{withProfile(runs({{10, 0.95}, {10, 0.6}})), withProfile(runs({{10, 0.1}}))};
	parents[0].id = 1;
	parents[1].id = EStep::childId(1, 0);
	EStepOptions o;
	o.finalStaticThreshold = 0.7;
	const EStep e(o);
	const EStepResult r = e.run(parents);
	ASSERT_EQ(r.children.size(), 2u);
	std::vector<uint64_t> parentIds;
	const auto out = e.finalSplit(r.children, &parentIds);
	ASSERT_EQ(out.size(), 3u);  // wall, door, the other's dynamic child
	ASSERT_EQ(parentIds.size(), out.size());
	std::set<uint64_t> ids;
	for (size_t i = 0; i < out.size(); ++i)
	{
		ids.insert(out[i].id);
		const size_t k = parentIds[i] == r.children[0].id ? 0 : 1;
		ASSERT_EQ(parentIds[i], r.children[k].id);
		EXPECT_EQ(EStep::parentIdOf(parentIds[i]), parents[k].id);  // and on to the per-scan vector
	}
	EXPECT_EQ(ids.size(), out.size());
}

TEST(EStep, FinalSplitFindsAStretchClearlyBelowItsWall)
{
	// a wall read 0.98 with a door closed 80 % of the time in it: above the final
	// threshold, but 0.18 below the rest of its vector
	EStepOptions o;
	o.finalStaticThreshold = 0.7;
	o.finalRelativeDrop = 0.1;
	GridVector child = withProfile(runs({{10, 0.98}, {9, 0.8}, {11, 0.98}}));
	child.state = VectorState::Static;
	const auto out = EStep(o).finalSplit({child});
	ASSERT_EQ(out.size(), 3u);
	EXPECT_EQ(out[1].state, VectorState::Dynamic);
	EXPECT_NEAR(out[1].length(), 0.9, 1e-9);
	// without the relative test it stays one static vector; a uniformly noisy wall (0.8) too
	o.finalRelativeDrop = 0;
	EXPECT_EQ(EStep(o).finalSplit({child}).size(), 1u);
	o.finalRelativeDrop = 0.1;
	GridVector noisy = withProfile(runs({{30, 0.8}}));
	noisy.state = VectorState::Static;
	const auto n = EStep(o).finalSplit({noisy});
	ASSERT_EQ(n.size(), 1u);
	EXPECT_EQ(n[0].state, VectorState::Static);
}

namespace
{
// A merged-looking vector: columns [a, b) covered by no part (all counts zero).
GridVector withHole(int cols, int a, int b)
{
	GridVector v = withProfile(std::vector<double>(size_t(cols), 0.95));
	for (int r = 0; r < v.rows(); ++r)
		for (int c = a; c < b; ++c) v.cell(r, c) = GridCell{0.f, 0.f, 0.f, 0.f, 0.f};
	return v;
}
}  // namespace

TEST(EStep, ObservedRunsSplitAtUnobservedGaps)
{
	const auto runs10 = EStep::observedRuns(withHole(30, 10, 20), 3);
	ASSERT_EQ(runs10.size(), 2u);
	EXPECT_EQ(runs10[0].first, 0);
	EXPECT_EQ(runs10[0].last, 10);
	EXPECT_EQ(runs10[1].first, 20);
	EXPECT_EQ(runs10[1].last, 30);
	// a gap shorter than the minimum stays inside; an unobserved end is trimmed
	const auto r2 = EStep::observedRuns(withHole(30, 10, 12), 3);
	ASSERT_EQ(r2.size(), 1u);
	EXPECT_EQ(r2[0].last, 30);
	const auto r3 = EStep::observedRuns(withHole(30, 25, 30), 3);
	ASSERT_EQ(r3.size(), 1u);
	EXPECT_EQ(r3[0].last, 25);
}

TEST(EStep, CutUnobservedSplitsMergedVectorsAndTheirSources)
{
	EStepOptions o;
	o.minPieceLength = 0.3;
	const EStep e(o);
	GridVector merged = withHole(30, 10, 20);  // (1, 1)-(4, 1), nothing seen in x 2..3
	merged.id = 100;
	merged.state = VectorState::Static;
	GridVector left(TPoint2D(1, 1), TPoint2D(2, 1), GridOptions{}),
		right(TPoint2D(3, 1), TPoint2D(4, 1), GridOptions{});
	left.id = 1, right.id = 2;
	MergeResult m;
	m.vectors = {merged};
	m.sources = {{1, 2}};
	const MergeResult out = e.cutUnobserved(m, {left, right});
	ASSERT_EQ(out.vectors.size(), 2u);
	ASSERT_EQ(out.sources.size(), 2u);
	EXPECT_NEAR(out.vectors[0].start().x, 1.0, 1e-9);
	EXPECT_NEAR(out.vectors[0].end().x, 2.0, 1e-9);
	EXPECT_NEAR(out.vectors[1].start().x, 3.0, 1e-9);
	EXPECT_NEAR(out.vectors[1].end().x, 4.0, 1e-9);
	EXPECT_EQ(out.sources[0], std::vector<uint64_t>{1});
	EXPECT_EQ(out.sources[1], std::vector<uint64_t>{2});
	for (const auto& v : out.vectors) EXPECT_EQ(v.state, VectorState::Static);
	EXPECT_NE(out.vectors[0].id, out.vectors[1].id);
	// counts are the merged vector's, none lost
	EXPECT_NEAR(out.vectors[0].totalOccupy() + out.vectors[1].totalOccupy(), merged.totalOccupy(), 1e-3);
	// a vector without gaps is copied unchanged
	m.vectors = {withProfile(runs({{10, 0.9}}))};
	m.sources = {{5}};
	const MergeResult same = e.cutUnobserved(m, {});
	ASSERT_EQ(same.vectors.size(), 1u);
	EXPECT_EQ(same.sources[0], std::vector<uint64_t>{5});
	EXPECT_EQ(same.vectors[0].cols(), 10);
}

TEST(EStep, SplitSpansMakesTheGivenStretchesDynamic)
{
	// a 3 m static wall (30 columns) with a door's closed state lying on it from 1.0 to 1.9 m
	const GridVector wall = withProfile(std::vector<double>(30, 0.95));
	const EStep e;
	const auto kids = e.splitSpans(wall, {{1.0, 1.9}});
	ASSERT_EQ(kids.size(), 3u);
	EXPECT_EQ(kids[0].state, VectorState::Static);
	EXPECT_EQ(kids[1].state, VectorState::Dynamic);
	EXPECT_EQ(kids[2].state, VectorState::Static);
	EXPECT_NEAR(kids[0].length(), 1.0, 1e-9);
	EXPECT_NEAR(kids[1].length(), 0.9, 1e-9);  // the columns whose centres lie in [1.0, 1.9]
	EXPECT_NEAR(kids[1].start().x, 2.0, 1e-9);  // the wall starts at x = 1
	EXPECT_NEAR(kids[2].length(), 1.1, 1e-9);
	EXPECT_EQ(kids[0].id, wall.id);  // the first child keeps the id, the caller numbers the others
	EXPECT_EQ(kids[1].id, 0u);
	EXPECT_NEAR(kids[0].totalOccupy() + kids[1].totalOccupy() + kids[2].totalOccupy(), wall.totalOccupy(), 1e-3);
	// no stretch on the vector: itself, unchanged
	const auto same = e.splitSpans(wall, {{5.0, 6.0}});
	ASSERT_EQ(same.size(), 1u);
	EXPECT_EQ(same[0].state, VectorState::Static);
	EXPECT_NEAR(same[0].length(), 3.0, 1e-9);
}

// Sec. 4.1's minimum vector length: the pieces a door's states cut from a wall keep no static
// sliver (vectors.txt held static vectors of 0.0002-0.043 m beside the sim rows' doors): a wall's
// last partial column past a closed state that reaches the wall's end, a stub between two states.
TEST(EStep, SplitSpansLeavesNoStaticSliverBesideAStretch)
{
	const EStep e;
	const double minLen = EStepOptions{}.minPieceLength;
	GridVector wall = withProfile(std::vector<double>(30, 0.95));
	wall = GridVector::fromParts(wall.start(), TPoint2D(wall.start().x + 3.003, wall.start().y), GridOptions{}, 31,
								 std::vector<GridCell>(size_t(3 * 31), wall.cell(1, 0)));
	ASSERT_EQ(wall.cols(), 31);  // the last column holds 3 mm of the wall, its centre 5 cm past the end
	wall.state = VectorState::Static;
	const auto pieces = e.splitSpans(wall, {{2.0, 3.003}});
	ASSERT_EQ(pieces.size(), 2u);
	EXPECT_EQ(pieces[0].state, VectorState::Static);
	EXPECT_NEAR(pieces[0].length(), 2.0, 1e-9);
	EXPECT_EQ(pieces[1].state, VectorState::Dynamic);
	EXPECT_NEAR(pieces[1].length(), 1.003, 1e-9);
	// a 0.2 m stub between two states joins them; the 1 m and 0.5 m ends stay static
	const auto stub = e.splitSpans(withProfile(std::vector<double>(30, 0.95)), {{1.0, 1.4}, {1.6, 2.5}});
	ASSERT_EQ(stub.size(), 3u);
	EXPECT_EQ(stub[1].state, VectorState::Dynamic);
	EXPECT_NEAR(stub[1].length(), 1.5, 1e-9);
	for (const auto& p : stub)
		if (p.state == VectorState::Static)
		{
			EXPECT_GE(p.length(), minLen - 1e-9);
		}
}

TEST(EStep, PeakRowProfileReadsCellsWithoutCountsAsThePrior)
{
	// A merged grid's cell that no part covered has no counts (n_visit = 0); the peak-row
	// profile reads it as a cell at the configured prior (here 0.3 of 1.5 visits, which
	// min_visits 1 lets count), as GridVector::occupancyProfile and Eq. 6 read it.
	GridOptions g;
	g.priorOccupy = 0.3, g.priorVisit = 1.5;
	EStepOptions o;
	o.usePeakRow = true;
	o.minVisits = 1;
	GridVector v(TPoint2D(0, 0), TPoint2D(1, 0), g);
	const auto atPrior = EStep(o, g).profile(v);
	for (auto& c : v.cells()) c = GridCell{0.f, 0.f, 0.f, 0.f, 0.f};
	const auto empty = EStep(o, g).profile(v);
	ASSERT_EQ(empty.size(), atPrior.size());
	for (size_t c = 0; c < empty.size(); ++c)
	{
		EXPECT_NEAR(atPrior[c], 0.2, 1e-6) << c;
		EXPECT_DOUBLE_EQ(empty[c], atPrior[c]) << c;  // was 1: a column of cells without counts read as unseen
	}
}

// Sec. 4.1: each E-step computes p(c_i | M^[k]) from the current map alone. A wall piece the
// first E-step made static (0.9) that the next map reads at 0.45 is dynamic at the second E-step.
TEST(EStep, EachEStepClassifiesFromTheMapAlone)
{
	const EStep e;
	const GridVector before = withProfile(runs({{10, 0.9}}));
	std::vector<ProfilePiece> first;
	ASSERT_EQ(e.split(before, &first)[0].state, VectorState::Static);
	const GridVector now = withProfile(runs({{10, 0.45}}));
	EXPECT_EQ(e.split(now)[0].state, VectorState::Dynamic);
	const EStepResult r1 = e.run({before});
	const EStepResult r2 = e.run({now});
	ASSERT_EQ(r2.children.size(), 1u);
	EXPECT_EQ(r2.children[0].state, VectorState::Dynamic);
	EXPECT_TRUE(EStep::changedChildren(r2, &r1)[0]);  // Eq. 25: its M_chd changed
}
