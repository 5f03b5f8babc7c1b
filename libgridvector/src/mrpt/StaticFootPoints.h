// Nearest points on the static parts of the map's vectors (Eq. 14, Fig. 4), for
// point-to-map correspondences (CGridVectorMap's matching API, beyond the paper).
#pragma once

#include "estep/EStep.h"
#include "map/GlobalMap.h"
#include "mrpt/StaticStretchCache.h"

#include <mrpt/math/TPoint2D.h>

#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace gridvector
{
/** The closest point of one vector's static stretches to a query point. */
struct FootPoint
{
	uint32_t slot = 0;  //!< index of the vector in GlobalMap::vectors()
	int column = 0;  //!< grid column of the vector the foot point lies in
	mrpt::math::TPoint2D at;  //!< on the vector's line (its grid's centre row), world frame
	double sqrDist = 0;  //!< squared distance from the query point [m^2]
};

/** Where a map point may correspond to a measured point: the stretches of the
 * vectors whose columns the E-step's Fig. 4 profile (EStep::profile) puts at or
 * above matching.static_threshold (0, the default: every column), on vectors not
 * classified dynamic (Eq. 14: state Dynamic). With a threshold (0.5: the E-step's
 * split), a door leaf seen in one state and later seen through, an object that stood
 * for a while: their columns read low, so scan points on them find no
 * correspondence on the map even where no E-step has run.
 *
 * Candidates come from the map's spatial index (GlobalMap::index()), so a query
 * of radius r costs O((r/B + 1)^2 + k) with B the index bucket and k the vectors
 * near the point. A vector's static stretches are computed on first use, once per
 * finder, or once per map state with a StaticStretchTable of the map's revision
 * (CGridVectorMap keeps one: its matching calls share it). The finder is meant to
 * live for one matching call: the map must not change meanwhile. Its own cache and
 * scratch are its own: one finder per thread; any number of finders may read one
 * map and one table at once (the index's query writes nothing, the table fills
 * each entry once). */
class StaticFootPoints
{
   public:
	/** `table`: the stretches shared between finders, for the map's current revision (or none). */
	StaticFootPoints(const GlobalMap& map, const GridVectorConfig& cfg, const StaticStretchTable* table = nullptr);

	/** For every vector with a static stretch within `radius` of p, its nearest
	 * static point (one per vector), appended to out unordered. */
	void within(const mrpt::math::TPoint2D& p, double radius, std::vector<FootPoint>& out) const;
	/** The nearest static point within `radius` of p; false if there is none. */
	bool nearest(const mrpt::math::TPoint2D& p, double radius, FootPoint& out) const;
	/** The nearest static point anywhere (the search radius doubles from the index
	 * bucket size until the box holds a nearer point or covers every vector);
	 * false if the map has no static stretch at all. */
	bool nearestAnywhere(const mrpt::math::TPoint2D& p, FootPoint& out) const;

	/** A vector's static stretches [u0, u1] along it (metres from its start), in order. */
	const std::vector<std::pair<double, double>>& stretches(uint32_t slot) const;

   private:
	std::vector<std::pair<double, double>> computeStretches(const GridVector& v) const;
	/** The nearest static point within `radius` of p among the vectors of the last index query. */
	bool nearestAmongSlots(const mrpt::math::TPoint2D& p, double radius, FootPoint& out) const;
	/** v's nearest static point to p, if any lies within `radius`. */
	bool footOn(uint32_t slot, const mrpt::math::TPoint2D& p, double radius, FootPoint& out) const;

	const GlobalMap& map_;
	const StaticStretchTable* table_;
	EStep estep_;
	double threshold_;
	mutable std::unordered_map<uint32_t, std::vector<std::pair<double, double>>> stretches_;
	mutable std::vector<uint32_t> slots_;  //!< scratch for index queries
};

}  // namespace gridvector
