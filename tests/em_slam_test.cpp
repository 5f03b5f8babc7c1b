// EmSlam (Sec. 4): E- and M-steps until no constraint changes; a transient object ends dynamic.
#include "em_world.h"

#include "em/EmSlam.h"

#include <gtest/gtest.h>

using namespace gridvector;
using emtest::TPoint2D;
using emtest::TPose2D;

TEST(EmSlam, ConvergesToTheTrueTrajectoryAndFindsTheTransientObject)
{
	const auto truth = emtest::ringPath(2, 0.5);
	const auto odo = emtest::odometryOf(truth, 3);
	auto walls = emtest::corridorWorld();
	// a board standing across part of the corridor during the first lap only (scans 4..14),
	// seen from the corridor behind it (open side towards -x)
	const std::vector<emtest::Wall> box = {{5.0, 1.35, 5.0, 1.95}};
	std::vector<LocalScan> scans;
	for (size_t t = 0; t < truth.size(); ++t)
	{
		auto w = walls;
		if (t >= 4 && t <= 14) w.insert(w.end(), box.begin(), box.end());
		scans.push_back(emtest::observe(w, truth[t], 6.0, unsigned(t)));
		scans.back().scanIndex = int64_t(t);
	}
	// later scans see through the box's place: the walls behind it are visible, and the
	// wipe triangles of the scans of the second lap pass where the box stood
	GridVectorConfig cfg;
	std::vector<int> perIteration;
	const EmResult r = EmSlam(cfg).run(
		scans, odo, [&](const EmIteration& it, const std::vector<TPose2D>&) { perIteration.push_back(it.index); });
	EXPECT_TRUE(r.converged);
	EXPECT_LE(r.iterations.size(), 6u);
	EXPECT_EQ(perIteration.size(), r.iterations.size());
	EXPECT_EQ(r.iterations.front().changedShare, 1.0);
	EXPECT_EQ(r.iterations.back().changedShare, 0.0);
	EXPECT_LT(emtest::ate(r.poses, truth), 0.05);
	ASSERT_FALSE(r.finalVectors.empty());
	// the box's front face (x = 5, facing -x... seen from the corridor) is dynamic in the final map
	const TPose2D T = truth[0] + (TPose2D(0, 0, 0) - r.poses[0]);
	double staticLen = 0, dynamicOnBox = 0;
	for (const auto& v : r.finalVectors)
	{
		const TPose2D c = T + TPose2D(v.centre().x, v.centre().y, 0);
		const bool onBox = c.x > 4.9 && c.x < 5.1 && c.y > 1.3 && c.y < 2.0;
		if (v.state == VectorState::Static)
			staticLen += v.length();
		else if (onBox)
			dynamicOnBox += v.length();
		EXPECT_TRUE(!onBox || v.state == VectorState::Dynamic) << c.x << " " << c.y;
	}
	EXPECT_GT(dynamicOnBox, 0.5);
	EXPECT_GT(staticLen, 60.0);
	// static and dynamic maps are disjoint merges of the per-scan children (M_cor)
	size_t sources = 0;
	for (const auto* m : {&r.staticMap, &r.dynamicMap})
		for (const auto& s : m->sources) sources += s.size();
	EXPECT_EQ(sources, r.perScan.size());
}

