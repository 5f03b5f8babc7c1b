// Test helper: synthetic 2D range scans by ray casting against segments and discs.
#pragma once

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>
#include <limits>
#include <vector>

namespace gvtest
{
struct Seg
{
	double x1, y1, x2, y2;
};
struct Disc
{
	double x, y, r;
};

inline double rayHit(double ox, double oy, double dx, double dy, const Seg& s)
{
	const double ex = s.x2 - s.x1, ey = s.y2 - s.y1;
	const double den = dx * ey - dy * ex;
	if (std::abs(den) < 1e-12) return std::numeric_limits<double>::infinity();
	const double t = ((s.x1 - ox) * ey - (s.y1 - oy) * ex) / den;
	const double u = ((s.x1 - ox) * dy - (s.y1 - oy) * dx) / den;
	return (t > 1e-9 && u >= 0 && u <= 1) ? t : std::numeric_limits<double>::infinity();
}

inline double rayHit(double ox, double oy, double dx, double dy, const Disc& c)
{
	const double fx = ox - c.x, fy = oy - c.y;
	const double b = fx * dx + fy * dy, cc = fx * fx + fy * fy - c.r * c.r;
	const double disc = b * b - cc;
	if (disc < 0) return std::numeric_limits<double>::infinity();
	const double t = -b - std::sqrt(disc);
	return t > 1e-9 ? t : std::numeric_limits<double>::infinity();
}

/** A scan taken by a sensor at world pose `sensor` (robot pose = sensor pose
 * unless sensorPose is set on the result afterwards). */
inline mrpt::obs::CObservation2DRangeScan castScan(const mrpt::math::TPose2D& sensor, const std::vector<Seg>& walls,
												   const std::vector<Disc>& discs = {}, size_t beams = 361,
												   double aperture = M_PI, double maxRange = 30.0)
{
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = float(aperture);
	scan.maxRange = float(maxRange);
	scan.rightToLeft = true;
	scan.resizeScan(beams);
	for (size_t i = 0; i < beams; ++i)
	{
		const double a = sensor.phi - aperture / 2 + aperture * double(i) / double(beams - 1);
		const double dx = std::cos(a), dy = std::sin(a);
		double best = std::numeric_limits<double>::infinity();
		for (const auto& w : walls) best = std::min(best, rayHit(sensor.x, sensor.y, dx, dy, w));
		for (const auto& d : discs) best = std::min(best, rayHit(sensor.x, sensor.y, dx, dy, d));
		const bool ok = best < maxRange;
		scan.setScanRange(i, ok ? float(best) : float(maxRange));
		scan.setScanRangeValidity(i, ok);
	}
	return scan;
}

/** The outline of an axis-aligned box [x0,x1] x [y0,y1], seen from outside (a piece of furniture). */
inline std::vector<Seg> box(double x0, double y0, double x1, double y1)
{
	return {{x0, y0, x0, y1}, {x0, y1, x1, y1}, {x1, y1, x1, y0}, {x1, y0, x0, y0}};
}

/** Axis-aligned rectangular room [x0,x1] x [y0,y1]. */
inline std::vector<Seg> room(double x0, double y0, double x1, double y1)
{
	return {{x0, y0, x1, y0}, {x1, y0, x1, y1}, {x1, y1, x0, y1}, {x0, y1, x0, y0}};
}

}  // namespace gvtest
