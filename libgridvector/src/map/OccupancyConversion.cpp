#include "map/OccupancyConversion.h"
#include "map/VectorIndex.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace gridvector
{
using mrpt::math::TPoint2D;

// Eq. 6-7 at a point.
std::pair<double, double> OccupancyConversion::countsAt(const std::vector<GridVector>& vectors, const TPoint2D& p)
{
	double o = 0, v = 0;
	for (const GridVector& g : vectors)
	{
		int r, c;
		if (!g.cellOf(p, r, c)) continue;
		o += g.cell(r, c).n_occupy;
		v += g.cell(r, c).n_visit;
	}
	return {o, v};
}

// Eq. 6 at one point (Eq. 7 selects the cells containing it).
double OccupancyConversion::occupancyAt(const std::vector<GridVector>& vectors, const TPoint2D& p,
										const GridOptions& grid)
{
	const auto [o, v] = countsAt(vectors, p);
	return v > 0 ? o / v : priorRatio(grid);
}

double OccupancyConversion::priorRatio(const GridOptions& grid)
{
	return double(float(grid.priorOccupy)) / double(float(grid.priorVisit));
}

bool OccupancyConversion::bounds(const std::vector<GridVector>& vectors, double& xmin, double& ymin, double& xmax,
								 double& ymax)
{
	xmin = ymin = 1e300;
	xmax = ymax = -1e300;
	for (const GridVector& g : vectors)
	{
		const Box2D b = Box2D::of(g);
		xmin = std::min(xmin, b.minX), ymin = std::min(ymin, b.minY);
		xmax = std::max(xmax, b.maxX), ymax = std::max(ymax, b.maxY);
	}
	return !vectors.empty();
}

namespace
{
/** x-interval where the horizontal line y meets a convex quadrilateral. */
bool spanAt(const TPoint2D (&q)[4], double y, double& x0, double& x1)
{
	x0 = 1e300, x1 = -1e300;
	for (int i = 0; i < 4; ++i)
	{
		const TPoint2D &a = q[i], &b = q[(i + 1) % 4];
		if ((y < a.y && y < b.y) || (y > a.y && y > b.y)) continue;
		if (a.y == b.y)
		{
			x0 = std::min({x0, a.x, b.x}), x1 = std::max({x1, a.x, b.x});
			continue;
		}
		const double x = a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x);
		x0 = std::min(x0, x), x1 = std::max(x1, x);
	}
	return x0 <= x1;
}

/** Eq. 6-7 at the points of a fine raster (s x s points per output cell). */
struct SampleRaster
{
	double xMin, yMin, step;
	long nx, ny;
	std::vector<float> occ, visit;
	SampleRaster(const OccupancyRaster& R, int s)
		: xMin(R.xMin),
		  yMin(R.yMin),
		  step(R.resolution / s),
		  nx(long(R.nx) * s),
		  ny(long(R.ny) * s),
		  occ(size_t(nx * ny), 0.f),
		  visit(size_t(nx * ny), 0.f)
	{}
	size_t index(long fx, long fy) const { return size_t(fy * nx + fx); }
};

// Eq. 7: adds one vector's cells to every sample point inside its grid band.
void addVector(const GridVector& g, SampleRaster& S)
{
	const double res = g.resolution(), uMax = g.cols() * res, wMax = (g.halfWidth() + 0.5) * res;
	const TPoint2D d = g.direction(), n = g.leftNormal(), o = g.start();
	auto at = [&](double u, double w) { return TPoint2D(o.x + u * d.x + w * n.x, o.y + u * d.y + w * n.y); };
	const TPoint2D quad[4] = {at(0, -wMax), at(uMax, -wMax), at(uMax, wMax), at(0, wMax)};
	double ylo = 1e300, yhi = -1e300;
	for (const auto& p : quad) ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
	const long fy0 = std::max(0L, long(std::ceil((ylo - S.yMin) / S.step - 0.5)));
	const long fy1 = std::min(S.ny - 1, long(std::floor((yhi - S.yMin) / S.step - 0.5)));
	for (long fy = fy0; fy <= fy1; ++fy)
	{
		const double y = S.yMin + (fy + 0.5) * S.step;
		double x0, x1;
		if (!spanAt(quad, y, x0, x1)) continue;
		const long fx0 = std::max(0L, long(std::ceil((x0 - S.xMin) / S.step - 0.5)));
		const long fx1 = std::min(S.nx - 1, long(std::floor((x1 - S.xMin) / S.step - 0.5)));
		for (long fx = fx0; fx <= fx1; ++fx)
		{
			const double dx = S.xMin + (fx + 0.5) * S.step - o.x, dy = y - o.y;
			const double u = dx * d.x + dy * d.y, w = dx * n.x + dy * n.y;
			const int c = int(std::floor(u / res)), r = int(std::floor(w / res + 0.5)) + g.halfWidth();
			if (c < 0 || c >= g.cols() || r < 0 || r >= g.rows()) continue;  // on the band's edge
			const GridCell& cell = g.cell(r, c);
			S.occ[S.index(fx, fy)] += cell.n_occupy;
			S.visit[S.index(fx, fy)] += cell.n_visit;
		}
	}
}

/** Observed: the counts are off the prior's ratio (a sum of priors lies on it). */
bool informative(float o, float v, double prior) { return v > 0 && std::abs(double(o) / v - prior) > 1e-6; }

// Pools the s x s sample points of every output cell into it; no observed point: unknown.
void pool(const SampleRaster& S, int s, bool maxPooling, double prior, OccupancyRaster& R)
{
	const double weight = 1.0 / (double(s) * s);
	for (int iy = 0; iy < R.ny; ++iy)
		for (int ix = 0; ix < R.nx; ++ix)
		{
			double sumO = 0, sumV = 0, bestP = -1, bestO = 0, bestV = 0;
			for (long fy = long(iy) * s; fy < long(iy + 1) * s; ++fy)
				for (long fx = long(ix) * s; fx < long(ix + 1) * s; ++fx)
				{
					const float o = S.occ[S.index(fx, fy)], v = S.visit[S.index(fx, fy)];
					sumO += o, sumV += v;
					if (informative(o, v, prior) && o / v > bestP) bestP = o / v, bestO = o, bestV = v;
				}
			const size_t i = size_t(iy) * R.nx + ix;
			const bool observed = bestP >= 0, useBest = maxPooling && observed;
			R.occ[i] = float(!observed ? 0.0 : useBest ? bestO : weight * sumO);
			R.visit[i] = float(!observed ? 0.0 : useBest ? bestV : weight * sumV);
		}
}
}  // namespace

