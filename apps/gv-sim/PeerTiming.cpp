#include "PeerTiming.h"

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPose2D.h>

#include <algorithm>
#include <chrono>
#include <cmath>

double timeMrptLaserSimulator(const gridvector::sim::SimResult& r)
{
	constexpr float res = 0.05f;
	double x0 = 1e9, y0 = 1e9, x1 = -1e9, y1 = -1e9;
	for (const auto& w : r.world.walls)
		for (const auto& p : {w.a, w.b})
			x0 = std::min(x0, p.x), y0 = std::min(y0, p.y), x1 = std::max(x1, p.x), y1 = std::max(y1, p.y);
	mrpt::maps::COccupancyGridMap2D grid;
	grid.setSize(float(x0 - 1), float(x1 + 1), float(y0 - 1), float(y1 + 1), res, 1.0f);  // all free
	for (const auto& w : r.world.walls)
	{
		const int n = int(std::ceil(w.length() / (0.5 * res))) + 1;
		for (int i = 0; i <= n; i++)
		{
			const auto p = w.at(double(i) / n);
			grid.setPos(float(p.x), float(p.y), 0.0f);  // occupied
		}
	}
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = float(r.laserResolution * (r.laser.beams - 1));
	scan.maxRange = float(r.laser.maxRange);
	const auto t0 = std::chrono::steady_clock::now();
	for (const auto& s : r.scans)
		grid.laserScanSimulator(scan, mrpt::poses::CPose2D(s.truth), 0.5f, size_t(r.laser.beams));
	return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
