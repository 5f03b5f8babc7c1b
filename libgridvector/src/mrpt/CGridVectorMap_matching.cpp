// CGridVectorMap: MRPT's matching API (CMetricMap::determineMatching2D and friends), so
// CICP can align a points map against the map's static vectors (beyond the paper).
#include "mrpt/StaticFootPoints.h"
#include "mrpt/CGridVectorMapImpl.h"
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/CPointsMap.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

using namespace mrpt::maps;
using gridvector::FootPoint;
using mrpt::math::TPoint2D;

namespace
{
const CPointsMap& pointsOf(const CMetricMap* other, const char* method)
{
	const auto* pts = dynamic_cast<const CPointsMap*>(other);
	if (!pts)
		throw std::invalid_argument(std::string("CGridVectorMap::") + method +
									": the other map must be a CPointsMap, not " +
									(other ? other->GetRuntimeClass()->className : "null"));
	return *pts;
}

mrpt::tfest::TMatchingPair pairOf(const FootPoint& f, size_t localIdx, float lx, float ly, float lz)
{
	// "global" is this map's point, "local" the other map's point in its own frame (MRPT >= 2.4 naming)
	mrpt::tfest::TMatchingPair m(f.slot, uint32_t(localIdx), float(f.at.x), float(f.at.y), lz, lx, ly, lz);
	m.errorSquareAfterTransformation = float(f.sqrDist);
	return m;
}

/** onlyUniqueRobust: of the pairs sharing one map place (vector, column) only the closest stays. */
void keepUniquePlaces(mrpt::tfest::TMatchingPairList& pairs, const std::vector<int>& columns)
{
	std::unordered_map<uint64_t, size_t> best;
	for (size_t k = 0; k < pairs.size(); ++k)
	{
		const uint64_t key = (uint64_t(pairs[k].globalIdx) << 32) | uint32_t(columns[k]);
		auto [it, fresh] = best.emplace(key, k);
		if (!fresh && pairs[k].errorSquareAfterTransformation < pairs[it->second].errorSquareAfterTransformation)
			it->second = k;
	}
	std::vector<bool> keep(pairs.size(), false);
	for (const auto& kv : best) keep[kv.second] = true;
	mrpt::tfest::TMatchingPairList out;
	out.reserve(best.size());
	for (size_t k = 0; k < pairs.size(); ++k)
		if (keep[k]) out.push_back(pairs[k]);
	pairs.swap(out);
}
}  // namespace

// Each point of the other map (a CPointsMap), moved by otherMapPose, to the nearest point of the
// static stretches (StaticFootPoints) within maxDist + maxAngularDist x its distance to the pivot.
void CGridVectorMap::determineMatching2D(const CMetricMap* otherMap, const mrpt::poses::CPose2D& otherMapPose,
										 mrpt::tfest::TMatchingPairList& correspondences, const TMatchingParams& params,
										 TMatchingExtraResults& extraResults) const
{
	extraResults = TMatchingExtraResults();
	correspondences.clear();
	const CPointsMap& other = pointsOf(otherMap, "determineMatching2D");
	const size_t dec = params.decimation_other_map_points, off = params.offset_other_map_points;
	if (dec == 0 || off >= dec)
		throw std::invalid_argument("CGridVectorMap::determineMatching2D: offset_other_map_points (" +
									std::to_string(off) + ") must be below decimation_other_map_points (" +
									std::to_string(dec) + "), which must be > 0");
	if (params.onlyUniqueRobust && !params.onlyKeepTheClosest)
		throw std::invalid_argument("CGridVectorMap::determineMatching2D: onlyUniqueRobust needs onlyKeepTheClosest");
	const size_t n = other.size();
	if (n <= off) return;
	const auto table = impl_->stretches.tableFor(impl_->map);
	const gridvector::StaticFootPoints feet(impl_->map, impl_->map.config(), table.get());
	const auto &xs = other.getPointsBufferRef_x(), &ys = other.getPointsBufferRef_y(),
			   &zs = other.getPointsBufferRef_z();
	const double c = std::cos(otherMapPose.phi()), s = std::sin(otherMapPose.phi());
	const TPoint2D pivot(params.angularDistPivotPoint.x, params.angularDistPivotPoint.y);
	std::vector<FootPoint> found;
	std::vector<int> columns;  // per pair, for onlyUniqueRobust
	size_t considered = 0, withCorr = 0;
	double sumSqr = 0;
	for (size_t i = off; i < n; i += dec)
	{
		++considered;
		const TPoint2D p(otherMapPose.x() + c * xs[i] - s * ys[i], otherMapPose.y() + s * xs[i] + c * ys[i]);
		// MRPT's gate: grows with the distance from the pivot (the sensor) by the angular tolerance
		const double gate = params.maxDistForCorrespondence +
							params.maxAngularDistForCorrespondence * std::hypot(p.x - pivot.x, p.y - pivot.y);
		found.clear();
		FootPoint f;
		if (params.onlyKeepTheClosest)
		{
			if (feet.nearest(p, gate, f)) found.push_back(f);
		}
		else
			feet.within(p, gate, found);
		if (found.empty()) continue;
		++withCorr;
		double closest = found[0].sqrDist;
		for (const FootPoint& g : found)
		{
			closest = std::min(closest, g.sqrDist);
			correspondences.push_back(pairOf(g, i, xs[i], ys[i], zs[i]));
			columns.push_back(g.column);
		}
		sumSqr += closest;
	}
	if (params.onlyUniqueRobust) keepUniquePlaces(correspondences, columns);
	extraResults.sumSqrDist = float(sumSqr);
	extraResults.correspondencesRatio = considered ? float(double(withCorr) / double(considered)) : 0.f;
}

// The share of the other map's points (3D pose, projected on the plane) within maxDistForCorr of a static stretch.
float CGridVectorMap::compute3DMatchingRatio(const CMetricMap* otherMap, const mrpt::poses::CPose3D& otherMapPose,
											 const TMatchingRatioParams& params) const
{
	const CPointsMap& other = pointsOf(otherMap, "compute3DMatchingRatio");
	if (other.size() == 0) return 0;
	const auto table = impl_->stretches.tableFor(impl_->map);
	const gridvector::StaticFootPoints feet(impl_->map, impl_->map.config(), table.get());
	size_t matched = 0;
	FootPoint f;
	for (size_t i = 0; i < other.size(); ++i)
	{
		double x, y, z;
		otherMapPose.composePoint(other.getPointsBufferRef_x()[i], other.getPointsBufferRef_y()[i],
								  other.getPointsBufferRef_z()[i], x, y, z);
		matched += feet.nearest(TPoint2D(x, y), params.maxDistForCorr, f);
	}
	return float(double(matched) / double(other.size()));
}

// Squared distance to the nearest static point of the map, no gate (as a points map's nearest neighbour).
float CGridVectorMap::squareDistanceToClosestCorrespondence(float x0, float y0) const
{
	const auto table = impl_->stretches.tableFor(impl_->map);
	const gridvector::StaticFootPoints feet(impl_->map, impl_->map.config(), table.get());
	FootPoint f;
	return feet.nearestAnywhere(TPoint2D(x0, y0), f) ? float(f.sqrDist) : std::numeric_limits<float>::max();
}
