#include "posegraph/CeresSolve.h"

#include <ceres/ceres.h>
#include <mrpt/math/wrap2pi.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <memory>

namespace gridvector
{
namespace
{
template <typename T>
T normalizeAngle(const T& a)  // to [-pi, pi), as in Ceres' slam/pose_graph_2d/normalize_angle.h
{
	const T twoPi(2.0 * M_PI);
	return a - twoPi * ceres::floor((a + T(M_PI)) / twoPi);
}

// Eq. 21: e = z^-1 (+) (x_i^-1 (+) x_j), the residual L^T e (L L^T = Omega).
struct PoseEdgeCost
{
	PoseEdgeCost(const mrpt::math::TPose2D& z, const Eigen::Matrix3d& sqrtInformation)
		: z_(z), sqrtInformation_(sqrtInformation)
	{
	}
	template <typename T>
	bool operator()(const T* xi, const T* xj, T* residual) const
	{
		using std::cos, std::sin, ceres::cos, ceres::sin;
		const T ci = cos(xi[2]), si = sin(xi[2]);
		const T dx = xj[0] - xi[0], dy = xj[1] - xi[1];
		const T ex = ci * dx + si * dy - z_.x, ey = -si * dx + ci * dy - z_.y;
		const double cz = std::cos(z_.phi), sz = std::sin(z_.phi);
		Eigen::Matrix<T, 3, 1> e(cz * ex + sz * ey, -sz * ex + cz * ey, normalizeAngle(xj[2] - xi[2] - T(z_.phi)));
		Eigen::Map<Eigen::Matrix<T, 3, 1>> r(residual);
		r = sqrtInformation_.template cast<T>() * e;
		return true;
	}
	static ceres::CostFunction* create(const PoseEdge& e)
	{
		return new ceres::AutoDiffCostFunction<PoseEdgeCost, 3, 3, 3>(new PoseEdgeCost(e.z, sqrtOf(e.information)));
	}
	// U with U^T U = Omega (U = L^T of the Cholesky factor; a semidefinite Omega by its eigenvalues).
	static Eigen::Matrix3d sqrtOf(const Eigen::Matrix3d& information)
	{
		const Eigen::LLT<Eigen::Matrix3d> llt(information);
		if (llt.info() == Eigen::Success) return llt.matrixU();
		const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(information);
		return es.eigenvalues().cwiseMax(0.0).cwiseSqrt().asDiagonal() * es.eigenvectors().transpose();
	}

   private:
	mrpt::math::TPose2D z_;
	Eigen::Matrix3d sqrtInformation_;
};

// (x, y, phi) with phi kept in [-pi, pi) by every step, as the built-in optimiser wraps it.
struct PosePlus
{
	template <typename T>
	bool Plus(const T* x, const T* delta, T* out) const
	{
		out[0] = x[0] + delta[0], out[1] = x[1] + delta[1], out[2] = normalizeAngle(x[2] + delta[2]);
		return true;
	}
	template <typename T>
	bool Minus(const T* y, const T* x, T* delta) const
	{
		delta[0] = y[0] - x[0], delta[1] = y[1] - x[1], delta[2] = normalizeAngle(y[2] - x[2]);
		return true;
	}
};

/** Dynamic covariance scaling as an M-estimator of s = chi2: rho(s) = s up to Phi, then
 * 4 Phi s / (Phi + s) - Phi, so that rho'(s) = (2 Phi / (Phi + s))^2 is DCS's scale squared. */
class DcsLoss : public ceres::LossFunction
{
   public:
	explicit DcsLoss(double phi) : phi_(phi) {}
	void Evaluate(double s, double rho[3]) const override
	{
		if (s <= phi_)
		{
			rho[0] = s, rho[1] = 1, rho[2] = 0;
			return;
		}
		const double d = phi_ + s;
		rho[0] = 4 * phi_ * s / d - phi_;
		rho[1] = 4 * phi_ * phi_ / (d * d);
		rho[2] = -8 * phi_ * phi_ / (d * d * d);
	}

   private:
	double phi_;
};
}  // namespace

int solveWithCeres(std::vector<mrpt::math::TPose2D>& nodes, const std::vector<PoseEdge>& edges,
				   const std::array<double, 4>& phiByDof, bool robust, int maxIterations, double minRelativeDecrease)
{
	if (nodes.size() < 2) return 0;
	std::vector<std::array<double, 3>> x(nodes.size());
	for (size_t i = 0; i < nodes.size(); ++i) x[i] = {nodes[i].x, nodes[i].y, nodes[i].phi};
	ceres::Problem::Options po;
	po.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
	ceres::Problem problem(po);
	ceres::AutoDiffManifold<PosePlus, 3, 3> manifold;
	for (const auto& e : edges)
	{
		if (!e.active || e.from == e.to) continue;
		const double phi = phiByDof[std::clamp(e.dof, 1, 3)];
		ceres::LossFunction* loss =
			robust && e.kind != EdgeKind::Odometry && phi > 0 ? new DcsLoss(phi) : nullptr;
		problem.AddResidualBlock(PoseEdgeCost::create(e), loss, x[e.from].data(), x[e.to].data());
	}
	for (size_t i = 0; i < x.size(); ++i)
		if (problem.HasParameterBlock(x[i].data())) problem.SetManifold(x[i].data(), &manifold);
	if (!problem.HasParameterBlock(x[0].data())) return 0;
	problem.SetParameterBlockConstant(x[0].data());
	ceres::Solver::Options so;
	so.minimizer_type = ceres::TRUST_REGION;
	so.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
	so.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
	so.sparse_linear_algebra_library_type = ceres::SUITE_SPARSE;
	so.max_num_iterations = maxIterations;
	so.function_tolerance = minRelativeDecrease;
	so.num_threads = 1;
	so.logging_type = ceres::SILENT;
	ceres::Solver::Summary summary;
	ceres::Solve(so, &problem, &summary);
	for (size_t i = 1; i < nodes.size(); ++i)
		nodes[i] = mrpt::math::TPose2D(x[i][0], x[i][1], mrpt::math::wrapToPi(x[i][2]));
	return summary.num_successful_steps + summary.num_unsuccessful_steps;
}

}  // namespace gridvector
