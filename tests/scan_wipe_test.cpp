// Eq. 8 for one scan: every triangle of the scan over the map, once per cell per scan.
#include "map/ScanWipe.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gridvector;
using mrpt::math::TPoint2D;

namespace
{
VectorIndex indexOf(const std::vector<GridVector>& map)
{
	VectorIndex idx(2.0);
	for (size_t i = 0; i < map.size(); ++i) idx.insert(uint32_t(i), Box2D::of(map[i]));
	return idx;
}
}  // namespace

TEST(ScanWipe, CellOnSharedRayCountedOncePerScan)
{
	// Two walls meeting at a corner (0, 2); a map vector along x = 0 lies on the shared ray.
	std::vector<GridVector> map{GridVector({0, 0.5}, {0, 1.5}, GridOptions{})};
	const VectorIndex idx = indexOf(map);
	ScanWipe w(0.05, false);  // the paper's per-cell weighting
	const std::vector<ScanWipe::Segment> scan{{{1, 2}, {0, 2}}, {{0, 2}, {-1, 2}}};
	const auto st = w.apply({0, 0}, scan, map, idx);
	EXPECT_EQ(st.triangles, 2u);
	EXPECT_EQ(st.vectorsTouched, 1u);
	// the middle row (on the ray) is in both triangles, but counted once
	for (int c = 0; c < map[0].cols(); ++c) EXPECT_FLOAT_EQ(map[0].cell(1, c).n_visit, 2.f);
}

TEST(ScanWipe, HitWinsOverVisit)
{
	// Two triangles sharing the ray x = 0: the first ends on the wall y = 2,
	// the second on a wall further away (y = 2.5). The map vector on y = 2 has
	// a cell centred on the shared ray: hit by the first, passed by the second.
	std::vector<GridVector> map{GridVector({0.55, 2}, {-0.45, 2}, GridOptions{})};
	const VectorIndex idx = indexOf(map);
	ScanWipe w(0.05, false);  // the paper's per-cell weighting
	const std::vector<ScanWipe::Segment> scan{{{1, 2}, {0, 2}}, {{0, 2.5}, {-1, 2.5}}};
	w.apply({0, 0}, scan, map, idx);
	ASSERT_EQ(map[0].cols(), 10);
	for (int c = 0; c < map[0].cols(); ++c)
	{
		const GridCell& cell = map[0].cell(1, c);
		EXPECT_FLOAT_EQ(cell.n_visit, 2.f) << c;
		EXPECT_FLOAT_EQ(cell.n_occupy, c <= 5 ? 1.5f : 0.5f) << c;  // col 5 centred on x = 0
	}
}

TEST(ScanWipe, SkippedVectorsAndFarVectorsUntouched)
{
	std::vector<GridVector> map{GridVector({1, 2}, {-1, 2}, GridOptions{}), GridVector({1, 2}, {-1, 2}, GridOptions{}),
								GridVector({101, 2}, {99, 2}, GridOptions{})};
	const VectorIndex idx = indexOf(map);
	ScanWipe w(0.05, false);  // the paper's per-cell weighting
	const auto st = w.apply({0, 0}, std::vector<ScanWipe::Segment>{{{1, 2}, {-1, 2}}}, map, idx,
							[](size_t, uint32_t s) { return s == 1 ? WipePart::Outside : WipePart::Hit; });
	EXPECT_EQ(st.candidates, 2u);  // the far vector never comes out of the index
	EXPECT_GT(map[0].totalVisit(), GridVector({1, 2}, {-1, 2}, GridOptions{}).totalVisit());
	EXPECT_FLOAT_EQ(map[1].totalVisit(), float(map[1].cells().size()));
	EXPECT_FLOAT_EQ(map[2].totalVisit(), float(map[2].cells().size()));
	EXPECT_EQ(st.cellsHit, size_t(map[0].cols()));
	EXPECT_EQ(st.cellsVisited, size_t(map[0].cols()));
}

