// CGridVectorMap: observation likelihood as a likelihood field over the vectors (MRPT's
// likelihood-field model), each vector weighted by its wall row's occupancy (n_occupy / n_visit).
#include "map/VectorIndex.h"
#include "mrpt/CGridVectorMapImpl.h"
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <algorithm>
#include <cmath>

using namespace mrpt::maps;
using gridvector::GridVector;
using mrpt::math::TPoint2D;

namespace
{
/** A point's hit term through one vector: the Gaussian of its distance d to the segment, weighted
 * by the occupancy of the vector's own row (the wall, Eq. 2's centre row) at the column of the
 * point's foot. The wall row's, not the cell the point falls in: the rows beside the wall read
 * free on the open side and prior behind it, which would pull every point behind the walls. */
double hitThrough(const GridVector& v, const TPoint2D& p, double inv2s2)
{
	const TPoint2D g = v.toGridFrame(p);
	const double u = std::clamp(g.x, 0.0, v.length());
	const double d2 = (g.x - u) * (g.x - u) + g.y * g.y;
	const int col = std::min(v.cols() - 1, int(u / v.resolution()));
	return v.cell(v.halfWidth(), col).occupancy(v.priorRatio()) * std::exp(-d2 * inv2s2);
}
}  // namespace

bool CGridVectorMap::internal_canComputeObservationLikelihood(const mrpt::obs::CObservation& obs) const
{
	return dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs) != nullptr && !isEmpty();
}

double CGridVectorMap::internal_computeObservationLikelihood(const mrpt::obs::CObservation& obs,
															 const mrpt::poses::CPose3D& takenFrom) const
{
	const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs);
	if (!scan || isEmpty()) return 0;
	// per-thread scratch: a particle filter calls this once per particle with the same scan
	thread_local std::vector<TPoint2D> pts;
	thread_local std::vector<uint32_t> slots;
	impl_->extractor.scanToPoints(*scan, pts, size_t(likelihoodOptions.decimation));
	const double c = std::cos(takenFrom.yaw()), s = std::sin(takenFrom.yaw());
	const double m = likelihoodOptions.maxCorrDistance;
	const double inv2s2 = 1.0 / (2 * likelihoodOptions.sigma * likelihoodOptions.sigma);
	const double zr = likelihoodOptions.zRandom, zh = 1.0 - zr;
	// as MRPT's likelihood field: a point with no map place within maxCorrDistance reads as one that far
	// from a wall, and so does a point near vectors that are mostly seen free (the field never dips below it)
	const double floorHit = std::exp(-m * m * inv2s2);
	double logLik = 0;
	for (size_t i = 0; i < pts.size(); ++i)
	{
		const TPoint2D p(takenFrom.x() + c * pts[i].x - s * pts[i].y, takenFrom.y() + s * pts[i].x + c * pts[i].y);
		// Only the vectors within maxCorrDistance of this point, through the map's spatial index.
		slots.clear();
		impl_->map.index().query(gridvector::Box2D{p.x, p.y, p.x, p.y}.expanded(m), slots);
		double hit = floorHit;
		for (uint32_t slot : slots) hit = std::max(hit, hitThrough(impl_->map.vectors()[slot], p, inv2s2));
		logLik += std::log(zh * hit + zr);
	}
	return logLik;
}
