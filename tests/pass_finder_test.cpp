// PassFinder (Sec. 4.3, the topology change): earlier poses near the current one, grouped into passes.
#include "mstep/PassFinder.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace gridvector;
using mrpt::math::TPose2D;

namespace
{
// Two passes along y = 0 (x = 0..4, poses 0-8 facing +x), a walk away (9-18), and back along y = 0 facing -x (19-27),
// then pose 28 at (2, 0) facing +x.
std::vector<TPose2D> twoPasses()
{
	std::vector<TPose2D> p;
	for (int k = 0; k <= 8; ++k) p.emplace_back(0.5 * k, 0, 0);
	for (int k = 1; k <= 10; ++k) p.emplace_back(4, 5.0 * k, M_PI / 2);
	for (int k = 8; k >= 0; --k) p.emplace_back(0.5 * k, 0.1, M_PI);
	p.emplace_back(2, 0, 0);
	return p;
}

std::vector<PassFinder::Pass> passesOf(const std::vector<TPose2D>& poses, uint32_t last, double headingWeight)
{
	PassFinder f(2.0, headingWeight);
	std::vector<PassFinder::Pass> out;
	for (uint32_t i = 0; i <= last; ++i)
	{
		const auto& p = f.next(i, poses, 3, 2, [&](uint32_t j) {
			return std::hypot(poses[i].x - poses[j].x, poses[i].y - poses[j].y) < 1.2;
		});
		if (i == last) out = p;
	}
	return out;
}
}  // namespace

TEST(PassFinder, GroupsTheNearPosesIntoPassesByTime)
{
	const auto poses = twoPasses();
	const auto passes = passesOf(poses, 28, 1.0);
	ASSERT_EQ(passes.size(), 2u);  // the first pass, the way back (the walk away is far)
	EXPECT_EQ(passes[0].lo, 2u);  // x in (0.8, 3.2): poses 2-6 of the first pass
	EXPECT_EQ(passes[0].hi, 6u);
	EXPECT_EQ(passes[1].lo, 21u);  // and 21-24 of the way back (25 is near too, but within the gap: 25 + 3 < 28 fails)
	EXPECT_EQ(passes[1].hi, 24u);
	for (const auto& p : passes)
	{
		EXPECT_EQ(p.members.front(), p.lo);
		EXPECT_EQ(p.members.back(), p.hi);
		EXPECT_TRUE(std::is_sorted(p.members.begin(), p.members.end()));
	}
	EXPECT_EQ(passes[0].nearest, 4u);  // (2, 0) itself
}

TEST(PassFinder, NearestInViewWeighsTheHeading)
{
	auto poses = twoPasses();
	poses[4].phi = M_PI;  // the first pass's pose at (2, 0) faces away from pose 28; its neighbours do not
	EXPECT_EQ(passesOf(poses, 28, 0.0)[0].nearest, 4u);  // position only
	const uint32_t n = passesOf(poses, 28, 1.0)[0].nearest;
	EXPECT_TRUE(n == 3u || n == 5u) << n;  // 0.5 m off but facing the same way
}

TEST(PassFinder, LeavesOutTheRecentPoses)
{
	const auto poses = twoPasses();
	for (const auto& p : passesOf(poses, 6, 1.0)) EXPECT_LT(p.hi + 3, 6u);  // j + gap < i
}

// kRecentPasses: the first pass through the place and the most recent ones, however many passes there are.
TEST(PassFinder, RegistersTheFirstAndTheMostRecentPassesOnly)
{
	for (size_t n = 1; n <= 1 + kRecentPasses; ++n)
		for (size_t k = 0; k < n; ++k) EXPECT_TRUE(PassFinder::registeredPass(k, n)) << k << " of " << n;
	const size_t n = 40;
	size_t kept = 0;
	for (size_t k = 0; k < n; ++k) kept += PassFinder::registeredPass(k, n);
	EXPECT_EQ(kept, 1 + kRecentPasses);
	EXPECT_TRUE(PassFinder::registeredPass(0, n));
	EXPECT_TRUE(PassFinder::registeredPass(n - 1, n));
	EXPECT_FALSE(PassFinder::registeredPass(1, n));
	EXPECT_FALSE(PassFinder::registeredPass(n - 1 - kRecentPasses, n));
}
