// LoopSearch (Sec. 4.2, issue 5): corner hypotheses, far-off priors, corridor and aliasing rejection.
#include "em_world.h"
#include "match_world.h"

#include "mstep/LoopSearch.h"

#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>

using namespace gridvector;
using emtest::TPose2D;

namespace
{
using Seg = matchtest::WorldSeg;

/** `world` seen exactly from `pose`. */
std::vector<MatchSegment> inFrame(const std::vector<Seg>& world, const TPose2D& pose, uint64_t firstId)
{
	return matchtest::observe(world, pose, 0.0, 0, firstId);
}

// An L-shaped room with an alcove: unique corners.
std::vector<Seg> room()
{
	return {{0, 0, 6, 0}, {6, 0, 6, 2}, {6, 2, 4, 2}, {4, 2, 4, 5}, {4, 5, 0, 5}, {0, 5, 0, 0}, {1, 3, 2, 3}};
}

double poseError(const TPose2D& a, const TPose2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }
}  // namespace

TEST(LoopSearch, FindsThePoseFromAFarOffPrior)
{
	const TPose2D xa(1, 1, 0.2), xb(3, 1.5, 2.0);
	const auto a = inFrame(room(), xa, 1), b = inFrame(room(), xb, 100);
	const TPose2D truth = xb - xa;
	// prior 1.5 m and 40 deg off: outside the matcher's own basin
	const TPose2D prior(truth.x + 1.2, truth.y - 0.9, truth.phi + 0.7);
	MStepOptions o;
	const LoopSearch ls(MatcherOptions{}, o);
	const VectorMatcher plain;
	EXPECT_GT(poseError(plain.match(a, b, prior).pose, truth), 0.2);  // the plain matcher is lost
	const auto hyp = ls.hypotheses(a, b, prior, LoopWindow{3.0, M_PI});
	ASSERT_FALSE(hyp.empty());
	EXPECT_LE(int(hyp.size()), o.loopSearchHypotheses);
	const MatchResult r = ls.search(a, b, prior, LoopWindow{3.0, M_PI});
	ASSERT_TRUE(r.ok()) << toString(r.status);
	EXPECT_LT(poseError(r.pose, truth), 0.01);
	EXPECT_LT(std::abs(mrpt::math::wrapToPi(r.pose.phi - truth.phi)), 0.005);
}

TEST(LoopSearch, WindowExcludesHypotheses)
{
	const TPose2D xa(1, 1, 0.2), xb(3, 1.5, 2.0);
	const auto a = inFrame(room(), xa, 1), b = inFrame(room(), xb, 100);
	const TPose2D truth = xb - xa;
	const TPose2D prior(truth.x + 1.2, truth.y - 0.9, truth.phi + 0.7);
	const LoopSearch ls(MatcherOptions{}, MStepOptions{});
	// a window too small to contain the true pose yields no loop edge
	EXPECT_FALSE(ls.search(a, b, prior, LoopWindow{0.5, 0.2}).ok());
	for (const TPose2D& h : ls.hypotheses(a, b, prior, LoopWindow{0.5, 0.2}))
	{
		EXPECT_LE(poseError(h, prior), 0.5 + 1e-9);
		EXPECT_LE(std::abs(mrpt::math::wrapToPi(h.phi - prior.phi)), 0.2 + 1e-9);
	}
}

TEST(LoopSearch, RejectsACorridorThatSlides)
{
	// two long parallel walls: the translation along them is not observable
	const std::vector<Seg> corridor{{0, 0, 20, 0}, {20, 2, 0, 2}};
	const TPose2D xa(5, 1, 0), xb(8, 1, 0);
	const auto a = inFrame(corridor, xa, 1), b = inFrame(corridor, xb, 100);
	const LoopSearch ls(MatcherOptions{}, MStepOptions{});
	const MatchResult r = ls.search(a, b, xb - xa, LoopWindow{3.0, M_PI});
	EXPECT_FALSE(r.ok());
}

TEST(LoopSearch, RejectsAliasedPlaces)
{
	// a corridor with identical recesses every 3 m: shifted by one period it matches as well
	std::vector<Seg> w;
	for (int k = 0; k < 6; ++k)
	{
		const double x = 3.0 * k;
		w.push_back({x, 0, x + 2, 0});
		w.push_back({x + 2, 0, x + 2, -0.5});
		w.push_back({x + 2, -0.5, x + 3, -0.5});
		w.push_back({x + 3, -0.5, x + 3, 0});
	}
	w.push_back({18, 2, 0, 2});
	const TPose2D xa(7.5, 1, 0), xb(8.0, 1, 0.05);
	const auto a = inFrame(w, xa, 1), b = inFrame(w, xb, 1000);
	MStepOptions o;
	o.loopSearchVectors = 40;  // the short recess walls make the corners
	const LoopSearch ls(MatcherOptions{}, o);
	const TPose2D truth = xb - xa;
	// with a window smaller than the period the place is unique ...
	const MatchResult local = ls.search(a, b, truth, LoopWindow{1.0, 0.3});
	ASSERT_TRUE(local.ok()) << toString(local.status);
	EXPECT_LT(poseError(local.pose, truth), 0.02);
	// ... a window over several periods sees the repetition and refuses
	EXPECT_FALSE(ls.search(a, b, truth, LoopWindow{4.0, 0.3}).ok());
}
