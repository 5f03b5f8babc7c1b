// Eq. 8, Fig. 2: wipe triangle parts a/b/c and its region-by-region rasterisation.
#include "map/WipeTriangle.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <limits>
#include <random>

using namespace gridvector;
using mrpt::math::TPoint2D;

namespace
{
// A wall at y = 2 seen from the origin: open space (the sensor) on its left.
const TPoint2D O(0, 0), S(1, 2), E(-1, 2);

GridOptions grid01()
{
	GridOptions g;
	g.resolution = 0.1;
	g.halfWidth = 1;
	return g;
}

// The part forEachCell reports for each cell of m (row-major; 0 = not reported), each cell at most once.
std::vector<int> walked(const WipeTriangle& t, const GridVector& m)
{
	std::vector<int> seen(m.cells().size(), 0);
	t.forEachCell(m, [&](int r, int c, WipePart p) {
		EXPECT_EQ(seen[size_t(r) * m.cols() + c], 0) << "cell reported twice";
		seen[size_t(r) * m.cols() + c] = int(p);
	});
	return seen;
}
}  // namespace

TEST(WipeTriangle, ClassifiesPartsABC)
{
	const WipeTriangle t(O, S, E, 0.05);
	ASSERT_FALSE(t.degenerate());
	EXPECT_EQ(t.classify({0, 1.0}), WipePart::Visited);  // between sensor and wall: b
	EXPECT_EQ(t.classify({0, 1.9}), WipePart::Visited);
	EXPECT_EQ(t.classify({0, 2.0}), WipePart::Hit);  // on the wall: c
	EXPECT_EQ(t.classify({0, 1.96}), WipePart::Hit);
	EXPECT_EQ(t.classify({0, 2.04}), WipePart::Hit);  // just behind, within the band: c
	EXPECT_EQ(t.classify({0, 2.1}), WipePart::Outside);  // behind the wall: a
	EXPECT_EQ(t.classify({0, -0.5}), WipePart::Outside);  // behind the sensor
	EXPECT_EQ(t.classify({1.5, 1.0}), WipePart::Outside);  // beside the fan
	EXPECT_EQ(t.classify({0.5, 1.0}), WipePart::Visited);  // on the fan's edge ray
	EXPECT_EQ(t.classify({0, 0}), WipePart::Visited);  // the apex itself
}

// A wall along y = 0 from (1, 0) to (3, 0) seen from 5 cm off its line: grazing incidence
// (d(O) = hitBand, so the band |d| <= hitBand alone would reach twice the range along the rays).
TEST(WipeTriangle, GrazingHitStaysNearTheSegment)
{
	const TPoint2D o(0, 0.05), s(1, 0), e(3, 0);
	const WipeTriangle t(o, s, e, 0.05);
	ASSERT_FALSE(t.degenerate());
	const TPoint2D far(o.x + 1.9 * (e.x - o.x), o.y + 1.9 * (e.y - o.y));  // on the ray to E, 2.7 m past E
	ASSERT_NEAR(far.y, -0.045, 1e-12);  // within the band of the line, in the cone
	EXPECT_EQ(t.classify(far), WipePart::Outside);  // no beam ended there
	EXPECT_EQ(t.classify({o.x + 1.01 * (e.x - o.x), o.y + 1.01 * (e.y - o.y)}), WipePart::Hit);  // 3 cm past E
	EXPECT_EQ(t.classify({o.x + 1.03 * (e.x - o.x), o.y + 1.03 * (e.y - o.y)}), WipePart::Outside);  // 9 cm past E
	EXPECT_EQ(t.classify({2, 0}), WipePart::Hit);  // on the wall
	EXPECT_EQ(t.classify({2, 0.01}), WipePart::Hit);  // just in front
	EXPECT_EQ(t.classify({2, -0.004}), WipePart::Hit);  // just behind (in the cone)
	EXPECT_EQ(t.classify({0.5, 0.03}), WipePart::Visited);  // between the sensor and S: passed, not hit
	EXPECT_EQ(t.classify({0.98, 0.0015}), WipePart::Hit);  // 2 cm before S, in the box
	// the bounding box hugs the triangle and the box around SE, not the rays' far reach
	EXPECT_NEAR(t.minX(), 0.0, 1e-12);
	EXPECT_NEAR(t.maxX(), 3.05, 1e-9);
	EXPECT_NEAR(t.maxY(), 0.05, 1e-12);
	EXPECT_GE(t.minY(), -0.05 - 1e-12);
	EXPECT_TRUE(t.misses(3.1, -0.1, 6, 0.1));  // behind E along the rays
	EXPECT_FALSE(t.misses(3.0, -0.1, 6, 0.1));
}

