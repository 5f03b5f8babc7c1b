// Sec. 4.2: vector-matching scan registration in the manner of Sohn & Kim (2008).
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <Eigen/Core>
#include <mrpt/math/TPose2D.h>

#include <cstdint>
#include <vector>

namespace gridvector
{
/** A static vector reduced to what registration needs, in its scan's frame. */
struct MatchSegment
{
	Eigen::Vector2d s{0, 0}, e{0, 0};  //!< start and terminal point (open space on the left)
	double length = 0;
	uint64_t id = 0;  //!< the grid vector's id (for M_cor, Eq. 25)
	double sigma = 0;  //!< its scanner's range std. dev. (LocalScan::rangeSigma) [m]

	static MatchSegment from(const GridVector& v, double sigma = 0);
	static std::vector<MatchSegment> fromVectors(const std::vector<GridVector>& v, double sigma = 0);
};

/** One correspondence: vector `a` of scan A matches vector `b` of scan B. */
struct VectorPair
{
	uint64_t a = 0, b = 0;
	bool operator==(const VectorPair& o) const { return a == o.a && b == o.b; }
	bool operator<(const VectorPair& o) const { return a < o.a || (a == o.a && b < o.b); }
};

enum class MatchStatus : uint8_t
{
	Ok = 0,
	TooFewMatches,  //!< fewer than min_matches pairs or min_matched_length metres
	HighResidual,  //!< RMS point-to-line residual above max_rms
	Degenerate  //!< rotation not observable (no usable geometry)
};
const char* toString(MatchStatus s);

/** Outcome of one registration of scan B against scan A. */
struct MatchResult
{
	MatchStatus status = MatchStatus::TooFewMatches;
	mrpt::math::TPose2D pose;  //!< pose of B's frame in A's frame (x_A^-1 (+) x_B)
	/** Information of (x, y, phi) from the least-squares Hessian J^T W J over
	 * point-to-line residuals divided by the residual variance: a direction
	 * no matched line constrains (a corridor's axis) has information ~0. */
	Eigen::Matrix3d information = Eigen::Matrix3d::Zero();
	std::vector<VectorPair> pairs;  //!< correspondences at the solution (sorted)
	double matchedLength = 0;  //!< sum of overlaps of the matched pairs [m]
	double matchedShare = 0;  //!< matchedLength / shorter scan's total length (<= 1)
	double rms = 0;  //!< length-weighted RMS point-to-line residual [m]
	double translationDegeneracy = 1;  //!< smallest / largest eigenvalue of the translation block
	/** Degrees of freedom `information` constrains (the pose graph's kernel and chi2 test
	 * compare an edge's chi2 at its own dof): always 3, the weak direction is scaled down. */
	int dof = 3;
	int iterations = 0;
	bool ok() const { return status == MatchStatus::Ok; }
};

/** Gates of the three correspondence criteria of Sec. 3.2. */
struct MatchGates
{
	double psi = 0.1;  //!< criterion 1: |psi_a - psi_b| [rad]
	double rho = 0.15;  //!< criterion 2: line offset at each other's centre [m]
	double minOverlap = 0.1;  //!< overlap along the line [m]
};

/** Registers the static vectors of two scans.
 *
 * Each iteration: transform B by the current estimate; correspondences by the
 * three criteria of Sec. 3.2 (direction psi, line (theta, rho), centres closer
 * than half the summed lengths) with gates that start wide and tighten;
 * while the gates are wider than their final values, the rotation from the
 * overlap-weighted angle differences (it brings the rotation into the basin);
 * then a Gauss-Newton step on point-to-line distances of the overlap-clipped
 * segments (integrated exactly along each segment by Simpson's rule) with Cauchy
 * weights, at the final gates alone, so the fit converges to the point-to-line
 * optimum (short vectors' angles are noisy and biased: an angle step there pulls
 * the estimate off it every iteration).
 * One workspace per matcher, written by its const members: one matcher per
 * thread. MStep, LoopSearch and the graphslam deciders each own one and call it
 * from the one thread that drives them; CGridVectorMap's const members use none.
 * Allocation-free once warm. */
class VectorMatcher
{
   public:
	explicit VectorMatcher(const MatcherOptions& opts = {});

	MatchResult match(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
					  const mrpt::math::TPose2D& guess) const;

	/** Correspondences under a fixed pose (no optimisation); returns the
	 * matched overlap length. Used to detect overlap and changed M_cor. */
	double correspondences(const std::vector<MatchSegment>& a, const std::vector<MatchSegment>& b,
						   const mrpt::math::TPose2D& pose, const MatchGates& gates,
						   std::vector<VectorPair>* out) const;

	const MatcherOptions& options() const { return opts_; }
	MatchGates finalGates(double factor = 1.0) const;
	/** matcher.step_within_gates: the factor (<= 1) that keeps a Gauss-Newton step (dx, dy, dphi)
	 * within `gates` (translation <= rho, rotation <= psi), its direction unchanged; match() bounds
	 * each step by the gates of its iteration. */
	static double stepScale(const Eigen::Vector3d& delta, const MatchGates& gates);

	/** One candidate correspondence with its overlap-clipped support on B. */
	struct Pair
	{
		int ia = 0, ib = 0;
		double s0 = 0, s1 = 1;  //!< clipped parameter range along b (0 = start, 1 = terminal)
		double overlap = 0;  //!< [m]
		double weight = 1;  //!< robust weight
	};

   private:
	/** Segment geometry in A's frame. */
	struct Geom
	{
		Eigen::Vector2d s, d, n, c;  //!< start, unit direction, left normal, centre
		double len = 0;
	};
	static void geometryOf(const MatchSegment& m, const mrpt::math::TPose2D& T, Geom& g);
	void prepareA(const std::vector<MatchSegment>& a) const;
	void transformB(const std::vector<MatchSegment>& b, const mrpt::math::TPose2D& T) const;
	void gather(const MatchGates& g) const;
	double rotationStep() const;
	void rotateAboutMatchedCentre(mrpt::math::TPose2D& T) const;
	void normalEquations(const std::vector<MatchSegment>& b, const mrpt::math::TPose2D& T, double robustScale,
						 Eigen::Matrix3d& H, Eigen::Vector3d& g, double& sumW, double& sumWr2) const;
	MatchGates gatesAt(int iteration) const;

	MatcherOptions opts_;
	// workspace (reused, never shrinks)
	mutable std::vector<Geom> ga_, gb_;  //!< A's and transformed B's geometry
	mutable std::vector<Pair> pairs_;
};

}  // namespace gridvector
