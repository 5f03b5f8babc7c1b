// Algorithm 2: merging keeps the Eq. 6 posterior and the totals; weighted refit; union extent.
#include "map/VectorMerger.h"

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>
#include <random>

#include "wall_pieces.h"

using namespace gridvector;
using gvtest::arcPiece;
using mrpt::math::TPoint2D;

namespace
{
/** Eq. 6 at p over a set of vectors: (sum n_occupy, sum n_visit) of the cells containing p. */
std::pair<double, double> eq6(const std::vector<const GridVector*>& vs, const TPoint2D& p)
{
	double o = 0, v = 0;
	for (const GridVector* g : vs)
	{
		int r, c;
		if (!g->cellOf(p, r, c)) continue;
		o += g->cell(r, c).n_occupy;
		v += g->cell(r, c).n_visit;
	}
	return {o, v};
}

/** A wall vector from s to e with beam endpoints on the line (optional noise)
 * and varied counts, as if wiped by other scans. */
GridVector wall(TPoint2D s, TPoint2D e, double noise, unsigned seed)
{
	GridVector v(s, e, GridOptions{});
	std::mt19937 rng(seed);
	std::normal_distribution<double> N(0, noise > 0 ? noise : 1e-12);
	std::uniform_int_distribution<int> K(0, 6);
	const TPoint2D d = v.direction(), n = v.leftNormal();
	for (double u = 0.01; u < v.length(); u += 0.02)
	{
		const double w = noise > 0 ? N(rng) : 0.0;
		v.addEndpoint({s.x + u * d.x + w * n.x, s.y + u * d.y + w * n.y});
	}
	for (auto& c : v.cells())
	{
		const int k = K(rng);  // wipes: some hits, some passes
		c.n_visit += float(k);
		c.n_occupy += float(k % 3);
	}
	return v;
}

void expectTotalsConserved(const std::vector<const GridVector*>& parts, const GridVector& m)
{
	double o = 0, v = 0, n = 0;
	for (const GridVector* p : parts) o += p->totalOccupy(), v += p->totalVisit(), n += p->totalPoints();
	EXPECT_NEAR(m.totalOccupy(), o, 1e-4 * o);
	EXPECT_NEAR(m.totalVisit(), v, 1e-4 * v);
	EXPECT_NEAR(m.totalPoints(), n, 1e-6);
}

double pointsMeanOffset(const GridVector& m)  // mean |distance| of the cells' gravity centres to y = 0
{
	double s = 0, w = 0;
	for (int r = 0; r < m.rows(); ++r)
		for (int c = 0; c < m.cols(); ++c)
			if (m.cell(r, c).n_acc > 0)
			{
				s += m.cell(r, c).n_acc * m.cellMeanPoint(r, c).y;
				w += m.cell(r, c).n_acc;
			}
	return s / w;
}
}  // namespace

TEST(VectorMerger, CollinearOverlapGivesUnionExtent)
{
	const GridVector a = wall({0, 0}, {2, 0}, 0, 1), b = wall({1, 0}, {3, 0}, 0, 2);
	const GridVector m = VectorMerger().merge(a, b);
	EXPECT_NEAR(m.start().x, 0, 1e-9);
	EXPECT_NEAR(m.start().y, 0, 1e-9);
	EXPECT_NEAR(m.end().x, 3, 1e-9);
	EXPECT_NEAR(m.end().y, 0, 1e-9);
	EXPECT_EQ(m.cols(), 30);
	EXPECT_EQ(m.scanIndex, -1);
	EXPECT_EQ(m.mergedCount, 2u);
	expectTotalsConserved({&a, &b}, m);
}

