#include "map/MemoryAccounting.h"
#include "map/CompactMap.h"
#include "io/JsonFile.h"

#include <nlohmann/json.hpp>

#include <mrpt/maps/COccupancyGridMap2D.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace gridvector
{
// Table 1.
MemoryReport MemoryAccounting::account(const std::vector<GridVector>& vectors, double resolution)
{
	MemoryReport r;
	r.resolution = resolution;
	r.vectorCount = vectors.size();
	r.bytesPerGridCell = sizeof(mrpt::maps::COccupancyGridMap2D::cellType);
	if (vectors.empty()) return r;
	r.xMin = r.yMin = 1e300;
	r.xMax = r.yMax = -1e300;
	for (const GridVector& v : vectors)
	{
		for (const auto& p : {v.start(), v.end()})
		{
			r.xMin = std::min(r.xMin, p.x), r.xMax = std::max(r.xMax, p.x);
			r.yMin = std::min(r.yMin, p.y), r.yMax = std::max(r.yMax, p.y);
		}
		r.vectorLength += v.length();
		r.columns += size_t(v.cols());
		r.cells += v.cells().size();
		r.bytesWorkingForm += v.cells().capacity() * sizeof(GridCell);
	}
	r.bytesWorkingForm += vectors.capacity() * sizeof(GridVector);
	r.bytesGridVector = CompactMap::encode(vectors).memoryBytes();
	r.spaceSize = (r.xMax - r.xMin) * (r.yMax - r.yMin);
	r.n_g = size_t(std::llround(r.spaceSize / (resolution * resolution)));
	r.n_v = size_t(std::llround(r.vectorLength / resolution));
	r.ratio = r.n_v ? double(r.n_g) / r.n_v : 0;
	r.ratioCells = r.cells ? double(r.n_g) / r.cells : 0;
	r.bytesGrid = r.n_g * r.bytesPerGridCell;
	r.ratioBytes = r.bytesGridVector ? double(r.bytesGrid) / r.bytesGridVector : 0;
	r.ratioBytesWorkingForm = r.bytesWorkingForm ? double(r.bytesGrid) / r.bytesWorkingForm : 0;
	return r;
}

void MemoryAccounting::setFileBytes(MemoryReport& r, size_t bytes)
{
	r.bytesFile = bytes;
	r.ratioBytesFile = bytes ? double(r.bytesGrid) / bytes : 0;
}

nlohmann::ordered_json MemoryAccounting::toJson(const MemoryReport& r)
{
	return {{"resolution_m", r.resolution},
			{"bounding_box", {{"x_min", r.xMin}, {"y_min", r.yMin}, {"x_max", r.xMax}, {"y_max", r.yMax}}},
			{"space_size_m2", r.spaceSize},
			{"vector_count", r.vectorCount},
			{"vector_length_m", r.vectorLength},
			{"n_g", r.n_g},
			{"n_v", r.n_v},
			{"ratio_ng_nv", r.ratio},
			{"grid_vector_columns", r.columns},
			{"grid_vector_cells", r.cells},
			{"ratio_ng_cells", r.ratioCells},
			{"bytes_per_grid_cell", r.bytesPerGridCell},
			{"bytes_occupancy_grid", r.bytesGrid},
			{"bytes_grid_vector_map", r.bytesGridVector},
			{"ratio_bytes", r.ratioBytes},
			{"bytes_working_form", r.bytesWorkingForm},
			{"ratio_bytes_working_form", r.ratioBytesWorkingForm},
			{"bytes_gvmap_file", r.bytesFile},
			{"ratio_bytes_gvmap_file", r.ratioBytesFile}};
}

void MemoryAccounting::writeJson(const MemoryReport& r, const std::string& path) { io::writeJsonFile(path, toJson(r)); }

std::string MemoryAccounting::summary(const MemoryReport& r)
{
	char buf[800];
	std::snprintf(buf, sizeof buf,
				  "space %.2f m^2, %zu vectors, %.2f m long\n"
				  "Table 1: n_g = %zu, n_v = %zu, n_g/n_v = %.2f (%.0f cm cells)\n"
				  "with the grid width: %zu cells, n_g/cells = %.2f\n"
				  "bytes: occupancy grid %zu (%zu B/cell), grid vector map %zu, ratio %.2f"
				  " (working form %zu, ratio %.2f; .gvmap %zu, ratio %.2f)\n",
				  r.spaceSize, r.vectorCount, r.vectorLength, r.n_g, r.n_v, r.ratio, r.resolution * 100, r.cells,
				  r.ratioCells, r.bytesGrid, r.bytesPerGridCell, r.bytesGridVector, r.ratioBytes, r.bytesWorkingForm,
				  r.ratioBytesWorkingForm, r.bytesFile, r.ratioBytesFile);
	return buf;
}

}  // namespace gridvector
