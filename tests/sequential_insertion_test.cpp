// Sequential mode (incremental use on a robot): scans inserted one by one into a
// CGridVectorMap cost O(vectors near the robot), not O(map size).
#include "estep/EStep.h"

#include <gtest/gtest.h>
#include "map/GlobalMap.h"
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cstdio>
#include <numeric>

#include "test_scans.h"

namespace
{
// A 120 m corridor whose walls are 1.5 m panels with 0.5 m door gaps: every
// panel is its own map vector, so the map keeps growing as the robot drives.
std::vector<gvtest::Seg> corridor()
{
	std::vector<gvtest::Seg> w;
	for (double x = 0; x < 120; x += 2.0)
	{
		w.push_back({x, -1.5, x + 1.5, -1.5});
		w.push_back({x + 1.5, 1.5, x, 1.5});
	}
	return w;
}

double mean(const std::vector<size_t>& v, size_t a, size_t b)
{
	return double(std::accumulate(v.begin() + long(a), v.begin() + long(b), size_t(0))) / double(b - a);
}
}  // namespace

TEST(sequential_insertion, cost_per_scan_does_not_grow_with_the_map)
{
	const auto walls = corridor();
	mrpt::maps::CGridVectorMap map;
	std::vector<size_t> candidates, touched;
	std::vector<double> mapLength;  // metres of wall in the map
	for (double x = 2; x < 116; x += 0.3)
	{
		const mrpt::math::TPose2D pose(x, 0, 0);
		const auto scan = gvtest::castScan(pose, walls, {}, 181, M_PI, 6.0);
		ASSERT_TRUE(map.insertObservation(scan, mrpt::poses::CPose3D(mrpt::poses::CPose2D(pose))));
		const auto& st = map.globalMap().lastInsertStats();
		candidates.push_back(st.wipe.candidates);
		touched.push_back(st.wipe.vectorsTouched);
		double len = 0;
		for (const auto& v : map.vectors()) len += v.length();
		mapLength.push_back(len);
	}
	const size_t n = mapLength.size(), q = n / 4;
	ASSERT_GT(n, 300u);
	// the map grows several-fold after the first quarter ...
	EXPECT_GT(mapLength.back(), 3.0 * mapLength[q]);
	EXPECT_GT(mapLength.back(), 150.0);
	std::printf("map %.0f m -> %.0f m of walls, %zu vectors; candidates/scan %.1f -> %.1f, touched/scan %.1f -> %.1f\n",
				mapLength[2 * q], mapLength.back(), map.vectors().size(), mean(candidates, q, 2 * q),
				mean(candidates, 3 * q, n), mean(touched, q, 2 * q), mean(touched, 3 * q, n));
	// ... while the work per scan (vectors found through the spatial index and
	// vectors whose cells were updated) stays the same: it depends on what the
	// 6 m sensor sees, not on the map.
	EXPECT_GT(mean(candidates, q, 2 * q), 0.0);
	EXPECT_LT(mean(candidates, 3 * q, n), 1.25 * mean(candidates, q, 2 * q));
	EXPECT_LT(mean(touched, 3 * q, n), 1.25 * mean(touched, q, 2 * q));
	const size_t maxTouched = *std::max_element(touched.begin() + long(q), touched.end());
	EXPECT_LE(maxTouched, 30u);  // panels within 6 m on two walls, plus a margin
	EXPECT_EQ(map.insertedScans(), n);
}

TEST(sequential_insertion, current_static_and_dynamic_vectors_are_readable_any_time)
{
	// a wall always there and a "door" panel seen only by the first half of the scans
	const std::vector<gvtest::Seg> wall = {{-3, 2, 3, 2}};
	std::vector<gvtest::Seg> withDoor = wall;
	withDoor.push_back({-1, 1, 1, 1});
	mrpt::maps::CGridVectorMap map;
	for (int i = 0; i < 40; ++i)
	{
		const mrpt::math::TPose2D pose(-0.5 + 0.025 * i, -1, M_PI / 2);
		const auto scan = gvtest::castScan(pose, i < 20 ? withDoor : wall, {}, 181, M_PI, 8.0);
		map.insertObservation(scan, mrpt::poses::CPose3D(mrpt::poses::CPose2D(pose)));
	}
	const gridvector::EStep estep(map.config().estep, map.config().grid);
	const auto split = estep.run(map.vectors());
	ASSERT_GT(split.staticCount, 0u);
	ASSERT_GT(split.dynamicCount, 0u);
	bool wallStatic = false, doorDynamic = false;
	for (const auto& v : split.children)
	{
		const double y = v.centre().y;
		if (std::abs(y - 2) < 0.2 && v.state == gridvector::VectorState::Static) wallStatic = true;
		if (std::abs(y - 1) < 0.2 && v.state == gridvector::VectorState::Dynamic) doorDynamic = true;
	}
	EXPECT_TRUE(wallStatic);
	EXPECT_TRUE(doorDynamic);
}