TEST(VectorMerger, AlignedGridsKeepEq6AtEveryPoint)
{
	const GridVector a = wall({0, 0}, {2, 0}, 0, 1), b = wall({1, 0}, {3.3, 0}, 0, 2);
	const GridVector m = VectorMerger().merge(a, b);
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> X(-0.2, 3.5), Y(-0.2, 0.2);
	int compared = 0;
	for (int i = 0; i < 5000; ++i)
	{
		const TPoint2D p(X(rng), Y(rng));
		const auto before = eq6({&a, &b}, p), after = eq6({&m}, p);
		if (before.second == 0)
		{
			EXPECT_EQ(after.second, 0) << p.x << " " << p.y;  // no new knowledge appears
			continue;
		}
		ASSERT_GT(after.second, 0) << p.x << " " << p.y;
		EXPECT_NEAR(after.first / after.second, before.first / before.second, 1e-5) << p.x << " " << p.y;
		EXPECT_NEAR(after.second, before.second, 1e-4);
		++compared;
	}
	EXPECT_GT(compared, 3000);
}

TEST(VectorMerger, OffsetGridsKeepEq6AveragedOverEachCell)
{
	// b's columns are shifted by half a cell: its counts are split evenly along
	// the vector. Eq. 6 with the counts averaged over each new cell agrees.
	const GridVector a = wall({0, 0}, {2, 0}, 0, 1), b = wall({1.05, 0}, {3.05, 0}, 0, 2);
	const GridVector m = VectorMerger().merge(a, b);
	ASSERT_NEAR(m.start().y, 0, 1e-9);
	ASSERT_NEAR(m.end().y, 0, 1e-9);
	for (int r = 0; r < m.rows(); ++r)
		for (int c = 0; c < m.cols(); ++c)
		{
			const TPoint2D ctr = m.cellCentre(r, c);
			double o = 0, v = 0;
			for (int k = 0; k < 10; ++k)  // sub-samples across the cell's length
			{
				const auto ov = eq6({&a, &b}, {ctr.x - 0.045 + 0.01 * k, ctr.y});
				o += ov.first, v += ov.second;
			}
			const GridCell& cell = m.cell(r, c);
			EXPECT_NEAR(cell.n_visit, v / 10, 1e-4) << r << " " << c;
			EXPECT_NEAR(cell.n_occupy, o / 10, 1e-4) << r << " " << c;
		}
	expectTotalsConserved({&a, &b}, m);
}

TEST(VectorMerger, NoisyWallsKeepDecisionsAndTotals)
{
	// Real parts: noisy points, so the refitted line differs slightly from both.
	const GridVector a = wall({0, 0}, {4, 0.01}, 0.01, 11), b = wall({1.0, 0.005}, {5.2, 0.0}, 0.01, 12);
	const GridVector m = VectorMerger().merge(a, b);
	expectTotalsConserved({&a, &b}, m);
	double sumErr = 0;
	int n = 0;
	for (int r = 0; r < m.rows(); ++r)
		for (int c = 0; c < m.cols(); ++c)
		{
			const TPoint2D p = m.cellCentre(r, c);
			const auto before = eq6({&a, &b}, p);
			if (before.second == 0) continue;
			const double pb = before.first / before.second, pa = m.cell(r, c).occupancy(m.priorRatio());
			EXPECT_NEAR(pa, pb, 0.06) << r << " " << c;
			if (std::abs(pb - 0.5) > 0.06)
			{
				EXPECT_EQ(pa > 0.5, pb > 0.5) << r << " " << c;
			}
			sumErr += std::abs(pa - pb);
			++n;
		}
	EXPECT_GT(n, 100);
	EXPECT_LT(sumErr / n, 0.01);
}

