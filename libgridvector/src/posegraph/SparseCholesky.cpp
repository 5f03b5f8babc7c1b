#include "posegraph/SparseCholesky.h"

#include <Eigen/CholmodSupport>
#ifdef GRIDVECTOR_HAVE_OPENMP
#include <omp.h>
#endif

namespace gridvector
{
namespace
{
/** CHOLMOD's supernodal factorisation opens OpenMP teams of a size fixed when it was built (4 in
 * Debian's), whatever cores the process may use: on a pinned or loaded process the extra threads spin
 * (half of a 5,000-scan run's optimisation time on one core). With the runtime's dynamic adjustment a
 * team gets at most the idle cores of the process's affinity set; the caller's setting is restored. */
class DynamicTeams
{
   public:
#ifdef GRIDVECTOR_HAVE_OPENMP
	DynamicTeams() : before_(omp_get_dynamic()) { omp_set_dynamic(1); }
	~DynamicTeams() { omp_set_dynamic(before_); }

   private:
	int before_;
#endif
};
}  // namespace

struct SparseCholesky::Impl
{
	Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
};

SparseCholesky::SparseCholesky(FillOrdering ordering) : impl_(std::make_unique<Impl>())
{
	cholmod_common& c = impl_->llt.cholmod();
	c.print = 0;  // a non-positive-definite H is reported by factorize(), not printed
	if (ordering == FillOrdering::Auto) return;
	c.nmethods = 1;
	c.method[0].ordering = ordering == FillOrdering::Metis    ? CHOLMOD_METIS
						   : ordering == FillOrdering::Colamd ? CHOLMOD_COLAMD
															  : CHOLMOD_AMD;
	c.postorder = 1;
}

SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::analyze(const Eigen::SparseMatrix<double>& H) { impl_->llt.analyzePattern(H); }

bool SparseCholesky::factorize(const Eigen::SparseMatrix<double>& H, double shift)
{
	impl_->llt.setShift(shift);
	const DynamicTeams teams;
	impl_->llt.factorize(H);
	return impl_->llt.info() == Eigen::Success;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const { return impl_->llt.solve(b); }

size_t SparseCholesky::factorNonZeros() const
{
	const cholmod_common& c = const_cast<Impl&>(*impl_).llt.cholmod();
	return c.lnz > 0 ? size_t(c.lnz) : 0;
}

}  // namespace gridvector
