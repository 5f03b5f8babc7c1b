// Sec. 4.2, Eq. 21-22: graph-based maximum-likelihood trajectory estimation.
#pragma once

#include <gridvector/GridVectorConfig.h>

#include <Eigen/Core>
#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/math/TPose2D.h>

#include <array>
#include <cstdint>
#include <vector>

namespace gridvector
{
enum class EdgeKind : uint8_t
{
	Odometry = 0,  //!< u_t between consecutive poses (never robustified)
	Sequential,  //!< registration against a recent predecessor
	Overlap,  //!< registration between poses whose scans overlap
	Loop  //!< registration found by the loop search
};
const char* toString(EdgeKind k);

/** An edge <j, i> ~ N(delta_ji, Sigma_ji) (Eq. 21): z is the pose of `to`
 * seen from `from`, `information` = Sigma^-1 over (x, y, phi). */
struct PoseEdge
{
	uint32_t from = 0, to = 0;
	mrpt::math::TPose2D z;
	Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
	EdgeKind kind = EdgeKind::Odometry;
	/** Degrees of freedom `information` constrains (2: a corridor registration with its
	 * along-corridor direction marginalised out); the robust kernel and the chi2 test
	 * compare its chi2 with their levels moved to the same tail probability. */
	int dof = 3;
	bool active = true;  //!< false once rejected by its residual
	double chi2 = 0;  //!< e^T Omega e at the last optimisation
	double scale = 1;  //!< robust (DCS) scale at the last optimisation
};

struct OptimizeStats
{
	int iterations = 0;
	double initialError = 0, finalError = 0;  //!< sum of robust chi2 (Eq. 22)
	size_t rejected = 0;  //!< edges deactivated by the chi2 test
	double seconds = 0;
};

/** Nodes x_0..x_{n-1} (x_0 fixed) and edges; stored so they convert to
 * MRPT's CNetworkOfPoses2DInf. optimize() minimises Eq. 22 either with the
 * built-in sparse Gauss-Newton/Levenberg-Marquardt (CHOLMOD supernodal LL^T,
 * dynamic covariance scaling on registration edges) or with MRPT's
 * optimize_graph_spa_levmarq; both then deactivate edges whose chi2 stays
 * above reject_chi2 and re-optimise. The paper minimises Eq. 22 by stochastic
 * gradient descent (Eq. 23) on a tree parameterisation (Sec. 4.3); a sparse
 * Cholesky step solves the same least-squares problem exactly. Ceres' Levenberg-Marquardt on the
 * same residuals, kernel and graduation was no more accurate and 3-10x slower in the optimiser
 * (doc/benchmarks-history.md), so the built-in one stays. */
class PoseGraph
{
   public:
	explicit PoseGraph(const PoseGraphOptions& opts = {});

	void setNodes(std::vector<mrpt::math::TPose2D> nodes) { nodes_ = std::move(nodes); }
	const std::vector<mrpt::math::TPose2D>& nodes() const { return nodes_; }
	size_t addEdge(const PoseEdge& e);
	void clearEdges() { edges_.clear(); }
	std::vector<PoseEdge>& edges() { return edges_; }
	const std::vector<PoseEdge>& edges() const { return edges_; }

	/** Eq. 22. `graduate`: the robust kernel starts wide (graduation_start_phi) whatever the start's fit,
	 * as for a loop-search edge far from it (for a caller whose new edges join places the start misplaces). */
	OptimizeStats optimize(bool graduate = false);

	/** e = z^-1 (+) (x_from^-1 (+) x_to), angle wrapped (Eq. 21's f - delta). */
	static Eigen::Vector3d error(const mrpt::math::TPose2D& xi, const mrpt::math::TPose2D& xj,
								 const mrpt::math::TPose2D& z);
	/** A registration's information (over z = (x, y, phi), the later pose in the earlier
	 * one's frame, as VectorMatcher gives it) in the frame of error(): its translation is
	 * in z's frame, so the information is D^T I D with D = diag(R(z.phi), 1). */
	static Eigen::Matrix3d errorFrameInformation(const Eigen::Matrix3d& information, const mrpt::math::TPose2D& z);
	/** Does a loop-search edge with this chi2 at the start need a correction so large that Eq. 22
	 * graduates its robust kernel (chi2 > graduation_trigger x robust_kernel_width)? */
	static bool farLoop(double chi2, const PoseGraphOptions& o) { return chi2 > o.graduationTrigger * o.robustKernelWidth; }
	/** Odometry edge information from the motion model of the options. */
	static Eigen::Matrix3d odometryInformation(const mrpt::math::TPose2D& delta, const PoseGraphOptions& o);

	mrpt::graphs::CNetworkOfPoses2DInf toMrpt(bool activeOnly = true) const;

	/** The chi2 level with `dof` (1-3) degrees of freedom whose upper tail probability
	 * equals that of `level3` with 3: the robust kernel's width and reject_chi2 are set
	 * for full-rank edges and moved to an edge's own dof by this. */
	static double levelForDof(double level3, int dof);
	/** levelForDof for 1, 2 and 3 dof, indexed by dof (index 0: level3). */
	static std::array<double, 4> levelsByDof(double level3);

   private:
	OptimizeStats optimizeGaussNewton(bool graduate);
	OptimizeStats levenbergMarquardt(int maxIterations, double minRelativeDecrease);
	double updateResiduals(const std::vector<mrpt::math::TPose2D>& x, bool robust);
	/** Sum of scale^2 chi2 at x with every edge's DCS scale as it is (the cost the linearisation minimises). */
	double fixedScaleCost(const std::vector<mrpt::math::TPose2D>& x) const;
	size_t rejectOutliers();

	PoseGraphOptions opts_;
	std::vector<mrpt::math::TPose2D> nodes_;
	std::vector<PoseEdge> edges_;
	double phi_ = 1;  //!< current DCS width
};

}  // namespace gridvector