TEST(VectorMerger, RotatedPartsConserveTotals)
{
	const GridVector a = wall({0, 0}, {3, 0}, 0.01, 1);
	const double t = 6 * M_PI / 180;
	const GridVector b = wall({0.5, 0.02}, {0.5 + 2.5 * std::cos(t), 0.02 + 2.5 * std::sin(t)}, 0.01, 2);
	const GridVector c = wall({2, -0.03}, {4, -0.02}, 0.01, 3);
	const GridVector m = VectorMerger().merge({&a, &b, &c});
	expectTotalsConserved({&a, &b, &c}, m);
	EXPECT_EQ(m.mergedCount, 3u);
	EXPECT_GT(m.length(), 3.9);
	EXPECT_LT(std::abs(m.psi()), 4 * M_PI / 180);
	// every point keeps its exact position: the mean of all points is unchanged
	double sx = 0, n = 0;
	for (const GridVector* p : {&a, &b, &c})
		for (int r = 0; r < p->rows(); ++r)
			for (int k = 0; k < p->cols(); ++k)
				if (p->cell(r, k).n_acc > 0)
				{
					sx += p->cell(r, k).n_acc * p->cellMeanPoint(r, k).x;
					n += p->cell(r, k).n_acc;
				}
	double mx = 0, mn = 0;
	for (int r = 0; r < m.rows(); ++r)
		for (int k = 0; k < m.cols(); ++k)
			if (m.cell(r, k).n_acc > 0)
			{
				mx += m.cell(r, k).n_acc * m.cellMeanPoint(r, k).x;
				mn += m.cell(r, k).n_acc;
			}
	EXPECT_NEAR(mx / mn, sx / n, 1e-4);
}

TEST(VectorMerger, DynamicBlobDoesNotPullTheLine)
{
	// Two views of the wall y = 0. In b's scan someone stood 10 cm in front of
	// the wall over x in [1, 2.5]; 50 later scans saw through those cells, so
	// they hold many points but a low n_occupy / n_visit.
	GridVector a = wall({0, 0}, {4, 0}, 0.005, 1);
	GridVector b(TPoint2D(0, 0), TPoint2D(4, 0), GridOptions{});
	for (double x = 0.01; x < 4; x += 0.02) b.addEndpoint({x, 0.0});
	for (double x = 1.01; x < 2.5; x += 0.02) b.addEndpoint({x, 0.1});
	for (int c = 10; c < 25; ++c) b.cell(2, c).n_visit += 50;
	const VectorMerger mg;
	const Line2D weighted = mg.fitLine({&a, &b}, true), plain = mg.fitLine({&a, &b}, false);
	// the line y = 0 with the normal to the right of +x: theta = -pi/2, rho = 0
	EXPECT_NEAR(std::abs(mrpt::math::wrapToPi(weighted.theta + M_PI / 2)), 0.0, 0.002);
	// Weights are the paper's n_occupy/n_visit (~0.1 here against ~0.9 on the
	// wall): the blob's pull is cut by about that factor, not removed.
	EXPECT_GT(std::abs(plain.rho), 0.02);  // the plain fit is pulled 2+ cm towards the blob
	EXPECT_LT(std::abs(weighted.rho), 0.008);
	EXPECT_LT(std::abs(weighted.rho), 0.3 * std::abs(plain.rho));
	const GridVector m = mg.merge(a, b);
	EXPECT_LT(std::abs(m.start().y), 0.008);
	EXPECT_LT(std::abs(m.end().y), 0.008);
	expectTotalsConserved({&a, &b}, m);
	EXPECT_GT(pointsMeanOffset(m), 0.0);  // the blob's points are still there, at their place
}

