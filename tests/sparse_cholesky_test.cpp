#include "posegraph/SparseCholesky.h"

#include <Eigen/SparseCholesky>
#include <gtest/gtest.h>

#include <random>

using gridvector::FillOrdering;
using gridvector::SparseCholesky;

namespace
{
// A random sparse SPD matrix shaped like a pose graph's H: 3x3 blocks along a chain
// plus random long-range blocks (loop closures), full storage.
Eigen::SparseMatrix<double> randomSpd(int blocks, int extra, unsigned seed)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> g;
	std::uniform_int_distribution<int> pick(0, blocks - 1);
	const int n = 3 * blocks;
	Eigen::SparseMatrix<double> J(0, n);
	std::vector<Eigen::Triplet<double>> t;
	int rows = 0;
	auto edge = [&](int a, int b) {
		for (int r = 0; r < 3; ++r, ++rows)
			for (int c = 0; c < 3; ++c)
			{
				t.emplace_back(rows, 3 * a + c, g(rng));
				if (b >= 0) t.emplace_back(rows, 3 * b + c, g(rng));
			}
	};
	for (int i = 0; i < blocks; ++i) edge(i, i + 1 < blocks ? i + 1 : -1);
	for (int k = 0; k < extra; ++k)
	{
		const int a = pick(rng), b = pick(rng);
		if (a != b) edge(a, b);
	}
	J.resize(rows, n);
	J.setFromTriplets(t.begin(), t.end());
	Eigen::SparseMatrix<double> H = Eigen::SparseMatrix<double>(J.transpose()) * J;
	for (int i = 0; i < n; ++i) H.coeffRef(i, i) += 1e-3;
	return H;
}
}  // namespace

TEST(SparseCholesky, SameSolutionAsSimplicialLdltForEveryOrdering)
{
	const Eigen::SparseMatrix<double> H = randomSpd(400, 600, 7);
	const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(H.rows(), -1, 2);
	Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ref(H);
	ASSERT_EQ(ref.info(), Eigen::Success);
	const Eigen::VectorXd xRef = ref.solve(b);
	for (auto o : {FillOrdering::Amd, FillOrdering::Metis, FillOrdering::Colamd, FillOrdering::Auto})
	{
		SparseCholesky llt(o);
		llt.analyze(H);
		ASSERT_TRUE(llt.factorize(H));
		const Eigen::VectorXd x = llt.solve(b);
		EXPECT_LT((x - xRef).norm() / xRef.norm(), 1e-9) << int(o);
		EXPECT_LT((H * x - b).norm() / b.norm(), 1e-9) << int(o);
		EXPECT_GE(llt.factorNonZeros(), size_t(H.rows()));
	}
}

TEST(SparseCholesky, ReadsOnlyTheLowerTriangle)
{
	const Eigen::SparseMatrix<double> H = randomSpd(50, 40, 3);
	const Eigen::SparseMatrix<double> lower = H.triangularView<Eigen::Lower>();
	const Eigen::VectorXd b = Eigen::VectorXd::Ones(H.rows());
	SparseCholesky full, low;
	full.analyze(H), low.analyze(lower);
	ASSERT_TRUE(full.factorize(H));
	ASSERT_TRUE(low.factorize(lower));
	EXPECT_LT((full.solve(b) - low.solve(b)).norm(), 1e-9 * full.solve(b).norm());
}

TEST(SparseCholesky, ShiftFactorisesTheDampedMatrixWithTheSameAnalysis)
{
	const Eigen::SparseMatrix<double> H = randomSpd(100, 80, 5);
	const Eigen::VectorXd b = Eigen::VectorXd::Ones(H.rows());
	SparseCholesky llt;
	llt.analyze(H);
	for (double lambda : {0.0, 0.5, 1e3})
	{
		ASSERT_TRUE(llt.factorize(H, lambda));
		Eigen::SparseMatrix<double> I(H.rows(), H.cols());
		I.setIdentity();
		const Eigen::SparseMatrix<double> damped = H + lambda * I;
		EXPECT_LT((damped * llt.solve(b) - b).norm(), 1e-9 * b.norm()) << lambda;
	}
}

TEST(SparseCholesky, ReportsAnIndefiniteMatrix)
{
	Eigen::SparseMatrix<double> H = randomSpd(20, 10, 9);
	H.coeffRef(30, 30) = -5;
	SparseCholesky llt;
	llt.analyze(H);
	EXPECT_FALSE(llt.factorize(H));
	EXPECT_TRUE(llt.factorize(H, 100));  // damping makes it positive definite again
}
