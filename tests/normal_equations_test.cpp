#include "posegraph/NormalEquations.h"

#include <gtest/gtest.h>

#include <random>

using Eigen::Matrix3d;
using Eigen::Vector3d;

// H = sum J^T W J and b = sum J^T W r, checked against a dense assembly.
TEST(NormalEquations, SameAsDenseAssemblyIncludingTheFixedFirstPose)
{
	const size_t nodes = 12;
	const std::vector<std::pair<uint32_t, uint32_t>> edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4},  {4, 5},   {5, 6},
															  {6, 7}, {7, 8}, {8, 9}, {9, 10}, {10, 11}, {11, 0},
															  {7, 2}, {3, 9}, {3, 9}, {5, 11}};
	std::mt19937 rng(1);
	std::normal_distribution<double> g;
	auto random3 = [&] { return Matrix3d(Matrix3d::NullaryExpr([&] { return g(rng); })); };
	gridvector::NormalEquations eq(nodes, edges);
	const int dim = int(3 * (nodes - 1));
	for (int round = 0; round < 2; ++round)  // refilled in place
	{
		Eigen::MatrixXd Hd = Eigen::MatrixXd::Zero(dim, dim);
		Eigen::VectorXd bd = Eigen::VectorXd::Zero(dim);
		eq.clear();
		for (size_t k = 0; k < edges.size(); ++k)
		{
			const Matrix3d A = random3(), B = random3(), S = random3();
			const Matrix3d W = S * S.transpose() + Matrix3d::Identity();
			const Vector3d r(g(rng), g(rng), g(rng));
			eq.add(k, A, B, W, r);
			Eigen::MatrixXd J = Eigen::MatrixXd::Zero(3, dim);
			if (edges[k].first) J.middleCols<3>(3 * edges[k].first - 3) += A;
			if (edges[k].second) J.middleCols<3>(3 * edges[k].second - 3) += B;
			Hd += J.transpose() * W * J;
			bd += J.transpose() * W * r;
		}
		const Eigen::MatrixXd lower = Eigen::MatrixXd(eq.H()).triangularView<Eigen::Lower>();
		const Eigen::MatrixXd expected = Hd.triangularView<Eigen::Lower>();
		EXPECT_LT((lower - expected).norm(), 1e-12 * Hd.norm());
		EXPECT_EQ(Eigen::MatrixXd(Eigen::MatrixXd(eq.H()).triangularView<Eigen::StrictlyUpper>()).norm(), 0.0);
		EXPECT_LT((eq.b() - bd).norm(), 1e-12 * bd.norm());
	}
	// the pattern: every diagonal block, and one lower block per pair of free nodes
	EXPECT_EQ(eq.H().nonZeros(), 11 * 6 + 13 * 9);
}