TEST(VectorMerger, ShortPartIntoALongWallKeepsTheWallsGrid)
{
	// A 20 m wall seen many times, and a new 1 m view of it 2 mm off: the refit
	// line stays within VectorMerger::kRegridTolerance of the wall's grid, so the wall's
	// cells stay where they are (Eq. 6 of the wall unchanged at every point) and
	// only the new part's counts are moved into them.
	GridVector a = wall({0, 0}, {20, 0}, 0.003, 1);
	for (auto& c : a.cells()) c.n_occupy *= 40, c.n_visit *= 40, c.n_acc *= 40, c.x_acc *= 40, c.y_acc *= 40;
	const GridVector b = wall({7.03, 0.002}, {8.04, 0.002}, 0.003, 2);
	const VectorMerger fast;
	const GridVector m = fast.merge(a, b);
	EXPECT_EQ(m.start().x, a.start().x);
	EXPECT_EQ(m.start().y, a.start().y);
	EXPECT_NEAR(m.end().y, a.end().y, 1e-12);
	EXPECT_NEAR(m.length(), a.length(), 1e-9);
	ASSERT_EQ(m.cols(), a.cols());
	expectTotalsConserved({&a, &b}, m);
	// the wall's cells outside b's extent are the wall's, bit for bit
	for (int r = 0; r < m.rows(); ++r)
		for (int c = 0; c < m.cols(); ++c)
			if (c < 69 || c > 81)
			{
				EXPECT_EQ(m.cell(r, c).n_occupy, a.cell(r, c).n_occupy) << r << " " << c;
				EXPECT_EQ(m.cell(r, c).n_visit, a.cell(r, c).n_visit) << r << " " << c;
				EXPECT_EQ(m.cell(r, c).n_acc, a.cell(r, c).n_acc) << r << " " << c;
			}
	// the same merge with a new grid always built (tolerance 0) agrees to within it
	const GridVector r = VectorMerger(GridVectorConfig{}, 0).merge(a, b);
	const double tol = VectorMerger::kRegridTolerance;
	EXPECT_LT(std::hypot(r.start().x - m.start().x, r.start().y - m.start().y), tol);
	EXPECT_LT(std::hypot(r.end().x - m.end().x, r.end().y - m.end().y), tol);
	expectTotalsConserved({&a, &b}, r);
	for (int k = 0; k < r.rows(); ++k)
		for (int c = 1; c + 1 < r.cols(); ++c)
			EXPECT_NEAR(r.cell(k, c).occupancy(r.priorRatio()), m.cell(k, c).occupancy(m.priorRatio()), 0.02)
				<< k << " " << c;
	// a part that moves the line further than the tolerance gets a new grid
	const GridVector once = wall({0, 0}, {20, 0}, 0.003, 4), far = wall({5, 0.12}, {15, 0.12}, 0.003, 3);
	const GridVector moved = fast.merge(once, far);
	EXPECT_GT(std::abs(moved.start().y - once.start().y), 0.005);
	expectTotalsConserved({&once, &far}, moved);
}

TEST(VectorMerger, ExtendingTheWallsEndKeepsItsGrid)
{
	GridVector a = wall({0, 0}, {6, 0}, 0, 1);
	for (auto& c : a.cells()) c.n_occupy *= 20, c.n_visit *= 20, c.n_acc *= 20, c.x_acc *= 20, c.y_acc *= 20;
	const GridVector b = wall({5.5, 0}, {7.25, 0}, 0, 2);
	const GridVector m = VectorMerger().merge(a, b);
	EXPECT_EQ(m.start().x, 0.0);
	EXPECT_NEAR(m.end().x, 7.25, 1e-9);
	EXPECT_NEAR(m.end().y, 0.0, 1e-9);
	EXPECT_EQ(m.cols(), 73);
	expectTotalsConserved({&a, &b}, m);
	for (int r = 0; r < m.rows(); ++r)
		for (int c = 0; c < 55; ++c) EXPECT_EQ(m.cell(r, c).n_visit, a.cell(r, c).n_visit);
}

TEST(VectorMerger, RejectsMixedResolutions)
{
	GridOptions g;
	g.resolution = 0.05;
	const GridVector a({0, 0}, {1, 0}, GridOptions{}), b({0, 0}, {1, 0}, g);
	EXPECT_THROW(VectorMerger().merge(a, b), std::invalid_argument);
	EXPECT_THROW(VectorMerger().merge(std::vector<const GridVector*>{}), std::invalid_argument);
}