// Both ends seen within 45 deg of the normal: the parts are those of the band |d| <= hitBand alone.
TEST(WipeTriangle, NearNormalIncidenceKeepsTheBand)
{
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> U(-3, 3), D(0.3, 4);
	size_t hits = 0, compared = 0;
	for (int trial = 0; trial < 200; ++trial)
	{
		// wall on y = 0 from x = sx to x = ex, sensor at (ox, dO) with |ex - ox|, |sx - ox| <= dO
		const double dO = D(rng), ox = U(rng), len = D(rng);
		const double sx = ox + std::uniform_real_distribution<double>(-dO, dO - std::min(len, 2 * dO))(rng);
		const double ex = std::min(sx + len, ox + dO), band = 0.05 + 0.1 * (trial % 3);
		ASSERT_LE(std::abs(sx - ox), dO + 1e-12);
		ASSERT_LE(std::abs(ex - ox), dO + 1e-12);
		const WipeTriangle t({ox, dO}, {sx, 0}, {ex, 0}, band);
		for (int k = 0; k < 200; ++k)
		{
			const TPoint2D p(std::uniform_real_distribution<double>(sx - 1, ex + 1)(rng),
							 std::uniform_real_distribution<double>(-2 * band, 3 * band)(rng));
			const double a = (p.x - ox) * (0 - dO) - (p.y - dO) * (sx - ox);  // sides of the rays O->S, O->E
			const double b = (p.x - ox) * (0 - dO) - (p.y - dO) * (ex - ox);
			if (!(a <= -1e-9 && b >= 1e-9)) continue;  // strictly inside the cone
			const WipePart band_only = p.y > band     ? WipePart::Visited
									   : p.y >= -band ? WipePart::Hit
													  : WipePart::Outside;
			if (std::abs(std::abs(p.y) - band) < 1e-9) continue;  // on the band's edge: rounding
			EXPECT_EQ(t.classify(p), band_only) << trial << " " << p.x << " " << p.y;
			hits += band_only == WipePart::Hit;
			++compared;
		}
	}
	EXPECT_GT(compared, 5000u);
	EXPECT_GT(hits, 1000u);
}

TEST(WipeTriangle, DegenerateWhenSensorOnTheLine)
{
	EXPECT_TRUE(WipeTriangle({3, 2}, S, E, 0.05).degenerate());
	EXPECT_TRUE(WipeTriangle(O, S, S, 0.05).degenerate());
	const WipeTriangle t({3, 2}, S, E, 0.05);
	EXPECT_EQ(t.classify({0, 2}), WipePart::Outside);
}

// A sensor or endpoint that is not finite (a diverged pose) makes no triangle: with NaN every comparison
// of the parts' predicate fails and each cell of a map vector would be reported "Visited".
TEST(WipeTriangle, NonFiniteInputIsDegenerate)
{
	const double nan = std::nan(""), inf = std::numeric_limits<double>::infinity();
	for (const auto& [o, s, e] : {std::array<TPoint2D, 3>{TPoint2D(nan, 0), S, E},
								  {O, TPoint2D(1, nan), E},
								  {O, S, TPoint2D(inf, 2)},
								  {TPoint2D(0, -inf), S, E},
								  {O, TPoint2D(inf, inf), E}})
	{
		const WipeTriangle t(o, s, e, 0.05);
		EXPECT_TRUE(t.degenerate()) << o.x << " " << o.y << " " << s.x << " " << s.y << " " << e.x << " " << e.y;
		EXPECT_EQ(t.classify({0, 1}), WipePart::Outside);
		GridVector m({-0.3, 1.0}, {0.3, 1.0}, grid01());
		EXPECT_EQ(t.apply(m), 0u);
	}
	EXPECT_TRUE(WipeTriangle(O, S, E, nan).degenerate());
}

