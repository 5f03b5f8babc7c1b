// LoopClosure: the loop search's orchestration over the trajectory (windows, links between passes).
#include "mstep/LoopClosure.h"
#include "extraction/VectorExtractor.h"
#include "room_loop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace gridvector;
using mrpt::math::TPose2D;

namespace
{
Poses straight(size_t n, double step)
{
	Poses p;
	for (size_t k = 0; k < n; ++k) p.emplace_back(step * double(k), 0, 0);
	return p;
}

Constraint edge(uint32_t from, uint32_t to, double degeneracy = 0.5)
{
	Constraint c;
	c.from = from;
	c.to = to;
	c.kind = EdgeKind::Overlap;
	c.degeneracy = degeneracy;
	return c;
}
}  // namespace

// The window grows with the odometry model along the path, between its floor and loop_search_max_radius.
TEST(LoopClosure, TheWindowGrowsAlongThePathBetweenItsBounds)
{
	const GridVectorConfig cfg;
	ConstraintSet book{cfg.matcher};
	const ProgressFn none;
	LoopClosure lc(cfg, book, none);
	lc.setOdometry(straight(2001, 0.5));
	const auto& o = cfg.posegraph;
	const double k = cfg.mstep.loopSearchSigmas;
	EXPECT_EQ(lc.windowOf(0, 1).translation, kLoopWindowMinTranslation);
	EXPECT_GE(lc.windowOf(0, 1).rotation, kLoopWindowMinRotationDeg * M_PI / 180);
	const uint32_t mid = uint32_t(std::ceil(1.5 * kLoopWindowMinTranslation / (k * o.odometrySigmaXYPerM) / 0.5));
	ASSERT_LT(k * o.odometrySigmaXYPerM * 0.5 * mid, cfg.mstep.loopSearchMaxRadius);
	EXPECT_NEAR(lc.windowOf(0, mid).translation, k * o.odometrySigmaXYPerM * 0.5 * mid, 1e-9);
	EXPECT_EQ(lc.windowOf(0, 2000).translation, cfg.mstep.loopSearchMaxRadius);
	EXPECT_EQ(lc.windowOf(0, 2000).rotation, M_PI);
	EXPECT_LT(lc.windowOf(0, mid).rotation, lc.windowOf(0, 2 * mid).rotation + 1e-12);
	EXPECT_EQ(lc.windowOf(100, 101).translation, lc.windowOf(0, 1).translation);  // the path between them counts
}

// mstep.loop_search_weak_links: a corridor-degenerate or rejected edge does not fix the place.
TEST(LoopClosure, WeakLinksDoNotFixThePlace)
{
	GridVectorConfig cfg;
	ConstraintSet book{cfg.matcher};
	const ProgressFn none;
	const LoopClosure on(cfg, book, none);
	Constraint rejected = edge(0, 1);
	rejected.rejected = true;
	EXPECT_TRUE(on.fixesPlace(edge(0, 1)));
	EXPECT_FALSE(on.fixesPlace(edge(0, 1, 0.5 * cfg.matcher.degenerateRatio)));
	EXPECT_FALSE(on.fixesPlace(rejected));
	cfg.mstep.loopSearchWeakLinks = false;
	const LoopClosure off(cfg, book, none);
	EXPECT_TRUE(off.fixesPlace(edge(0, 1, 0.5 * cfg.matcher.degenerateRatio)));
	EXPECT_TRUE(off.fixesPlace(rejected));
}

// An edge of this M-step before verifyOverlaps links two places only provisionally.
TEST(LoopClosure, AnUnverifiedEdgeLinksThePlacesOnlyProvisionally)
{
	const GridVectorConfig cfg;
	ConstraintSet book{cfg.matcher};
	const ProgressFn none;
	const LoopClosure lc(cfg, book, none);
	using Link = LoopClosure::Link;
	book.edges[{5, 40}] = edge(5, 40);
	EXPECT_EQ(lc.linked(0, 10, 35, 45, {}), Link::Verified);
	EXPECT_EQ(lc.linked(0, 10, 35, 45, {{5, 40}}), Link::Unverified);
	EXPECT_EQ(lc.linked(6, 10, 35, 45, {}), Link::None);  // j outside the range
	EXPECT_EQ(lc.linked(0, 10, 41, 45, {}), Link::None);  // i outside the range
	book.edges[{6, 41}] = edge(6, 41, 0.5 * cfg.matcher.degenerateRatio);  // a corridor slide
	EXPECT_EQ(lc.linked(0, 10, 35, 45, {{5, 40}}), Link::Unverified);
	book.edges[{7, 42}] = edge(7, 42);
	EXPECT_EQ(lc.linked(0, 10, 35, 45, {{5, 40}}), Link::Verified);
}

// MStep::closeLoopsByReach's rounds: the path up to which the window covers its drift, and a maximum path that
// keeps longer loops out of a round.
TEST(LoopClosure, ARoundSearchesOnlyLoopsUpToItsPath)
{
	const GridVectorConfig cfg;
	const ProgressFn none;
	const gvtest::RoomLoop world;
	const VectorExtractor ex(cfg.extraction, cfg.grid);
	Scans scans;
	uint64_t id = 0;
	for (const auto& t : world.truth)
	{
		scans.push_back(MatchSegment::fromVectors(ex.extract(gvtest::castScan(t, gvtest::clutteredRoom())).vectors));
		for (auto& m : scans.back()) m.id = id++;
	}
	std::vector<double> along{0};  // odometry path length from the first pose
	for (size_t t = 1; t < world.odometry.size(); ++t)
		along.push_back(along.back() + std::hypot(world.odometry[t].x - world.odometry[t - 1].x,
												  world.odometry[t].y - world.odometry[t - 1].y));
	const auto path = [&](const EdgeKey& k) { return along[k.second] - along[k.first]; };
	const double cut = along.back() / 4;  // half a lap
	const auto loops = [&](double maxPath) {
		ConstraintSet book{cfg.matcher};
		LoopClosure lc(cfg, book, none);
		lc.setOdometry(world.odometry);
		EXPECT_NEAR(lc.pathLength(), along.back(), 1e-9);
		EXPECT_NEAR(lc.coveredPath() * cfg.mstep.loopSearchSigmas * cfg.posegraph.odometrySigmaXYPerM,
					cfg.mstep.loopSearchMaxRadius, 1e-9);
		lc.setMaxPath(maxPath);
		book.beginStep(scans, nullptr);  // the scans' signatures, as MStep::run
		MStepReport rep;
		return lc.search(scans, world.odometry, {}, rep);
	};
	const auto within = loops(cut);
	for (const EdgeKey& k : within) EXPECT_LE(path(k), cut) << k.first << " " << k.second;
	const auto all = loops(std::numeric_limits<double>::infinity());
	EXPECT_TRUE(std::any_of(all.begin(), all.end(), [&](const EdgeKey& k) { return path(k) > cut; }));
}
