#include "posegraph/NormalEquations.h"

#include <algorithm>

namespace gridvector
{
using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace
{
int firstColumn(uint32_t node) { return node ? int(node) * 3 - 3 : -1; }  // node 0 is fixed
}  // namespace

NormalEquations::NormalEquations(size_t nodes, const std::vector<std::pair<uint32_t, uint32_t>>& edges)
{
	const int dim = nodes > 1 ? int(3 * (nodes - 1)) : 0;
	std::vector<Eigen::Triplet<double>> trip;
	trip.reserve(6 * (nodes + edges.size()));
	auto block = [&](int r0, int c0) {
		for (int q = 0; q < 3; ++q)
			for (int p = 0; p < 3; ++p)
				if (r0 + p >= c0 + q) trip.emplace_back(r0 + p, c0 + q, 0.0);
	};
	for (int c = 0; c < dim; c += 3) block(c, c);  // every diagonal block, edges or not
	for (const auto& [i, j] : edges)
	{
		const int ci = firstColumn(i), cj = firstColumn(j);
		if (ci >= 0 && cj >= 0 && ci != cj) block(std::max(ci, cj), std::min(ci, cj));
	}
	H_.resize(dim, dim);
	H_.setFromTriplets(trip.begin(), trip.end());
	H_.makeCompressed();
	b_.setZero(dim);
	edges_.reserve(edges.size());
	for (const auto& [i, j] : edges)
	{
		EdgeSlots s;
		s.ci = firstColumn(i), s.cj = firstColumn(j);
		s.ii = s.ci >= 0 ? slots(s.ci, s.ci) : BlockSlots{-1, -1, -1};
		s.jj = s.cj >= 0 ? slots(s.cj, s.cj) : BlockSlots{-1, -1, -1};
		s.ij = s.ci >= 0 && s.cj >= 0 && s.ci != s.cj ? slots(std::max(s.ci, s.cj), std::min(s.ci, s.cj))
													  : BlockSlots{-1, -1, -1};
		edges_.push_back(s);
	}
}

// The stored rows of a column are sorted: a block's three rows are consecutive.
NormalEquations::BlockSlots NormalEquations::slots(int row, int col) const
{
	BlockSlots s;
	for (int q = 0; q < 3; ++q)
	{
		const int c = col + q, r = row == col ? row + q : row;
		const int* begin = H_.innerIndexPtr() + H_.outerIndexPtr()[c];
		const int* end = H_.innerIndexPtr() + H_.outerIndexPtr()[c + 1];
		s[q] = int(std::lower_bound(begin, end, r) - H_.innerIndexPtr());
	}
	return s;
}

void NormalEquations::clear()
{
	std::fill(H_.valuePtr(), H_.valuePtr() + H_.nonZeros(), 0.0);
	b_.setZero();
}

void NormalEquations::addBlock(const BlockSlots& s, bool diagonal, const Matrix3d& M)
{
	double* v = H_.valuePtr();
	for (int q = 0; q < 3; ++q)
		for (int p = diagonal ? q : 0; p < 3; ++p) v[s[q] + p - (diagonal ? q : 0)] += M(p, q);
}

void NormalEquations::add(size_t k, const Matrix3d& A, const Matrix3d& B, const Matrix3d& W, const Vector3d& r)
{
	const EdgeSlots& s = edges_[k];
	const Matrix3d AtW = A.transpose() * W, BtW = B.transpose() * W;
	if (s.ci >= 0)
	{
		addBlock(s.ii, true, AtW * A);
		b_.segment<3>(s.ci) += AtW * r;
	}
	if (s.cj >= 0)
	{
		addBlock(s.jj, true, BtW * B);
		b_.segment<3>(s.cj) += BtW * r;
	}
	if (s.ij[0] >= 0)  // lower block: rows of the later node
		addBlock(s.ij, false, s.ci > s.cj ? Matrix3d(AtW * B) : Matrix3d(BtW * A));
}

}  // namespace gridvector