TEST(WipeTriangle, CoincidentWallRowsGetHitVisitUntouched)
{
	// The same wall already in the map: row h on it, row h+1 in front (left,
	// towards the sensor), row h-1 behind.
	GridVector m(S, E, grid01());
	const std::vector<GridCell> before = m.cells();
	const WipeTriangle t(O, S, E, 0.05);
	const size_t n = t.apply(m);
	EXPECT_EQ(n, size_t(2 * m.cols()));
	for (int c = 0; c < m.cols(); ++c)
	{
		const auto& hit = m.cell(1, c);
		EXPECT_FLOAT_EQ(hit.n_occupy, before[size_t(m.cols() + c)].n_occupy + 1) << c;
		EXPECT_FLOAT_EQ(hit.n_visit, 2.f);
		EXPECT_FLOAT_EQ(m.cell(2, c).n_occupy, 0.5f);  // in front: b
		EXPECT_FLOAT_EQ(m.cell(2, c).n_visit, 2.f);
		EXPECT_FLOAT_EQ(m.cell(0, c).n_visit, 1.f);  // behind: a
		EXPECT_FLOAT_EQ(m.cell(0, c).n_occupy, 0.5f);
	}
}

TEST(WipeTriangle, ObjectInsideTheFanIsOnlyVisited)
{
	// A vector crossing the fan between sensor and wall (someone who left).
	GridVector person({-0.3, 1.0}, {0.3, 1.0}, grid01());
	const WipeTriangle t(O, S, E, 0.05);
	t.apply(person);
	for (const auto& c : person.cells())
	{
		EXPECT_FLOAT_EQ(c.n_occupy, 0.5f);
		EXPECT_FLOAT_EQ(c.n_visit, 2.f);
	}
}

TEST(WipeTriangle, PartialOverlapOnlyTouchesCellsInside)
{
	// A long vector at y = 1 from x = -3 to 3: only the part within |x| <= 0.5 is in the fan.
	GridVector m({3, 1}, {-3, 1}, grid01());
	const WipeTriangle t(O, S, E, 0.05);
	t.apply(m);
	for (int r = 0; r < m.rows(); ++r)
		for (int c = 0; c < m.cols(); ++c)
		{
			const TPoint2D p = m.cellCentre(r, c);
			const bool inside = std::abs(p.x) <= p.y / 2 + 1e-9;
			EXPECT_FLOAT_EQ(m.cell(r, c).n_visit, inside ? 2.f : 1.f) << p.x << " " << p.y;
		}
}

// The closed-form row intervals must give exactly the brute-force per-cell classification.
TEST(WipeTriangle, RasterisationEqualsBruteForce)
{
	std::mt19937 rng(7);
	std::uniform_real_distribution<double> U(-4, 4);
	size_t checked = 0, nonEmpty = 0;
	for (int trial = 0; trial < 400; ++trial)
	{
		const TPoint2D o(U(rng), U(rng)), s(U(rng), U(rng)), e(U(rng), U(rng));
		const WipeTriangle t(o, s, e, 0.05 + 0.1 * (trial % 3));
		if (t.degenerate()) continue;
		GridOptions g = grid01();
		g.halfWidth = trial % 3;
		const GridVector m({U(rng), U(rng)}, {U(rng), U(rng)}, g);
		const std::vector<int> seen = walked(t, m);
		for (int r = 0; r < m.rows(); ++r)
			for (int c = 0; c < m.cols(); ++c)
			{
				const WipePart want = t.classify(m.cellCentre(r, c));
				EXPECT_EQ(seen[size_t(r) * m.cols() + c], int(want)) << trial << " r" << r << " c" << c;
				nonEmpty += want != WipePart::Outside;
				++checked;
			}
	}
	EXPECT_GT(checked, 10000u);
	EXPECT_GT(nonEmpty, 500u);
}