// Eq. 6 at the sample points of every output cell, pooled per cell.
OccupancyRaster OccupancyConversion::rasterise(const std::vector<GridVector>& vectors, double xMin, double yMin,
											   double res, int nx, int ny, int samplesPerAxis, bool maxPooling,
											   const GridOptions& grid)
{
	OccupancyRaster R;
	R.xMin = xMin, R.yMin = yMin, R.resolution = res;
	R.nx = std::max(0, nx), R.ny = std::max(0, ny);
	// automatic: one point per vector cell along each axis, so at the vectors'
	// own resolution every output cell is Eq. 6 at its centre
	int s = std::max(1, samplesPerAxis);
	if (samplesPerAxis <= 0)
		for (const GridVector& g : vectors) s = std::max(s, int(std::ceil(res / g.resolution() - 1e-6)));
	requireRasterSize(R.nx * res, R.ny * res, res, s);
	R.occ.assign(size_t(R.nx) * R.ny, 0.f);
	R.visit.assign(size_t(R.nx) * R.ny, 0.f);
	SampleRaster S(R, s);
	for (const GridVector& g : vectors) addVector(g, S);
	pool(S, s, maxPooling, priorRatio(grid), R);
	return R;
}

OccupancyRaster OccupancyConversion::rasterise(const std::vector<GridVector>& vectors,
											   const OccupancyConversionOptions& opt, const GridOptions& grid)
{
	double x0, y0, x1, y1;
	if (!bounds(vectors, x0, y0, x1, y1)) return rasterise(vectors, 0, 0, opt.resolution, 0, 0, 0, true, grid);
	requireRasterSize(x1 - x0 + 2 * opt.margin, y1 - y0 + 2 * opt.margin, opt.resolution);  // before int(cells)
	x0 = std::floor((x0 - opt.margin) / opt.resolution) * opt.resolution;
	y0 = std::floor((y0 - opt.margin) / opt.resolution) * opt.resolution;
	const int nx = int(std::ceil((x1 + opt.margin - x0) / opt.resolution));
	const int ny = int(std::ceil((y1 + opt.margin - y0) / opt.resolution));
	return rasterise(vectors, x0, y0, opt.resolution, nx, ny, opt.samplesPerAxis, opt.maxPooling, grid);
}

