// OnlineEmSlam (Sec. 6's sequential mode): scan by scan on the ring corridor of em_world.h, the final
// and the causal trajectory accurate, and an object seen through mid-run dynamic at once.
#include "em_world.h"

#include "online/OnlineEmSlam.h"

#include <gtest/gtest.h>

using namespace gridvector;
using gridvector::online::OnlineEmSlam;
using gridvector::online::OnlineStep;
using emtest::TPose2D;

namespace
{
// em_slam_test's transient object: a board across the corridor during the first lap only (scans 4..14).
const std::vector<emtest::Wall> kBoard = {{5.0, 1.35, 5.0, 1.95}};
bool onBoard(const GridVector& v, const TPose2D& toTruth)
{
	const TPose2D c = toTruth + TPose2D(v.centre().x, v.centre().y, 0);
	return c.x > 4.9 && c.x < 5.1 && c.y > 1.3 && c.y < 2.0;
}
}  // namespace

TEST(OnlineEmSlam, TrajectoryAccurateAndAnObjectSeenThroughIsDynamicWithinTenScans)
{
	const auto truth = emtest::ringPath(2, 0.5);
	const auto odo = emtest::odometryOf(truth, 3);
	const size_t lap = truth.size() / 2;
	OnlineEmSlam slam;
	std::vector<TPose2D> causal;
	std::vector<VectorState> boardState(truth.size(), VectorState::Unknown);
	size_t loops = 0;
	for (size_t t = 0; t < truth.size(); ++t)
	{
		auto walls = emtest::corridorWorld();
		if (t >= 4 && t <= 14) walls.insert(walls.end(), kBoard.begin(), kBoard.end());
		LocalScan s = emtest::observe(walls, truth[t], 6.0, unsigned(t));
		s.scanIndex = int64_t(t);
		const OnlineStep st = slam.addScan(s, odo[t]);
		loops += st.loops;
		causal.push_back(st.pose);
		EXPECT_EQ(slam.currentPose(), st.pose);
		// the board's state as the map holds it now (the estimate's frame: first poses aligned)
		const TPose2D toTruth = truth[0] + (TPose2D(0, 0, 0) - causal[0]);
		// the board's state: Static while any of its vectors is, Dynamic once all are
		for (const auto& v : slam.map().perScan())
			if (onBoard(v, toTruth) && v.length() > 0.3 && boardState[t] != VectorState::Static)
				boardState[t] = slam.map().stateOf(v) == VectorState::Static ? VectorState::Static : VectorState::Dynamic;
	}
	slam.finish();
	EXPECT_GT(loops, 0u);
	EXPECT_EQ(slam.keyframes().size(), truth.size());  // 0.5 m apart: every scan is a keyframe
	const auto final = slam.trajectory();
	ASSERT_EQ(final.size(), truth.size());
	EXPECT_LT(emtest::ate(final, truth), 0.1);
	EXPECT_LT(emtest::ate(causal, truth), 0.3);
	// em_world's scans see every facing wall within range, occluded or not: the walls beyond the board
	// are seen through its place by the scans before it stood there and by every scan while it stands
	// (Eq. 8's full product, as the batch's E-step). Dynamic within 10 scans of being first seen, and
	// once it has gone while the run goes on.
	size_t dynamicAt = truth.size();
	for (size_t t = 4; t < truth.size() && dynamicAt == truth.size(); ++t)
		if (boardState[t] == VectorState::Dynamic) dynamicAt = t;
	EXPECT_LE(dynamicAt, 4u + 10u) << "board dynamic at scan " << dynamicAt;
	// gone from scan 15 on: every vector it left dynamic until the first lap ends
	for (size_t t = 15; t < lap; ++t) EXPECT_EQ(boardState[t], VectorState::Dynamic) << t;
	// the queries: static and dynamic maps disjoint, the occupancy grid from the static one
	const auto stat = slam.staticMap(), dyn = slam.dynamicVectors();
	double staticLen = 0;
	for (const auto& v : stat) staticLen += v.length();
	EXPECT_GT(staticLen, 60.0);
	EXPECT_EQ(slam.vectors().size(), stat.size() + dyn.size());
	const auto grid = slam.occupancyGrid();
	EXPECT_GT(grid.getSizeX(), 10u);
	EXPECT_GT(slam.report().loop, 0u);
	// the batch's final map at the online trajectory: the board dynamic there too
	const auto fin = slam.finalMap();
	double finStatic = 0;
	const TPose2D toTruth = truth[0] + (TPose2D(0, 0, 0) - final[0]);
	for (const auto& v : fin)
	{
		if (v.state == VectorState::Static) finStatic += v.length();
		EXPECT_TRUE(!onBoard(v, toTruth) || v.state == VectorState::Dynamic);
	}
	EXPECT_GT(finStatic, 60.0);
}

TEST(OnlineEmSlam, ScansWithoutVectorsFollowTheOdometry)
{
	OnlineEmSlam slam;
	LocalScan empty;
	for (int t = 0; t < 5; ++t)
	{
		const OnlineStep st = slam.addScan(empty, TPose2D(0.3 * t, 0, 0));
		EXPECT_FALSE(st.registered);
		EXPECT_NEAR(st.pose.x, 0.3 * t, 1e-9);
	}
	slam.finish();
	EXPECT_EQ(slam.trajectory().size(), 5u);
	EXPECT_TRUE(slam.vectors().empty());
}