// As above with the sensor within a few hit bands of the new vector's line (the box around SE cuts parts b and c).
TEST(WipeTriangle, RasterisationEqualsBruteForceAtGrazingIncidence)
{
	std::mt19937 rng(11);
	std::uniform_real_distribution<double> U(-4, 4), off(-0.3, 0.3);
	size_t checked = 0, hit = 0, visited = 0;
	for (int trial = 0; trial < 400; ++trial)
	{
		const TPoint2D s(U(rng), U(rng)), e(U(rng), U(rng));
		// O at S + k dir on the new vector's line, moved h off it
		const double len = std::hypot(e.x - s.x, e.y - s.y), k = U(rng), h = off(rng);
		if (len < 0.5) continue;
		const TPoint2D dir((e.x - s.x) / len, (e.y - s.y) / len);
		const TPoint2D o(s.x + k * dir.x - h * dir.y, s.y + k * dir.y + h * dir.x);
		const WipeTriangle t(o, s, e, 0.05 + 0.1 * (trial % 3));
		if (t.degenerate()) continue;
		GridOptions g = grid01();
		g.halfWidth = 1 + trial % 3;
		// a map vector along the new one's line, past its ends
		const GridVector m({s.x - 2 * dir.x, s.y - 2 * dir.y}, {e.x + 2 * dir.x, e.y + 2 * dir.y}, g);
		const std::vector<int> seen = walked(t, m);
		for (int r = 0; r < m.rows(); ++r)
			for (int c = 0; c < m.cols(); ++c)
			{
				const TPoint2D p = m.cellCentre(r, c);
				const WipePart want = t.classify(p);
				EXPECT_EQ(seen[size_t(r) * m.cols() + c], int(want)) << trial << " r" << r << " c" << c;
				hit += want == WipePart::Hit;
				visited += want == WipePart::Visited;
				if (want != WipePart::Outside)  // inside the bounding box, and never missed
				{
					EXPECT_TRUE(p.x >= t.minX() - 1e-9 && p.x <= t.maxX() + 1e-9 && p.y >= t.minY() - 1e-9 &&
								p.y <= t.maxY() + 1e-9)
						<< trial;
					EXPECT_FALSE(t.misses(p.x - 1e-3, p.y - 1e-3, p.x + 1e-3, p.y + 1e-3)) << trial;
				}
				++checked;
			}
	}
	EXPECT_GT(checked, 20000u);
	EXPECT_GT(hit, 2000u);
	EXPECT_GT(visited, 500u);
}

TEST(WipeTriangle, BoundingBoxContainsTheFanAndBand)
{
	const WipeTriangle t(O, S, E, 0.1);
	EXPECT_LE(t.minX(), -1.0);
	EXPECT_GE(t.maxX(), 1.0);
	EXPECT_LE(t.minY(), 0.0);
	EXPECT_GE(t.maxY(), 2.1 - 1e-9);
	EXPECT_LT(t.maxY(), 2.2);
}

TEST(WipeTriangle, MissesOnlyBoxesBeyondAnEdge)
{
	// sensor at the origin, new vector from (2, -1) to (2, 1), hit band 0.05
	const WipeTriangle tri({0, 0}, {2, -1}, {2, 1}, 0.05);
	EXPECT_TRUE(tri.misses(0.5, -3, 2, -1.2));  // beyond the edge O-S
	EXPECT_FALSE(tri.misses(-3, -1, -0.5, 1));  // behind the sensor: no edge separates it (conservative)
	EXPECT_TRUE(tri.misses(2.2, -1, 3, 1));  // behind the vector, beyond the hit band
	EXPECT_TRUE(tri.misses(0, 1.5, 2, 3));  // beside the cone
	EXPECT_FALSE(tri.misses(1, -0.2, 1.2, 0.2));  // inside
	EXPECT_FALSE(tri.misses(2.02, -0.1, 3, 0.1));  // reaches into the hit band
	EXPECT_FALSE(tri.misses(-5, -5, 5, 5));  // contains the triangle
	// never rejects a box holding a point the triangle classifies as b or c
	for (double x = -0.5; x <= 2.5; x += 0.05)
		for (double y = -1.5; y <= 1.5; y += 0.05)
			if (tri.classify({x, y}) != WipePart::Outside)
			{
				EXPECT_FALSE(tri.misses(x - 0.01, y - 0.01, x + 0.01, y + 0.01));
			}
}

