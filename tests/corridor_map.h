// Test helper: a corridor with a door and a trolley (world, scans, the map built from 12 scans
// along it), for the map's matching and concurrency tests.
#pragma once

#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <cmath>
#include <random>
#include <vector>

#include "test_scans.h"

namespace gvtest
{
/** A corridor (y 0..2, x 0..10) with a door gap at x 4..5 in its south wall into a room
 * (x 2.5..7, y -4..0), a pillar in the corridor's east end and a recess in its north wall. */
inline std::vector<Seg> corridorWorld()
{
	std::vector<Seg> w{{0, 0, 4, 0},       {5, 0, 10, 0},        {10, 0, 10, 2},     {10, 2, 6.5, 2},
					   {6.5, 2, 6.5, 2.6}, {6.5, 2.6, 5.5, 2.6}, {5.5, 2.6, 5.5, 2}, {5.5, 2, 0, 2},
					   {0, 2, 0, 0},       {2.5, 0, 2.5, -4},    {2.5, -4, 7, -4},   {7, -4, 7, 0}};
	const auto pillar = box(8.5, 0.8, 8.9, 1.2);
	w.insert(w.end(), pillar.begin(), pillar.end());
	return w;
}
inline const Seg kDoorClosed{4, 0, 5, 0};
/** A trolley (0.8 x 0.4 m) parked in the corridor. A standing person, a disc of the simulator's
 * 0.2-0.28 m radius, makes no grid vector at all (the arc's pieces under the split threshold stay
 * shorter than extraction.min_length), so the thing left standing here is a box. */
inline const std::vector<Seg> kTrolley = box(5.6, 1.3, 6.4, 1.7);

/** A 270-degree scan at pose x, 1 cm range noise. */
inline mrpt::obs::CObservation2DRangeScan scanOf(const mrpt::math::TPose2D& x, const std::vector<Seg>& walls,
												 const std::vector<Disc>& discs, unsigned seed)
{
	auto scan = castScan(x, walls, discs, 541, 1.5 * M_PI, 30.0);
	std::mt19937 rng(seed);
	std::normal_distribution<float> n(0.f, 0.01f);
	for (size_t i = 0; i < scan.getScanSize(); ++i)
		if (scan.getScanRangeValidity(i)) scan.setScanRange(i, scan.getScanRange(i) + n(rng));
	return scan;
}

/** The map from scans along the corridor (x 1..9 at y 0.8): the door closed and the trolley
 * there in the first 3 scans, the door open and the trolley gone in the other 9. */
inline mrpt::maps::CGridVectorMap corridorMap(const gridvector::GridVectorConfig& cfg = {})
{
	mrpt::maps::CGridVectorMap map(cfg);
	for (int k = 0; k < 12; ++k)
	{
		const mrpt::math::TPose2D x(1.0 + 8.0 * k / 11, 0.8 + 0.1 * std::sin(k), 0.15 * std::cos(1.3 * k));
		auto walls = corridorWorld();
		if (k < 3)
		{
			walls.push_back(kDoorClosed);
			walls.insert(walls.end(), kTrolley.begin(), kTrolley.end());
		}
		else
			walls.push_back({4, 0, 4, -0.9});  // the leaf swung into the room
		map.insertObservation(scanOf(x, walls, {}, 100 + k), mrpt::poses::CPose3D(mrpt::poses::CPose2D(x)));
	}
	return map;
}

inline mrpt::maps::CSimplePointsMap scanPoints(const mrpt::obs::CObservation2DRangeScan& scan)
{
	mrpt::maps::CSimplePointsMap pts;
	pts.insertionOptions.minDistBetweenLaserPoints = 0;
	pts.loadFromRangeScan(scan);
	return pts;
}

}  // namespace gvtest
