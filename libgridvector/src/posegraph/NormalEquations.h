// Sec. 4.2, Eq. 22: the Gauss-Newton normal equations H dx = -b of the pose graph.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

namespace gridvector
{
/** H (lower triangle, 3x3 blocks) and b over the poses x_1..x_{n-1} (x_0 fixed),
 * summed over edges e_ij with Jacobians A = de/dx_i, B = de/dx_j and weight W.
 * The sparsity pattern is built once for a list of edges; clear() and add() then
 * refill its values in place at every linearisation. */
class NormalEquations
{
   public:
	NormalEquations(size_t nodes, const std::vector<std::pair<uint32_t, uint32_t>>& edges);

	void clear();
	/** Adds edge k (of the constructor's list): H += J^T W J, b += J^T W r. */
	void add(size_t k, const Eigen::Matrix3d& A, const Eigen::Matrix3d& B, const Eigen::Matrix3d& W,
			 const Eigen::Vector3d& r);

	const Eigen::SparseMatrix<double>& H() const { return H_; }
	const Eigen::VectorXd& b() const { return b_; }

   private:
	// Value index of the first stored entry of each of a block's three columns
	// (diagonal blocks: the diagonal entry, the lower triangle follows); -1: fixed node.
	using BlockSlots = std::array<int, 3>;
	struct EdgeSlots
	{
		BlockSlots ii, jj, ij;
		int ci, cj;  // first column of x_i, x_j (-1 for x_0)
	};
	BlockSlots slots(int row, int col) const;
	void addBlock(const BlockSlots& s, bool diagonal, const Eigen::Matrix3d& M);

	Eigen::SparseMatrix<double> H_;
	Eigen::VectorXd b_;
	std::vector<EdgeSlots> edges_;
};

}  // namespace gridvector
