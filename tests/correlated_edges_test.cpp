// CorrelatedEdges (Eq. 22 with covariance intersection): registrations of one scan against one pass weigh as one.
#include "posegraph/CorrelatedEdges.h"
#include "posegraph/PoseGraph.h"
#include "core/SE2.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace gridvector;
using mrpt::math::TPose2D;
using se2::relative;

namespace
{
PoseEdge edge(uint32_t from, uint32_t to, EdgeKind kind)
{
	PoseEdge e;
	e.from = from, e.to = to, e.kind = kind;
	return e;
}

// Pass A (scans 0-9) east along y = 0, pass B (10-19) back west along y = 0.5, 0.5 m apart.
std::vector<TPose2D> twoPasses()
{
	std::vector<TPose2D> p;
	for (int k = 0; k < 10; ++k) p.emplace_back(0.5 * k, 0.0, 0.0);
	for (int k = 10; k < 20; ++k) p.emplace_back(0.5 * (19 - k), 0.5, M_PI);
	return p;
}

// Odometry and exact sequential registrations along each pass (each pass rigid), two independent
// correct registrations 2-17 and 5-14, and scan 8 registered against 11, 12 and 13 with one alias:
// pass B 0.24 m further west than it is (the same wall piece matched one recess off, three times).
PoseGraph twoPassGraph(const PoseGraphOptions& o)
{
	const auto truth = twoPasses();
	PoseGraph g(o);
	const Eigen::Matrix3d reg = Eigen::Vector3d(1e4, 1e4, 1e5).asDiagonal();
	for (uint32_t i = 1; i < truth.size(); ++i)
	{
		PoseEdge e = edge(i - 1, i, EdgeKind::Odometry);
		e.z = relative(truth[i - 1], truth[i]);
		e.information = PoseGraph::odometryInformation(e.z, o);
		g.addEdge(e);
		if (i == 10) continue;  // the turn: odometry only
		e.kind = EdgeKind::Sequential, e.information = 100 * reg;  // along a pass: rigid
		g.addEdge(e);
	}
	for (auto [a, b] : {std::pair{2u, 17u}, std::pair{5u, 14u}})
	{
		PoseEdge e = edge(a, b, EdgeKind::Overlap);
		e.z = relative(truth[a], truth[b]), e.information = reg;
		g.addEdge(e);
	}
	for (uint32_t b : {11u, 12u, 13u})
	{
		TPose2D alias = truth[b];
		alias.x -= 0.24;
		PoseEdge e = edge(8, b, EdgeKind::Overlap);
		e.z = relative(truth[8], alias), e.information = reg;
		g.addEdge(e);
	}
	g.setNodes(truth);
	return g;
}

double worstOffTruth(const PoseGraph& g)
{
	const auto truth = twoPasses();
	double m = 0;
	for (size_t i = 0; i < truth.size(); ++i)
		m = std::max(m, std::hypot(g.nodes()[i].x - truth[i].x, g.nodes()[i].y - truth[i].y));
	return m;
}
}  // namespace

TEST(CorrelatedEdges, RegistrationsOfOneScanAgainstConsecutiveScansShareTheirEvidence)
{
	std::vector<PoseEdge> edges{edge(8, 11, EdgeKind::Overlap), edge(8, 12, EdgeKind::Overlap),
								edge(8, 13, EdgeKind::Loop),	edge(2, 17, EdgeKind::Overlap),
								edge(5, 14, EdgeKind::Overlap), edge(8, 30, EdgeKind::Overlap),
								edge(7, 8, EdgeKind::Sequential), edge(6, 8, EdgeKind::Sequential),
								edge(8, 9, EdgeKind::Odometry)};
	const auto off = correlatedEdgeWeights(edges, 0);
	EXPECT_TRUE(std::all_of(off.begin(), off.end(), [](double w) { return w == 1.0; }));
	const auto w = correlatedEdgeWeights(edges, 1);
	for (size_t k = 0; k < 3; ++k) EXPECT_DOUBLE_EQ(w[k], 1.0 / 3) << k;  // 8 x 11-13: one group
	for (size_t k = 3; k < edges.size(); ++k) EXPECT_EQ(w[k], 1.0) << k;  // another pass, or not a registration
	EXPECT_DOUBLE_EQ(correlatedEdgeWeights(edges, 1, 0.5)[0], 0.5);  // 3 / (1 + 2 x 0.5) = 1.5 edges' worth
	EXPECT_EQ(correlatedEdgeWeights(edges, 1, 0.0)[0], 1.0);  // uncorrelated: independent edges
	edges[1].active = false;  // 11 and 13 are 2 apart: two groups of one at gap 1, one of two at gap 2
	EXPECT_EQ(correlatedEdgeWeights(edges, 1)[0], 1.0);
	EXPECT_DOUBLE_EQ(correlatedEdgeWeights(edges, 2)[2], 0.5);
	edges[1].active = true;
	edges.push_back(edge(4, 12, EdgeKind::Overlap));  // 4-12 and 5-14 ... share no scan: 8-12 stays in its group of 3
	edges.push_back(edge(3, 12, EdgeKind::Overlap));  // scan 12 against 3, 4 and 8: groups {3, 4} and {8} at 12
	const auto both = correlatedEdgeWeights(edges, 1);
	EXPECT_DOUBLE_EQ(both[1], 1.0 / 3);  // the smaller weight of its two ends
	EXPECT_DOUBLE_EQ(both[9], 0.5);
	EXPECT_DOUBLE_EQ(both[10], 0.5);
}

TEST(CorrelatedEdges, ThreeRegistrationsOfOneAliasNoLongerOutvoteTwoIndependentOnes)
{
	const PoseGraphOptions off;
	EXPECT_EQ(off.correlatedGroupGap, 0);  // off by default: Eq. 22 as before
	PoseGraph before = twoPassGraph(off);
	before.optimize();
	EXPECT_GT(worstOffTruth(before), 0.15);  // the alias wins: pass B moved most of the 0.24 m
	for (const auto& e : before.edges())  // ... and the correct registrations lose
	{
		if (e.kind == EdgeKind::Overlap && (e.from == 2 || e.from == 5))
		{
			EXPECT_TRUE(!e.active || e.scale < 0.2) << e.from << "-" << e.to;
		}
	}
	PoseGraphOptions on;
	on.correlatedGroupGap = 1;
	PoseGraph after = twoPassGraph(on);
	after.optimize();
	EXPECT_LT(worstOffTruth(after), 0.02);
	for (const auto& e : after.edges())
	{
		if (e.kind != EdgeKind::Overlap) continue;
		const bool alias = e.from == 8;  // weighed as one edge, then rejected (its chi2 taken with share 1/3)
		EXPECT_TRUE(alias ? !e.active && e.chi2 > 100 : e.active && e.scale > 0.9) << e.from << "-" << e.to;
	}
}
