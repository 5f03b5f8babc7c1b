// CGridVectorMap: observation likelihood as a likelihood field over the vectors,
// each weighted by the occupancy (n_occupy / n_visit) of the cell the point falls in.
#include <gridvector/OccupancyConversion.h>
#include <gridvector/VectorIndex.h>
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

double CGridVectorMap::internal_computeObservationLikelihood(
	const mrpt::obs::CObservation& obs, const mrpt::poses::CPose3D& takenFrom) const
{
	const auto* scan = dynamic_cast<const mrpt::obs::CObservation2DRangeScan*>(&obs);
	if (!scan || isEmpty()) return 0;
	std::vector<TPoint2D> pts;
	std::vector<size_t> runs;
	extractor_.scanToRuns(*scan, pts, runs);
	const double c = std::cos(takenFrom.yaw()), s = std::sin(takenFrom.yaw());
	double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
	for (auto& p : pts)
	{
		p = TPoint2D(takenFrom.x() + c * p.x - s * p.y, takenFrom.y() + s * p.x + c * p.y);
		xmin = std::min(xmin, p.x), xmax = std::max(xmax, p.x);
		ymin = std::min(ymin, p.y), ymax = std::max(ymax, p.y);
	}
	// Only vectors near the scan, through the map's spatial index: O(nearby vectors).
	const double m = likelihoodOptions.maxCorrDistance;
	std::vector<uint32_t> slots;
	map_.index().query(gridvector::Box2D{xmin, ymin, xmax, ymax}.expanded(m), slots);
	std::vector<const GridVector*> near;
	near.reserve(slots.size());
	for (uint32_t s : slots) near.push_back(&map_.vectors()[s]);
	const double inv2s2 = 1.0 / (2 * likelihoodOptions.sigma * likelihoodOptions.sigma);
	const double zr = likelihoodOptions.zRandom, zh = 1.0 - zr;
	const double prior = gridvector::OccupancyConversion::priorRatio(map_.config().grid);
	double logLik = 0;
	for (size_t i = 0; i < pts.size(); i += size_t(likelihoodOptions.decimation))
	{
		double best = m;
		const GridVector* bestV = nullptr;
		for (const GridVector* v : near)
		{
			const double d = distanceToSegment(*v, pts[i]);
			if (d < best) best = d, bestV = v;
		}
		const double hit = bestV ? occupancyNear(*bestV, pts[i], prior) * std::exp(-best * best * inv2s2) : 0.0;
		logLik += std::log(zh * hit + zr);
	}
	return logLik;
}