// EM from another trajectory (gv-em-slam --init, --online --refine): it starts there, and the odometry edges
// (Eq. 20) stay the odometry's.
TEST(EmSlam, StartsFromAnInitialTrajectoryWithTheOdometryEdges)
{
	const auto truth = emtest::ringPath(2, 0.5);
	const auto odo = emtest::odometryOf(truth, 3, 6.0);
	const auto walls = emtest::corridorWorld();
	std::vector<LocalScan> scans, blind(truth.size());
	for (size_t t = 0; t < truth.size(); ++t)
	{
		scans.push_back(emtest::observe(walls, truth[t], 6.0, unsigned(t)));
		scans.back().scanIndex = int64_t(t);
		blind[t].scanIndex = int64_t(t);
	}
	std::vector<TPose2D> first;
	const EmResult r = EmSlam().run(scans, odo, truth, [&](const EmIteration& it, const std::vector<TPose2D>& p) {
		if (it.index == 1) first = p;
	});
	EXPECT_LT(emtest::ate(r.poses, truth), 0.05);
	ASSERT_EQ(first.size(), truth.size());
	EXPECT_LT(emtest::ate(first, truth), 0.05);  // the first M-step registered from the truth, not from the odometry
	// nothing to register: only the odometry edges act, so the result has the odometry's shape, not the start's
	const EmResult b = EmSlam().run(blind, odo, truth);
	ASSERT_EQ(b.poses.size(), odo.size());
	const auto worstStep = [&](const std::vector<TPose2D>& p) {  // largest step unlike the odometry's [m]
		double worst = 0;
		for (size_t t = 1; t < odo.size(); ++t)
		{
			const TPose2D d = (p[t] - p[t - 1]) - (odo[t] - odo[t - 1]);
			worst = std::max(worst, std::hypot(d.x, d.y));
		}
		return worst;
	};
	ASSERT_GT(worstStep(truth), 0.02);  // (the start's steps are not the odometry's)
	EXPECT_LT(worstStep(b.poses), 0.25 * worstStep(truth));
}

// The first M-step's loop rounds end when there is no loop window at all (mstep.loop_search_max_radius 0).
TEST(EmSlam, RunsWithoutALoopWindow)
{
	const auto truth = emtest::ringPath(1, 0.5);
	const auto odo = emtest::odometryOf(truth, 3);
	std::vector<LocalScan> scans;
	for (size_t t = 0; t < truth.size(); ++t)
	{
		scans.push_back(emtest::observe(emtest::corridorWorld(), truth[t], 6.0, unsigned(t)));
		scans.back().scanIndex = int64_t(t);
	}
	GridVectorConfig cfg;
	cfg.mstep.loopSearchMaxRadius = 0;
	const EmResult r = EmSlam(cfg).run(scans, odo);
	EXPECT_EQ(r.poses.size(), truth.size());
	EXPECT_FALSE(r.iterations.empty());
}

// The rvalue run moves the keyframes' scans in: the same result as from a copy, every scan's sensor origin left.
TEST(EmSlam, ARunOnScansGivenUpEqualsARunOnACopy)
{
	const auto truth = emtest::ringPath(2, 0.5);
	const auto odo = emtest::odometryOf(truth, 3, 6.0);
	const auto walls = emtest::corridorWorld();
	std::vector<LocalScan> scans;
	for (size_t t = 0; t < truth.size(); ++t)
	{
		scans.push_back(emtest::observe(walls, truth[t], 6.0, unsigned(t)));
		scans.back().scanIndex = int64_t(t);
		scans.back().sensorOrigin = mrpt::math::TPoint2D(0.1, 0.0);
	}
	const EmResult copied = EmSlam().run(scans, odo, odo);
	const EmResult moved = EmSlam().run(std::move(scans), odo, odo);
	ASSERT_EQ(copied.poses.size(), moved.poses.size());
	for (size_t t = 0; t < copied.poses.size(); ++t)
	{
		EXPECT_EQ(copied.poses[t].x, moved.poses[t].x);
		EXPECT_EQ(copied.poses[t].phi, moved.poses[t].phi);
	}
	EXPECT_EQ(copied.finalVectors.size(), moved.finalVectors.size());
	ASSERT_EQ(scans.size(), truth.size());  // the elements were moved from, not the vector
	size_t emptied = 0;
	for (const LocalScan& s : scans)
	{
		EXPECT_EQ(s.sensorOrigin.x, 0.1);
		emptied += s.vectors.empty();
	}
	EXPECT_GT(emptied, 0u);  // the keyframes' vectors went into the run
}
