// Sec. 3.2 + Sec. 4.1 in sequential mode: the merged map (Eq. 4, Eq. 8 scan by scan) with the E-step
// (Eq. 14-15, Fig. 4) run on the vectors each scan touched, so every vector's state is known at once.
#pragma once

#include "estep/EStep.h"
#include "map/GlobalMap.h"

#include <gridvector/GridVectorConfig.h>
#include <gridvector/LocalScan.h>

#include <mrpt/math/TPose2D.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace gridvector
{
/** A GlobalMap in sequential mode (insertScan) whose vectors carry the E-step's verdict.
 *
 * insert(): Eq. 8 and Algorithm 2 as GlobalMap::insertScan, then Fig. 4's split-and-merge of the
 * occupancy profile (EStep::split) on every map vector whose band meets the box of the sensor and
 * the scan's vectors: the only vectors the scan's wipe triangles and merges can have changed. The
 * cost of a scan is that of the vectors near the robot, not of the map's size. */
class ClassifiedMap
{
   public:
	explicit ClassifiedMap(const GridVectorConfig& cfg = {});

	/** Inserts the scan observed from `pose` and classifies what it touched; returns how many vectors. */
	size_t insert(const mrpt::math::TPose2D& pose, const LocalScan& scan);

	const GlobalMap& map() const { return map_; }
	size_t size() const { return map_.size(); }

	/** Eq. 14 for one map vector as of the last scan that touched it: Static or Dynamic when all its
	 * pieces (Fig. 4) agree, Unknown when it is part static and part dynamic or was never classified. */
	VectorState stateOf(const GridVector& v) const;
	/** Fig. 4's pieces of a map vector by id (null: not classified). */
	const std::vector<ProfilePiece>* piecesOf(uint64_t id) const;

	/** Every map vector split into its children (Eq. 14), state set: static and dynamic vectors. */
	std::vector<GridVector> children() const;

   private:
	/** Drops the verdicts of vectors merged away, once they outnumber the map's vectors. */
	void prune();

	GridVectorConfig cfg_;
	GlobalMap map_;
	EStep estep_;
	std::unordered_map<uint64_t, std::vector<ProfilePiece>> pieces_;  //!< by map vector id
	std::vector<uint32_t> touched_;  //!< workspace
};

}  // namespace gridvector
