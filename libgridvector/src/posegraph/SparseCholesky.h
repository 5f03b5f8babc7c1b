// Sec. 4.2, Eq. 22: the sparse Cholesky factorisation behind each Levenberg-Marquardt step.
#pragma once

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace gridvector
{
/** Fill-reducing orderings of CHOLMOD's analysis. */
enum class FillOrdering
{
	Amd,  //!< approximate minimum degree
	Metis,  //!< METIS nested dissection
	Colamd,  //!< CHOLMOD_COLAMD (AMD on a symmetric matrix)
	Auto  //!< CHOLMOD's default strategy: AMD, then METIS if AMD's fill is poor
};

/** Solves (H + shift I) x = b for a sparse symmetric positive definite H
 * (only its lower triangle is read) with CHOLMOD's supernodal LL^T. analyze()
 * computes the ordering and the symbolic factor once for a pattern; factorize()
 * reuses them for every matrix with that pattern (one per LM iteration). */
class SparseCholesky
{
   public:
	/** Auto: CHOLMOD's own choice, AMD unless its fill is poor, then METIS if that fills less (a graph of many
	 * passes through one place: 20,000 simulated scans, factor 12.9M -> 11.4M non-zeros, Eq. 22 -18 %; on the
	 * benchmark logs AMD is kept). */
	explicit SparseCholesky(FillOrdering ordering = FillOrdering::Auto);
	~SparseCholesky();
	SparseCholesky(const SparseCholesky&) = delete;
	SparseCholesky& operator=(const SparseCholesky&) = delete;

	void analyze(const Eigen::SparseMatrix<double>& H);
	/** false if H + shift I is not positive definite (numerically). */
	bool factorize(const Eigen::SparseMatrix<double>& H, double shift = 0);
	Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
	/** Non-zeros of the factor L (after factorize()). */
	size_t factorNonZeros() const;

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};

}  // namespace gridvector
