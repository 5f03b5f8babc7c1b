// Eq. 6-7: the grid vector map as an occupancy grid, at any resolution.
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPoint2D.h>

#include <vector>

namespace gridvector
{
/** Eq. 6 over a regular raster. Each output cell is sampled at s x s points;
 * at each point Eq. 6-7 sums the n_occupy and n_visit of every vector cell
 * containing it. Max pooling keeps the counts of the observed point with the
 * largest occupancy (a cell holding any obstacle is occupied, as in a
 * ray-casting grid or OctoMap's inner nodes); mean pooling averages the counts
 * over the points. A point is observed where its counts are off the prior's
 * ratio ([gridvector_grid] prior_occupy / prior_visit): a never-observed cell
 * holds the prior, and any sum of priors (overlapping or merged cells) lies on
 * its ratio. A cell with no observed point is unknown (the prior is no
 * evidence). p = occ / visit; unknown where visit == 0. */
struct OccupancyRaster
{
	double xMin = 0, yMin = 0, resolution = 0.1;  //!< lower-left corner of cell (0, 0)
	int nx = 0, ny = 0;
	std::vector<float> occ, visit;  //!< row-major, iy * nx + ix

	bool known(int ix, int iy) const { return visit[size_t(iy) * nx + ix] > 0; }
	/** Eq. 6; 0.5 (MRPT's unknown) where no observed point lies in the cell. */
	double probability(int ix, int iy) const
	{
		const size_t i = size_t(iy) * nx + ix;
		return visit[i] > 0 ? double(occ[i]) / visit[i] : 0.5;
	}
};

/** Conversion options (resolution, margin, sub-samples, pooling): the
 * `[gridvector_occupancy]` group of GridVectorConfig. */
using OccupancyConversionOptions = OccupancyOptions;

class OccupancyConversion
{
   public:
	/** Eq. 6 at one point: (sum n_occupy, sum n_visit) of all cells containing p (Eq. 7). */
	static std::pair<double, double> countsAt(const std::vector<GridVector>& vectors, const mrpt::math::TPoint2D& p);
	/** Eq. 6 at one point; the prior's ratio where no vector covers it.
	 * `grid`: the vectors' grid options (their prior, see priorRatio). */
	static double occupancyAt(const std::vector<GridVector>& vectors, const mrpt::math::TPoint2D& p,
							  const GridOptions& grid = {});
	/** prior_occupy / prior_visit as the cells hold them (floats): the
	 * occupancy of a never-observed cell and of any sum of such cells. */
	static double priorRatio(const GridOptions& grid);

	/** Raster over the vectors' bounding box (plus margin). */
	static OccupancyRaster rasterise(const std::vector<GridVector>& vectors, const OccupancyConversionOptions& opt = {},
									 const GridOptions& grid = {});
	/** Raster with a given geometry (cells of side res from (xMin, yMin)). */
	static OccupancyRaster rasterise(const std::vector<GridVector>& vectors, double xMin, double yMin, double res,
									 int nx, int ny, int samplesPerAxis = 0, bool maxPooling = true,
									 const GridOptions& grid = {});

	/** Eq. 6 as an MRPT occupancy grid; unknown cells stay 0.5. Note MRPT's
	 * convention: a cell's value is p(free) = 1 - p(occupied). */
	static mrpt::maps::COccupancyGridMap2D toOccupancyGrid(const std::vector<GridVector>& vectors,
														   const OccupancyConversionOptions& opt = {},
														   const GridOptions& grid = {});
	/** Fills an existing grid (its size and resolution are kept). */
	static void fill(const std::vector<GridVector>& vectors, mrpt::maps::COccupancyGridMap2D& grid,
					 int samplesPerAxis = 0, bool maxPooling = true, const GridOptions& gridOptions = {});
	static void fill(const OccupancyRaster& raster, mrpt::maps::COccupancyGridMap2D& grid);
	/** Most cells (sample points included) a raster may have: 2^28, a few GB of floats. */
	static constexpr double kMaxCells = 268435456.0;
	/** Throws "occupancy grid of W x H m at resolution R m: N cells ..." when a raster of that extent
	 * with samplesPerAxis^2 sample points per cell would exceed kMaxCells (a resolution far below
	 * the map's scale, or vectors far apart), instead of failing in an allocation. */
	static void requireRasterSize(double width, double height, double res, int samplesPerAxis = 1);
	/** Bounding box of all vectors' grid bands: {xmin, ymin, xmax, ymax}; false if none. */
	static bool bounds(const std::vector<GridVector>& vectors, double& xmin, double& ymin, double& xmax, double& ymax);
};

}  // namespace gridvector