// Cell centres on, or within 1e-9 of, the cone's edge rays (a = 0, b = 0): the walk's row intervals are
// widened against rounding, and every cell it reports must still be one classify() puts in b or c, and
// the other way round. The grid is shifted by a_off (S - O) + b_off (E - O) from a lattice through which
// both edge rays run, so the centres on the rays get a = a_off or b = b_off (to ~1e-15).
TEST(WipeTriangle, RasterisationEqualsClassifyOnTheConeEdges)
{
	std::mt19937 rng(5);
	std::uniform_int_distribution<int> step(-3, 3), reach(4, 30), cols(20, 80);
	const double offsets[] = {0,      1e-13, -1e-13, 1e-12, -1e-12, 3e-12, -3e-12, 1e-10,
							  -1e-10, 5e-10, -5e-10, 9e-10, -9e-10, 2e-9,  -2e-9};
	size_t checked = 0, inside = 0, nearEdgeOut = 0, nearEdgeIn = 0;
	for (int trial = 0; trial < 600; ++trial)
	{
		GridOptions g = grid01();
		g.halfWidth = 2 + trial % 5;
		const int n = cols(rng);
		const GridVector lattice({0, 0}, {n * g.resolution, 0}, g);  // its centres: the lattice
		const int r0 = int(rng() % unsigned(lattice.rows())), c0 = int(rng() % unsigned(n));
		int di1 = step(rng), dj1 = step(rng), di2 = step(rng), dj2 = step(rng);
		if (di1 * dj2 - dj1 * di2 == 0) continue;  // parallel rays
		const TPoint2D o = lattice.cellCentre(r0, c0);
		const double k1 = reach(rng) * g.resolution, k2 = reach(rng) * g.resolution;
		const TPoint2D s(o.x + k1 * di1, o.y + k1 * dj1), e(o.x + k2 * di2, o.y + k2 * dj2);
		const WipeTriangle t(o, s, e, 0.05 + 0.1 * (trial % 3));
		if (t.degenerate()) continue;
		const double aOff = offsets[rng() % std::size(offsets)], bOff = offsets[rng() % std::size(offsets)];
		const TPoint2D w(aOff * (s.x - o.x) + bOff * (e.x - o.x), aOff * (s.y - o.y) + bOff * (e.y - o.y));
		const GridVector m({w.x, w.y}, {w.x + n * g.resolution, w.y}, g);
		const std::vector<int> seen = walked(t, m);
		const double det = (s.x - o.x) * (e.y - o.y) - (s.y - o.y) * (e.x - o.x);
		for (int r = 0; r < m.rows(); ++r)
			for (int c = 0; c < m.cols(); ++c)
			{
				const TPoint2D p = m.cellCentre(r, c);
				const WipePart want = t.classify(p);
				EXPECT_EQ(seen[size_t(r) * m.cols() + c], int(want))
					<< trial << " r" << r << " c" << c << " offsets " << aOff << " " << bOff;
				// cone coordinates, for the counts: a along S - O, b along E - O
				const double a = ((p.x - o.x) * (e.y - o.y) - (p.y - o.y) * (e.x - o.x)) / det;
				const double b = ((s.x - o.x) * (p.y - o.y) - (s.y - o.y) * (p.x - o.x)) / det;
				const bool nearEdge = (std::abs(a) < 3e-9 && b > -3e-9) || (std::abs(b) < 3e-9 && a > -3e-9);
				nearEdgeOut += nearEdge && want == WipePart::Outside;
				nearEdgeIn += nearEdge && want != WipePart::Outside;
				inside += want != WipePart::Outside;
				++checked;
			}
	}
	EXPECT_GT(checked, 100000u);
	EXPECT_GT(inside, 10000u);
	EXPECT_GT(nearEdgeOut, 500u);  // centres just outside an edge ray (within the walk's old 1e-9 slack)
	EXPECT_GT(nearEdgeIn, 500u);  // and on or just inside one
}
