// GraphOptimisation (Eq. 20-22): the pose graph over odometry and registrations, its chi2 rejections and
// how often a rejected pair comes back (mstep.reconsider_rejected, reconsider_limit).
#include "mstep/GraphOptimisation.h"
#include <mrpt/math/TPose2D.h>

#include <gtest/gtest.h>

#include <algorithm>

using namespace gridvector;
using mrpt::math::TPose2D;

namespace
{
// 11 poses 1 m apart along x; the odometry overestimates every step by 5 %.
struct Line
{
	Poses truth, odometry;
	Line()
	{
		for (int k = 0; k <= 10; ++k)
		{
			truth.emplace_back(k, 0, 0);
			odometry.emplace_back(1.05 * k, 0, 0);
		}
	}
	Constraint edge(uint32_t from, uint32_t to, double errorY = 0) const
	{
		Constraint c;
		c.from = from;
		c.to = to;
		c.kind = EdgeKind::Overlap;
		c.z = truth[to] - truth[from];
		c.z.y += errorY;
		c.information = Eigen::Vector3d(1e4, 1e4, 1e5).asDiagonal();
		c.correspondences = {{1, 2}};
		return c;
	}
};
}  // namespace

TEST(GraphOptimisation, RegistrationsCorrectTheOdometry)
{
	const Line l;
	const GridVectorConfig cfg;
	GraphOptimisation opt(cfg);
	std::map<EdgeKey, Constraint> edges{{{0, 10}, l.edge(0, 10)}, {{0, 5}, l.edge(0, 5)}};
	Poses poses = l.odometry;
	MStepReport rep;
	opt.beginStep();
	EXPECT_TRUE(opt.optimise(poses, l.odometry, edges, rep).empty());
	EXPECT_NEAR(poses[10].x - poses[0].x, 10.0, 0.01);
	EXPECT_NEAR(poses[5].x - poses[0].x, 5.0, 0.01);
	EXPECT_GT(rep.optimisation.iterations, 0);
	EXPECT_EQ(opt.graph().edges().size(), 12u);  // 10 odometry edges + 2 registrations
}

// A wrong registration among right ones is rejected; with reconsider_rejected it returns at every optimisation
// until it has been rejected reconsider_limit times after the first kReconsiderFreeSteps M-steps.
TEST(GraphOptimisation, ARejectionStandsAfterTheLimit)
{
	const Line l;
	const GridVectorConfig cfg;
	ASSERT_TRUE(cfg.mstep.reconsiderRejected);
	GraphOptimisation opt(cfg);
	std::map<EdgeKey, Constraint> edges{
		{{0, 10}, l.edge(0, 10)}, {{2, 10}, l.edge(2, 10)}, {{1, 10}, l.edge(1, 10, 2.0)}};
	const int limit = cfg.mstep.reconsiderLimit;
	ASSERT_GT(limit, 0);
	for (int step = 1; step <= kReconsiderFreeSteps + limit + 1; ++step)
	{
		Poses poses = l.odometry;
		MStepReport rep;
		opt.beginStep();
		const auto rejected = opt.optimise(poses, l.odometry, edges, rep);
		EXPECT_TRUE(edges.at({1, 10}).rejected) << step;
		EXPECT_FALSE(edges.at({0, 10}).rejected) << step;
		const bool retried = std::find(rejected.begin(), rejected.end(), EdgeKey{1, 10}) != rejected.end();
		EXPECT_EQ(retried, step <= kReconsiderFreeSteps + limit) << step;  // then it no longer enters the graph
		EXPECT_NEAR(poses[10].y, 0.0, 0.01) << step;
	}
	// other correspondences (a changed data association) start the count again
	edges.at({1, 10}).correspondences = {{1, 3}};
	Poses poses = l.odometry;
	MStepReport rep;
	opt.beginStep();
	const auto rejected = opt.optimise(poses, l.odometry, edges, rep);
	EXPECT_EQ(rejected, (std::vector<EdgeKey>{{1, 10}}));
}

TEST(GraphOptimisation, TheInformationIsRotatedIntoTheErrorsFrame)
{
	const Line l;
	Constraint c = l.edge(0, 1);
	c.z.phi = 0.5;
	c.information = Eigen::Vector3d(1, 100, 10).asDiagonal();
	MStepOptions o;
	ASSERT_TRUE(o.informationInEdgeFrame);
	EXPECT_TRUE(graphInformation(c, o).isApprox(PoseGraph::errorFrameInformation(c.information, c.z)));
	EXPECT_FALSE(graphInformation(c, o).isApprox(c.information));
	o.informationInEdgeFrame = false;
	EXPECT_EQ(graphInformation(c, o), c.information);
}
