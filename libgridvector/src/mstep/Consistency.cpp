#include "mstep/Consistency.h"
#include "mstep/GraphOptimisation.h"
#include <mrpt/math/TPose2D.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace gridvector
{
using Eigen::Matrix3d;
using Eigen::Vector3d;
using mrpt::math::TPose2D;

namespace
{
/** Information added to each edge's before inverting it (caps its std. dev. at 1 m and 0.32 rad): a near-singular
 * registration must not make the test's covariance singular. */
constexpr double kInfoXY = 1.0;  // [1/m^2]
constexpr double kInfoPhi = 10.0;  // [1/rad^2]
/** Variance of the local trajectory chain per scan step between the two edges' ends (times 1 + steps). */
constexpr double kChainVarXY = 1e-3;  // [m^2]
constexpr double kChainVarPhi = 1e-4;  // [rad^2]
/** An edge no other edge supports or contradicts is kept with at least this many correspondences, this matched
 * share and this translation degeneracy ratio (a registration that cannot be an alias or a corridor slide). */
constexpr size_t kStrongMinCorrespondences = 4;
constexpr double kStrongMinShare = 0.4;
constexpr double kStrongMinDegeneracy = 0.05;

const Matrix3d& regulariser()
{
	static const Matrix3d reg = Vector3d(kInfoXY, kInfoXY, kInfoPhi).asDiagonal();
	return reg;
}
}  // namespace

// Pairwise consistency of loop closures: a new overlap edge (j, i) is supported by
// another edge (j', i') near both of its ends when the cycle j -> i -> i' -> j' -> j
// closes within the edges' and the local chains' uncertainty (Mahalanobis gate).
Support supportOf(const Constraint& c, const std::map<EdgeKey, Constraint>& edges, const Poses& poses,
				  const MStepOptions& opts)
{
	const uint32_t K = uint32_t(std::max(1, opts.overlapRunGap));
	const Matrix3d& reg = regulariser();
	const Matrix3d covC = (graphInformation(c, opts) + reg).inverse();
	Support s;
	anyEdgeIn(edges, c.from > K ? c.from - K : 0, c.from + K, c.to > K ? c.to - K : 0, c.to + K,
			  [&](const EdgeKey&, const Constraint& o) {
		if (&o == &c || o.kind == EdgeKind::Sequential || o.rejected) return false;
		// z' predicted from z through the local chains of the current trajectory
		const TPose2D pred = ((poses[c.from] - poses[o.from]) + c.z) + (poses[o.to] - poses[c.to]);
		const Vector3d d = PoseGraph::error(TPose2D(0, 0, 0), pred, o.z);
		const double steps = std::abs(double(o.from) - c.from) + std::abs(double(o.to) - c.to);
		const Matrix3d chain = Vector3d(kChainVarXY, kChainVarXY, kChainVarPhi).asDiagonal() * (1.0 + steps);
		const Matrix3d cov = covC + (graphInformation(o, opts) + reg).inverse() + chain;
		(d.dot(cov.ldlt().solve(d)) < opts.consistencyChi2 ? s.support : s.against)++;
		return false;
	});
	return s;
}

bool strong(const Constraint& c)
{
	return c.correspondences.size() >= kStrongMinCorrespondences && c.matchedShare >= kStrongMinShare &&
		   c.degeneracy >= kStrongMinDegeneracy;
}

void verifyOverlaps(ConstraintSet& book, const MStepOptions& opts, const Poses& poses,
					const std::vector<EdgeKey>& fresh, MStepReport& rep)
{
	std::vector<EdgeKey> drop;
	for (const EdgeKey& key : fresh)
	{
		const Constraint& c = book.edges.at(key);
		const Support s = supportOf(c, book.edges, poses, opts);
		if (s.support > s.against || (s.support == 0 && s.against == 0 && strong(c))) continue;
		drop.push_back(key);
	}
	for (const EdgeKey& k : drop)
	{
		book.fail(k, poses[k.second] - poses[k.first]);
		++rep.unverified;
		auto r = book.replaced.find(k);
		if (r != book.replaced.end())
		{
			book.edges[k] = std::move(r->second);  // the weak edge it replaced stays
			--rep.recomputed;
			continue;
		}
		book.edges.erase(k);
		--rep.added;
	}
	book.replaced.clear();
}

}  // namespace gridvector