TEST(ScanWipe, BeamWeightCountsTheFansBeams)
{
	// 201 endpoints spread over the wall y = 2, x in [-1, 1] (fan of ~53 deg):
	// a cell of the coincident map vector straight ahead (range 2) is crossed
	// by about density * 0.1 / 2 beams, as Algorithm 1 would count endpoints.
	std::vector<GridVector> map{GridVector({1, 2}, {-1, 2}, GridOptions{})};
	const VectorIndex idx = indexOf(map);
	ScanWipe w(0.05, true);
	const std::vector<ScanWipe::Segment> scan{{{1, 2}, {-1, 2}, 201}};
	w.apply({0, 0}, scan, map, idx);
	const double fan = 2 * std::atan2(1.0, 2.0), density = 200 / fan;
	const GridCell& hit = map[0].cell(1, 10);  // centred at x = -0.05
	EXPECT_NEAR(hit.n_visit - 1, density * 0.1 / 2.0, 0.05 * density * 0.1 / 2.0);
	EXPECT_NEAR(hit.n_occupy - 0.5, hit.n_visit - 1, 1e-5);  // part c: every beam ends there
	const GridCell& front = map[0].cell(2, 10);
	EXPECT_NEAR(front.n_occupy, 0.5, 1e-6);  // part b: beams pass
	EXPECT_GT(front.n_visit - 1, 0.9 * (hit.n_visit - 1));
	// the endpoints of that fan within the cell: about 10 (one per cm)
	EXPECT_NEAR(hit.n_visit - 1, 10.0, 1.5);
}

TEST(ScanWipe, AloneTriangleAddsWhatItsMarksWould)
{
	// A slanted wall seen obliquely: cells of part b and c, weights varying with range.
	const GridVector wall({-1, 2.2}, {1.5, 1.8}, GridOptions{});
	const WipeTriangle tri({0.2, 0}, {1.4, 1.85}, {-0.9, 2.15}, 0.05, 180);
	for (const bool beams : {false, true})
	{
		GridVector viaMarks = wall, alone = wall;
		std::vector<ScanWipe::Mark> marks(wall.cells().size());
		ScanWipe::Span span;
		ScanWipe::Stats a, b;
		ScanWipe::mark(
			tri, viaMarks, WipePart::Hit, beams, [&] { return marks.data(); }, span);
		ASSERT_LT(span.first, span.last);
		EXPECT_TRUE(ScanWipe::add(marks.data(), span, viaMarks.cells(), beams, a));
		EXPECT_TRUE(ScanWipe::addAlone(tri, alone, beams, b));
		EXPECT_GT(a.cellsHit, 0u);
		EXPECT_GT(a.cellsVisited, 0u);
		EXPECT_EQ(a.cellsHit, b.cellsHit);
		EXPECT_EQ(a.cellsVisited, b.cellsVisited);
		for (size_t i = 0; i < wall.cells().size(); ++i)
		{
			EXPECT_EQ(viaMarks.cells()[i].n_occupy, alone.cells()[i].n_occupy) << i;
			EXPECT_EQ(viaMarks.cells()[i].n_visit, alone.cells()[i].n_visit) << i;
			EXPECT_EQ(marks[i].hit + marks[i].pass, 0.f) << i;  // add() leaves the marks zeroed
		}
	}
}

TEST(ScanWipe, CompleteAddsWhatTheHeldBackPartsWouldHave)
{
	// The HitWinsOverVisit scan, applied with the first triangle capped at part b,
	// then completed to all parts: the cells end as with the full apply, per cell
	// (the shared ray's cell still counted once) and per beam.
	for (const bool beams : {false, true})
	{
		const GridVector wall({0.55, 2}, {-0.45, 2}, GridOptions{});
		std::vector<GridVector> full{wall}, held{wall};
		const VectorIndex idx = indexOf(full);
		ScanWipe w(0.05, beams);
		const std::vector<ScanWipe::Segment> scan{{{1, 2}, {0, 2}, 50}, {{0, 2.5}, {-1, 2.5}, 50}};
		w.apply({0, 0}, scan, full, idx);
		w.apply({0, 0}, scan, held, idx,
				[](size_t seg, uint32_t) { return seg == 0 ? WipePart::Visited : WipePart::Hit; });
		ASSERT_LT(held[0].totalOccupy(), full[0].totalOccupy() - 1);  // the hits held back
		const std::vector<WipeTriangle> tris{w.triangleOf({0, 0}, scan[0]), w.triangleOf({0, 0}, scan[1])};
		ScanWipe::Stats st;
		EXPECT_TRUE(ScanWipe::complete(tris, {WipePart::Visited, WipePart::Hit}, {WipePart::Hit, WipePart::Hit},
									   held[0], beams, st));
		EXPECT_GT(st.cellsHit, 0u);
		for (size_t i = 0; i < wall.cells().size(); ++i)
		{
			EXPECT_NEAR(held[0].cells()[i].n_occupy, full[0].cells()[i].n_occupy, 1e-5) << beams << " " << i;
			EXPECT_NEAR(held[0].cells()[i].n_visit, full[0].cells()[i].n_visit, 1e-5) << beams << " " << i;
		}
		// nothing held back: nothing to add
		EXPECT_FALSE(ScanWipe::complete(tris, {WipePart::Hit, WipePart::Hit}, {WipePart::Hit, WipePart::Hit}, held[0],
										beams, st));
	}
}
