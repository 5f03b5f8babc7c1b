// Sec. 5.5, Table 1: memory of the grid vector map against an occupancy grid of the same area.
#pragma once

#include <gridvector/GridVector.h>

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace gridvector
{
/** Table 1 for one map, plus the full honest count.
 *
 * Table 1's numbers: n_g = space size / 0.1^2 (678.56 m^2 -> 67 856) and
 * n_v = vector length / 0.1 m (194.73 m -> 1947, 93.50 m -> 935; 47.04 m ->
 * 471 is within the rounding of the printed length): one cell per 10 cm of
 * vector, i.e. the width of the slender grid is not counted. `cells` counts
 * it (rows x columns of every vector), and the bytes compare what each
 * representation really holds in memory: the map as it is held once built
 * (CompactMap: its buffer and the object) and, for comparison, the working
 * form the EM loop edits (GridVector objects, their float cells' capacity and
 * the vector of them's capacity). */
struct MemoryReport
{
	double resolution = 0.1;  //!< of the reference occupancy grid and of n_v [m]
	double xMin = 0, yMin = 0, xMax = 0, yMax = 0;  //!< bounding box of the vectors' endpoints
	double spaceSize = 0;  //!< its area [m^2]
	size_t vectorCount = 0;
	double vectorLength = 0;  //!< sum of lengths [m]
	size_t n_g = 0;  //!< occupancy grid cells over the space (Table 1)
	size_t n_v = 0;  //!< grid vector cells as in Table 1: length / resolution
	double ratio = 0;  //!< n_g / n_v (Table 1)
	size_t columns = 0;  //!< sum of the vectors' grid columns
	size_t cells = 0;  //!< sum of rows x columns (the width counted)
	double ratioCells = 0;  //!< n_g / cells
	size_t bytesPerGridCell = 1;  //!< sizeof(COccupancyGridMap2D::cellType)
	size_t bytesGrid = 0;  //!< n_g * bytesPerGridCell
	size_t bytesGridVector = 0;  //!< CompactMap::encode(vectors).memoryBytes(): the map as held
	double ratioBytes = 0;  //!< bytesGrid / bytesGridVector
	/** capacity * sizeof(GridVector) + cells' capacity * sizeof(GridCell), summed: the working form. */
	size_t bytesWorkingForm = 0;
	double ratioBytesWorkingForm = 0;  //!< bytesGrid / bytesWorkingForm
	size_t bytesFile = 0;  //!< the saved .gvmap (gzip), when the caller sets it (0: not saved)
	double ratioBytesFile = 0;  //!< bytesGrid / bytesFile
};

class MemoryAccounting
{
   public:
	static MemoryReport account(const std::vector<GridVector>& vectors, double resolution = 0.1);
	/** Sets bytesFile (and its ratio) from a saved map's size on disk. */
	static void setFileBytes(MemoryReport& r, size_t bytes);
	/** One JSON object (keys as the fields, snake_case), in the order of the fields. */
	static nlohmann::ordered_json toJson(const MemoryReport& r);
	/** io::writeJsonFile(path, toJson(r)): atomically; throws std::runtime_error("path: cannot write (...)"). */
	static void writeJson(const MemoryReport& r, const std::string& path);
	/** A few human-readable lines. */
	static std::string summary(const MemoryReport& r);
};

}  // namespace gridvector
