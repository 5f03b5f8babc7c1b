#include <gridvector/OccupancyConversion.h>
#include <gridvector/VectorIndex.h>

#include <algorithm>
#include <cmath>

namespace gridvector
{
using mrpt::math::TPoint2D;

// Eq. 6-7 at a point.
std::pair<double, double> OccupancyConversion::countsAt(const std::vector<GridVector>& vectors,
														 const TPoint2D& p)
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

double OccupancyConversion::occupancyAt(const std::vector<GridVector>& vectors, const TPoint2D& p)
{
	const auto [o, v] = countsAt(vectors, p);
	return v > 0 ? o / v : 0.5;
}

bool OccupancyConversion::bounds(const std::vector<GridVector>& vectors, double& xmin, double& ymin,
								 double& xmax, double& ymax)
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

// Eq. 6 summed over the sub-samples of the raster that fall in one vector's grid band.
void addVector(const GridVector& g, OccupancyRaster& R, int s)
{
	const double res = g.resolution(), uMax = g.cols() * res, wMax = (g.halfWidth() + 0.5) * res;
	const TPoint2D d = g.direction(), n = g.leftNormal(), o = g.start();
	auto at = [&](double u, double w) { return TPoint2D(o.x + u * d.x + w * n.x, o.y + u * d.y + w * n.y); };
	const TPoint2D quad[4] = {at(0, -wMax), at(uMax, -wMax), at(uMax, wMax), at(0, wMax)};
	const double fine = R.resolution / s, weight = 1.0 / (s * s);
	double ylo = 1e300, yhi = -1e300;
	for (const auto& p : quad) ylo = std::min(ylo, p.y), yhi = std::max(yhi, p.y);
	const long fy0 = std::max(0L, long(std::ceil((ylo - R.yMin) / fine - 0.5)));
	const long fy1 = std::min(long(R.ny) * s - 1, long(std::floor((yhi - R.yMin) / fine - 0.5)));
	for (long fy = fy0; fy <= fy1; ++fy)
	{
		const double y = R.yMin + (fy + 0.5) * fine;
		double x0, x1;
		if (!spanAt(quad, y, x0, x1)) continue;
		const long fx0 = std::max(0L, long(std::ceil((x0 - R.xMin) / fine - 0.5)));
		const long fx1 = std::min(long(R.nx) * s - 1, long(std::floor((x1 - R.xMin) / fine - 0.5)));
		const size_t rowBase = size_t(fy / s) * R.nx;
		for (long fx = fx0; fx <= fx1; ++fx)
		{
			const double x = R.xMin + (fx + 0.5) * fine;
			const double dx = x - o.x, dy = y - o.y;
			const double u = dx * d.x + dy * d.y, w = dx * n.x + dy * n.y;
			const int c = int(std::floor(u / res)), r = int(std::floor(w / res + 0.5)) + g.halfWidth();
			if (c < 0 || c >= g.cols() || r < 0 || r >= g.rows()) continue;  // on the band's edge
			const GridCell& cell = g.cell(r, c);
			const size_t i = rowBase + size_t(fx / s);
			R.occ[i] += float(weight * cell.n_occupy);
			R.visit[i] += float(weight * cell.n_visit);
		}
	}
}
}  // namespace

OccupancyRaster OccupancyConversion::rasterise(const std::vector<GridVector>& vectors, double xMin,
											   double yMin, double res, int nx, int ny, int samplesPerAxis)
{
	OccupancyRaster R;
	R.xMin = xMin, R.yMin = yMin, R.resolution = res;
	R.nx = std::max(0, nx), R.ny = std::max(0, ny);
	R.occ.assign(size_t(R.nx) * R.ny, 0.f);
	R.visit.assign(size_t(R.nx) * R.ny, 0.f);
	for (const GridVector& g : vectors)
	{
		const int s = samplesPerAxis > 0 ? samplesPerAxis
										 : std::max(1, int(std::ceil(2 * res / g.resolution() - 1e-6)));
		addVector(g, R, s);
	}
	return R;
}

OccupancyRaster OccupancyConversion::rasterise(const std::vector<GridVector>& vectors,
											   const OccupancyConversionOptions& opt)
{
	double x0, y0, x1, y1;
	if (!bounds(vectors, x0, y0, x1, y1)) return rasterise(vectors, 0, 0, opt.resolution, 0, 0);
	x0 = std::floor((x0 - opt.margin) / opt.resolution) * opt.resolution;
	y0 = std::floor((y0 - opt.margin) / opt.resolution) * opt.resolution;
	const int nx = int(std::ceil((x1 + opt.margin - x0) / opt.resolution));
	const int ny = int(std::ceil((y1 + opt.margin - y0) / opt.resolution));
	return rasterise(vectors, x0, y0, opt.resolution, nx, ny, opt.samplesPerAxis);
}

void OccupancyConversion::fill(const OccupancyRaster& R, mrpt::maps::COccupancyGridMap2D& grid)
{
	for (int iy = 0; iy < R.ny; ++iy)
		for (int ix = 0; ix < R.nx; ++ix)
			if (R.known(ix, iy)) grid.setCell(ix, iy, float(1.0 - R.probability(ix, iy)));  // MRPT stores p(free)
}

void OccupancyConversion::fill(const std::vector<GridVector>& vectors,
							   mrpt::maps::COccupancyGridMap2D& grid, int samplesPerAxis)
{
	const OccupancyRaster R = rasterise(vectors, grid.getXMin(), grid.getYMin(), grid.getResolution(),
										int(grid.getSizeX()), int(grid.getSizeY()), samplesPerAxis);
	fill(R, grid);
}

// Eq. 6: the global occupancy grid from the grid vectors.
mrpt::maps::COccupancyGridMap2D OccupancyConversion::toOccupancyGrid(
	const std::vector<GridVector>& vectors, const OccupancyConversionOptions& opt)
{
	mrpt::maps::COccupancyGridMap2D grid;
	double x0, y0, x1, y1;
	if (!bounds(vectors, x0, y0, x1, y1)) x0 = y0 = -opt.margin, x1 = y1 = opt.margin;
	grid.setSize(x0 - opt.margin, x1 + opt.margin, y0 - opt.margin, y1 + opt.margin, opt.resolution, 0.5f);
	fill(vectors, grid, opt.samplesPerAxis);  // in the grid's own (snapped) geometry
	return grid;
}

}  // namespace gridvector
