#include "graphslam/EngineEdge.h"

namespace gridvector::graphslam
{
mrpt::poses::CPosePDFGaussianInf engineEdge(const mrpt::math::TPose2D& z, const Eigen::Matrix3d& information)
{
	mrpt::poses::CPosePDFGaussianInf c;
	c.mean = mrpt::poses::CPose2D(z);
	for (int r = 0; r < 3; ++r)
		for (int k = 0; k < 3; ++k) c.cov_inv(r, k) = information(r, k);
	return c;
}

}  // namespace gridvector::graphslam
