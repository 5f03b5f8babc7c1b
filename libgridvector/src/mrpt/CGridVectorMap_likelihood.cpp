// CGridVectorMap: observation likelihood as a likelihood field over the vectors,
// each weighted by the occupancy (n_occupy / n_visit) of the cell the point falls in.
#include "map/OccupancyConversion.h"
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
double distanceToSegment(const GridVector& v, const TPoint2D& p)
{
	const TPoint2D g = v.toGridFrame(p);
	const double u = std::clamp(g.x, 0.0, v.length());
	return std::hypot(g.x - u, g.y);
}

// Occupancy of the cell of v nearest to p (the prior's ratio where no cell covers p or the cell has no counts).
double occupancyNear(const GridVector& v, const TPoint2D& p, double prior)
{
	int row, col;
	if (!v.cellOf(p, row, col)) return prior;
	return v.cell(row, col).occupancy(prior);
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
	const double prior = gridvector::OccupancyConversion::priorRatio(impl_->map.config().grid);
	double logLik = 0;
	for (size_t i = 0; i < pts.size(); ++i)
	{
		const TPoint2D p(takenFrom.x() + c * pts[i].x - s * pts[i].y, takenFrom.y() + s * pts[i].x + c * pts[i].y);
		// Only the vectors within maxCorrDistance of this point, through the map's spatial index.
		slots.clear();
		impl_->map.index().query(gridvector::Box2D{p.x, p.y, p.x, p.y}.expanded(m), slots);
		double best = m;
		const GridVector* bestV = nullptr;
		for (uint32_t slot : slots)
		{
			const GridVector& v = impl_->map.vectors()[slot];
			const double d = distanceToSegment(v, p);
			if (d < best) best = d, bestV = &v;
		}
		const double hit = bestV ? occupancyNear(*bestV, p, prior) * std::exp(-best * best * inv2s2) : 0.0;
		logLik += std::log(zh * hit + zr);
	}
	return logLik;
}
