#include <gridvector/GlobalMap.h>

namespace gridvector
{
GlobalMap::GlobalMap(const GridVectorConfig& cfg) : cfg_(cfg) {}

void GlobalMap::clear()
{
	vectors_.clear();
	nextId_ = 1;
}

void GlobalMap::setVectors(std::vector<GridVector> v)
{
	vectors_ = std::move(v);
	nextId_ = 1;
	for (const auto& g : vectors_) nextId_ = std::max(nextId_, g.id + 1);
}

// m_{i,t} = x_t (+) v_{i,t} (Sec. 3.2). Wipe triangles and merging: see issue #4.
void GlobalMap::insertScan(const mrpt::math::TPose2D& robotPose, const LocalScan& scan)
{
	for (const auto& v : scan.vectors)
	{
		GridVector m = v.compose(robotPose);
		m.scanIndex = scan.scanIndex;
		m.timestamp = scan.timestamp;
		m.id = nextId_++;
		vectors_.push_back(std::move(m));
	}
}

}  // namespace gridvector
