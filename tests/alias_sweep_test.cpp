// AliasSweep (issue 21, item 2): a corridor's repeated recesses seen in part, the covisible share.
#include "match_world.h"

#include "mstep/AliasSweep.h"
#include "mstep/LoopSearch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace gridvector;
using mrpt::math::TPose2D;

namespace
{
using Seg = matchtest::WorldSeg;

// A corridor along x, 2 m wide, with a 0.5 m deep recess of 1 m every `period` metres in its lower wall.
std::vector<Seg> corridor(double period, int n)
{
	std::vector<Seg> w;
	for (int k = 0; k < n; ++k)
	{
		const double x = period * k;
		w.push_back({x, 0, x + period - 1, 0});
		w.push_back({x + period - 1, 0, x + period - 1, -0.5});
		w.push_back({x + period - 1, -0.5, x + period, -0.5});
		w.push_back({x + period, -0.5, x + period, 0});
	}
	w.push_back({period * n, 2, 0, 2});
	return w;
}

// What a robot at `pose` sees of `world`: the parts within `range` metres of it along x, in its frame.
std::vector<MatchSegment> view(const std::vector<Seg>& world, const TPose2D& pose, double range, uint64_t firstId)
{
	std::vector<Seg> seen;
	for (Seg s : world)
	{
		const double lo = pose.x - range, hi = pose.x + range;
		if (std::max(s.x1, s.x2) < lo || std::min(s.x1, s.x2) > hi) continue;
		const auto clip = [&](double& x, double& y, double ox, double oy) {
			const double cx = std::clamp(x, lo, hi);
			if (cx != x && std::abs(ox - x) > 1e-9) y += (oy - y) * (cx - x) / (ox - x);
			x = cx;
		};
		const double x1 = s.x1, y1 = s.y1;
		clip(s.x1, s.y1, s.x2, s.y2);
		clip(s.x2, s.y2, x1, y1);
		if (std::hypot(s.x2 - s.x1, s.y2 - s.y1) > 0.05) seen.push_back(s);
	}
	return matchtest::observe(seen, pose, 0.0, 0, firstId);
}
}  // namespace

TEST(AliasSweep, CovisibleLengthIsWhatBothShowAlongTheDirection)
{
	// a 4 m wall along x with a 1 m crosswise wall at x = 2; B's frame shifted by 1 m: both crosswise walls lie in
	// the slab [1, 4] both cover, the walls along x tell nothing along x
	const std::vector<Seg> w{{0, 0, 4, 0}, {2, 0, 2, 1}};
	const auto a = matchtest::observe(w, TPose2D(0, 0, 0), 0, 0, 1),
			   b = matchtest::observe(w, TPose2D(0, 0, 0), 0, 0, 10);
	EXPECT_NEAR(AliasSweep::covisibleLength(a, b, TPose2D(1, 0, 0), Eigen::Vector2d(1, 0)), 1.0, 1e-9);
	EXPECT_NEAR(AliasSweep::covisibleLength(a, b, TPose2D(5, 0, 0), Eigen::Vector2d(1, 0)), 0.0, 1e-9);
	// along y the walls along x count whole (the slab is along y), the crosswise ones tell nothing
	EXPECT_NEAR(AliasSweep::covisibleLength(a, b, TPose2D(1, 0, 0), Eigen::Vector2d(0, 1)), 4.0, 1e-9);
}

TEST(AliasSweep, FindsTheShiftThatLaysOneViewOverTheOther)
{
	// scans one period (5 m) apart, each seeing 6 m either way: the estimate says they are at the same place,
	// where the views coincide and match more than at the true shift
	const auto w = corridor(5.0, 8);
	const TPose2D xa(15.5, 1, 0), xb(20.5, 1, 0);
	const auto a = view(w, xa, 6.0, 1), b = view(w, xb, 6.0, 1000);
	const VectorMatcher matcher;
	const MatchResult wrong = matcher.match(a, b, TPose2D(0.2, 0.05, 0.02));
	ASSERT_TRUE(wrong.ok()) << toString(wrong.status);
	ASSERT_LT(std::hypot(wrong.pose.x, wrong.pose.y), 0.1);  // the alias: the views laid over each other
	const MatchResult right = matcher.match(a, b, xb - xa);
	ASSERT_TRUE(right.ok()) << toString(right.status);
	EXPECT_GT(wrong.matchedLength, right.matchedLength);  // the matched length prefers the alias
	const AliasSweep sweep(matcher, MStepOptions{}.loopSearchAmbiguity);
	EXPECT_TRUE(sweep.aliased(a, b, wrong.pose, wrong.information, wrong.pairs, 6.0));
	EXPECT_TRUE(sweep.aliased(a, b, right.pose, right.information, right.pairs, 6.0));
	// within less than a period the registration is unique
	EXPECT_FALSE(sweep.aliased(a, b, right.pose, right.information, right.pairs, 3.0));
	// and the loop search refuses the place over a window of more than a period
	MStepOptions o;
	o.loopSearchVectors = 40;
	const LoopSearch ls(MatcherOptions{}, o);
	EXPECT_FALSE(ls.search(a, b, TPose2D(0.2, 0.05, 0.02), LoopWindow{6.0, 0.3}).ok());
}

TEST(AliasSweep, AUniquePlaceIsNotAliased)
{
	// the same corridor with its recesses at irregular places: no other shift explains the view
	std::vector<Seg> w;
	double x = 0;
	for (double len : {3.0, 6.5, 2.0, 4.5, 7.0, 2.5})
	{
		w.push_back({x, 0, x + len, 0});
		w.push_back({x + len, 0, x + len, -0.5});
		w.push_back({x + len, -0.5, x + len + 1, -0.5});
		w.push_back({x + len + 1, -0.5, x + len + 1, 0});
		x += len + 1;
	}
	w.push_back({x, 2, 0, 2});
	const TPose2D xa(12, 1, 0), xb(14, 1, 0.05);
	const auto a = view(w, xa, 8.0, 1), b = view(w, xb, 8.0, 1000);
	const VectorMatcher matcher;
	const MatchResult r = matcher.match(a, b, xb - xa);
	ASSERT_TRUE(r.ok()) << toString(r.status);
	EXPECT_FALSE(
		AliasSweep(matcher, MStepOptions{}.loopSearchAmbiguity).aliased(a, b, r.pose, r.information, r.pairs, 6.0));
}