void OccupancyConversion::requireRasterSize(double width, double height, double res, int samplesPerAxis)
{
	const double cells = std::ceil(width / res) * std::ceil(height / res) * samplesPerAxis * samplesPerAxis;
	if (cells <= kMaxCells) return;  // also false for NaN
	char msg[320];
	std::snprintf(msg, sizeof msg,
				  "occupancy grid of %.4g x %.4g m at resolution %g m%s: %.3g cells, more than %.0f (raise "
				  "[gridvector_occupancy] resolution, or check the vectors' extent)",
				  width, height, res,
				  samplesPerAxis > 1 ? (" with " + std::to_string(samplesPerAxis) + "^2 samples per cell").c_str() : "",
				  cells, kMaxCells);
	throw std::runtime_error(msg);
}

void OccupancyConversion::fill(const OccupancyRaster& R, mrpt::maps::COccupancyGridMap2D& grid)
{
	for (int iy = 0; iy < R.ny; ++iy)
		for (int ix = 0; ix < R.nx; ++ix)
			if (R.known(ix, iy)) grid.setCell(ix, iy, float(1.0 - R.probability(ix, iy)));  // MRPT stores p(free)
}

void OccupancyConversion::fill(const std::vector<GridVector>& vectors, mrpt::maps::COccupancyGridMap2D& grid,
							   int samplesPerAxis, bool maxPooling, const GridOptions& gridOptions)
{
	const OccupancyRaster R =
		rasterise(vectors, grid.getXMin(), grid.getYMin(), grid.getResolution(), int(grid.getSizeX()),
				  int(grid.getSizeY()), samplesPerAxis, maxPooling, gridOptions);
	fill(R, grid);
}

// Eq. 6: the global occupancy grid from the grid vectors.
mrpt::maps::COccupancyGridMap2D OccupancyConversion::toOccupancyGrid(const std::vector<GridVector>& vectors,
																	 const OccupancyConversionOptions& opt,
																	 const GridOptions& gridOptions)
{
	mrpt::maps::COccupancyGridMap2D grid;
	double x0, y0, x1, y1;
	if (!bounds(vectors, x0, y0, x1, y1)) x0 = y0 = -opt.margin, x1 = y1 = opt.margin;
	requireRasterSize(x1 - x0 + 2 * opt.margin, y1 - y0 + 2 * opt.margin, opt.resolution);  // before MRPT allocates
	grid.setSize(x0 - opt.margin, x1 + opt.margin, y0 - opt.margin, y1 + opt.margin, opt.resolution, 0.5f);
	fill(vectors, grid, opt.samplesPerAxis, opt.maxPooling, gridOptions);  // in the grid's own (snapped) geometry
	return grid;
}

}  // namespace gridvector
