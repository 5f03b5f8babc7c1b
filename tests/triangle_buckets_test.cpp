// TriangleBuckets: every wipe triangle that reaches a point of a box is returned for it, once, in order.
#include "map/TriangleBuckets.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

using namespace gridvector;
using mrpt::math::TPoint2D;

namespace
{
std::vector<WipeTriangle> randomTriangles(size_t n, std::mt19937& rng)
{
	std::uniform_real_distribution<double> pos(-20, 20), len(0.2, 3), ang(-M_PI, M_PI), range(0.5, 25);
	std::vector<WipeTriangle> out;
	for (size_t k = 0; k < n; ++k)
	{
		const TPoint2D s(pos(rng), pos(rng));
		const double a = ang(rng), l = len(rng), b = ang(rng), r = range(rng);
		const TPoint2D e(s.x + l * std::cos(a), s.y + l * std::sin(a));
		const TPoint2D sensor(s.x + r * std::cos(b), s.y + r * std::sin(b));
		out.emplace_back(sensor, s, e, 0.05);
	}
	return out;
}
}  // namespace

TEST(TriangleBuckets, ReturnsEveryTriangleReachingTheBoxOnceInOrder)
{
	std::mt19937 rng(7);
	const auto tris = randomTriangles(300, rng);
	for (const double cell : {0.25, 0.5, 2.0})
	{
		SCOPED_TRACE(cell);
		TriangleBuckets buckets(cell);
		for (uint32_t k = 0; k < tris.size(); ++k) buckets.insert(k, tris[k]);
		std::uniform_real_distribution<double> pos(-22, 22), side(0.1, 2.5);
		size_t reached = 0, returned = 0;
		for (int q = 0; q < 200; ++q)
		{
			const double x = pos(rng), y = pos(rng);
			const Box2D box{x, y, x + side(rng), y + side(rng)};
			std::vector<uint32_t> got;
			buckets.query(box, got);
			EXPECT_TRUE(std::is_sorted(got.begin(), got.end()));
			EXPECT_EQ(std::adjacent_find(got.begin(), got.end()), got.end());
			returned += got.size();
			for (uint32_t k = 0; k < tris.size(); ++k)
			{
				bool reaches = false;  // a point of the box (a 9 x 9 lattice) in part b or c
				for (int i = 0; i <= 8 && !reaches; ++i)
					for (int j = 0; j <= 8 && !reaches; ++j)
					{
						const TPoint2D p(box.minX + (box.maxX - box.minX) * i / 8, box.minY + (box.maxY - box.minY) * j / 8);
						reaches = tris[k].classify(p) != WipePart::Outside;
					}
				if (!reaches) continue;
				++reached;
				EXPECT_TRUE(std::binary_search(got.begin(), got.end(), k)) << "triangle " << k << " query " << q;
			}
		}
		EXPECT_GT(reached, 100u);  // the queries did meet triangles
		EXPECT_LT(returned, 4 * reached + 2000);  // and the buckets return few that cannot reach the box
	}
}

TEST(TriangleBuckets, ListsNoDegenerateTriangleAndRejectsABadCellSize)
{
	TriangleBuckets b(0.5);
	b.insert(0, WipeTriangle({0, 0}, {0, 0}, {0, 0}, 0.05));  // zero length
	std::vector<uint32_t> got;
	b.query({-1, -1, 1, 1}, got);
	EXPECT_TRUE(got.empty());
	EXPECT_THROW(TriangleBuckets(0.0), std::invalid_argument);
	EXPECT_THROW(TriangleBuckets(-1.0), std::invalid_argument);
}
