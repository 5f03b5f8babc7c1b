// Sec. 3.2: the global grid vector map M = {x_t (+) V_t}, merged (Eq. 4).
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>
#include <gridvector/VectorExtractor.h>

#include <mrpt/math/TPose2D.h>

#include <vector>

namespace gridvector
{
/** The global map: vectors in world coordinates. insertScan() does the
 * pose compounding m = x (+) v, the wipe-triangle update of Eq. 8 and, when
 * configured, correspondence + Algorithm 2 merging. */
class GlobalMap
{
   public:
	explicit GlobalMap(const GridVectorConfig& cfg = {});

	void clear();
	bool empty() const { return vectors_.empty(); }
	size_t size() const { return vectors_.size(); }
	const std::vector<GridVector>& vectors() const { return vectors_; }
	const GridVectorConfig& config() const { return cfg_; }
	void setConfig(const GridVectorConfig& cfg) { cfg_ = cfg; }

	/** Insert V_t observed from robot pose x_t. */
	void insertScan(const mrpt::math::TPose2D& robotPose, const LocalScan& scan);

	/** Replace the content (deserialisation, EM rebuilds). */
	void setVectors(std::vector<GridVector> v);

   private:
	GridVectorConfig cfg_;
	std::vector<GridVector> vectors_;
	uint64_t nextId_ = 1;
};

}  // namespace gridvector