TEST(VectorMerger, GuardRefusesAChordAcrossACurvedWall)
{
	// an arc with 0.5 m sagitta over 12 m (R = 36 m, as Intel's corridor walls
	// in its corrected poses): two 6 m pieces, each within its own grid, whose
	// chord would leave the wall up to 0.25 m outside the new grid's band
	const GridVector a = arcPiece(36, -6, 0), b = arcPiece(36, 0, 6);
	const VectorMerger merger;
	EXPECT_GT(merger.wallOffset({&a, &b}), 0.15);
	GridVector out;
	EXPECT_FALSE(merger.tryMerge({&a, &b}, out));
	EXPECT_EQ(out.cols(), 0);  // untouched
	GridVectorConfig paper;
	paper.map.mergeHoldsWall = false;
	EXPECT_TRUE(VectorMerger(paper).tryMerge({&a, &b}, out));
	EXPECT_NEAR(out.length(), 12, 0.1);
	// a gentler bend (2 m pieces of the same arc) and a straight noisy wall are merged
	const GridVector c = arcPiece(36, -2, 0), d = arcPiece(36, 0, 2);
	EXPECT_LT(merger.wallOffset({&c, &d}), 0.05);
	EXPECT_TRUE(merger.tryMerge({&c, &d}, out));
	const GridVector e = wall({0, 0}, {6, 0.05}, 0.02, 1), f = wall({4, 0.1}, {10, 0.0}, 0.02, 2);
	EXPECT_TRUE(merger.tryMerge({&e, &f}, out));
	expectTotalsConserved({&e, &f}, out);
}

TEST(VectorMerger, MergeGreedyTakesTheCandidatesThatHold)
{
	// the base piece of the arc holds with its neighbour but not with the far piece
	const GridVector base = arcPiece(36, -1, 3), near = arcPiece(36, -4, -1), far = arcPiece(36, 3, 9);
	const VectorMerger merger;
	GridVector out;
	const auto taken = merger.mergeGreedy(base, {&far, &near}, out);
	ASSERT_EQ(taken.size(), 1u);
	EXPECT_EQ(taken[0], 1u);
	expectTotalsConserved({&base, &near}, out);
	const auto none = merger.mergeGreedy(base, {}, out);
	EXPECT_TRUE(none.empty());
}

TEST(VectorMerger, UncoveredCellsOfTheMergedGridReadTheConfiguredPrior)
{
	// Two pieces of one wall 1 m apart: Algorithm 2's new grid spans the gap, whose cells no part
	// covers and get no counts (the totals are moved, no prior added). They read the configured
	// prior's ratio, 0.3 / 1.5, not the paper's 1/2.
	GridVectorConfig cfg;
	cfg.grid.priorOccupy = 0.3, cfg.grid.priorVisit = 1.5;
	auto piece = [&](double x0, double x1) {
		GridVector v(TPoint2D(x0, 0), TPoint2D(x1, 0), cfg.grid);
		for (double u = x0 + 0.01; u < x1; u += 0.02) v.addEndpoint({u, 0});
		return v;
	};
	const GridVector a = piece(0, 1), b = piece(2, 3);
	const GridVector m = VectorMerger(cfg).merge(a, b);
	EXPECT_DOUBLE_EQ(m.priorRatio(), double(0.3f) / double(1.5f));
	expectTotalsConserved({&a, &b}, m);
	const auto prof = m.occupancyProfile();
	int empty = 0;
	for (int c = 0; c < m.cols(); ++c)
	{
		bool counts = false;
		for (int r = 0; r < m.rows(); ++r) counts |= m.cell(r, c).n_visit > 0;
		if (counts) continue;
		++empty;
		EXPECT_DOUBLE_EQ(m.cell(m.halfWidth(), c).occupancy(m.priorRatio()), m.priorRatio()) << c;
		EXPECT_NEAR(prof[size_t(c)], m.priorRatio(), 1e-12) << c;  // was 0.5
	}
	EXPECT_GE(empty, 8);  // the 1 m gap at 0.1 m, less the columns the parts' edges reach
	double mean = 0;
	for (double p : prof) mean += p / double(prof.size());
	EXPECT_NEAR(m.pStatic(), mean, 1e-12);
}
