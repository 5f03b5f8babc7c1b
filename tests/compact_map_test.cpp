// CompactMap: the map in the bytes its information needs; half floats for the counts.
#include <gtest/gtest.h>

#include "map/CompactMap.h"
#include "map/HalfFloat.h"
#include "map/OccupancyConversion.h"

#include <cmath>

using gridvector::CompactMap;
using gridvector::GridCell;
using gridvector::GridVector;
using mrpt::math::TPoint2D;

namespace
{
GridVector wall(double x0, double y0, double x1, double y1, float visits)
{
	GridVector v(TPoint2D(x0, y0), TPoint2D(x1, y1), gridvector::GridOptions{});
	for (int c = 0; c < v.cols(); ++c)
	{
		v.addEndpoint(TPoint2D((c + 0.3) * v.resolution(), 0.01 * (c % 3)));
		GridCell& free = v.cell(2, c);  // the open side: beams through it
		free.n_visit += visits * (1 + c);
		free.n_occupy += 0.25f * c;
	}
	v.cell(0, 0) = GridCell{0.f, 0.f, 0.f, 0.f, 0.f};  // a cell no part covered
	return v;
}
}  // namespace

TEST(HalfFloat, RoundsToNearestAndKeepsSmallIntegersExact)
{
	for (float f : {0.f, 0.5f, 1.f, 3.f, 2047.f, 2048.f, 65504.f, 6.1035156e-05f, 5.9604645e-08f})
		EXPECT_EQ(gridvector::fromHalf(gridvector::toHalf(f)), f) << f;
	EXPECT_EQ(gridvector::fromHalf(gridvector::toHalf(2049.f)), 2048.f);  // a tie: to even
	EXPECT_EQ(gridvector::fromHalf(gridvector::toHalf(2051.f)), 2052.f);
	EXPECT_TRUE(std::isinf(gridvector::fromHalf(gridvector::toHalf(70000.f))));
	for (float f = 1e-4f; f < 6e4f; f *= 1.37f)
		EXPECT_NEAR(gridvector::fromHalf(gridvector::toHalf(f)), f, f / 2048) << f;
	EXPECT_EQ(gridvector::fromHalf(gridvector::toHalf(-2.f)), -2.f);
}

TEST(CompactMap, RoundTripKeepsGeometryCountsAndOccupancy)
{
	std::vector<GridVector> map{wall(0, 0, 3.05, 0.02, 7.f), wall(1, 2, 1.1, 4.3, 3000.f)};
	map[0].id = 4, map[0].scanIndex = 17, map[0].timestamp = 1e9 + 0.25, map[0].mergedCount = 3;
	map[1].id = 9, map[1].scanIndex = -1, map[1].timestamp = 1e9 + 80.5;
	map[1].state = gridvector::VectorState::Dynamic;
	const CompactMap c = CompactMap::encode(map);
	EXPECT_EQ(c.vectorCount(), 2u);
	const std::vector<GridVector> back = c.decode(gridvector::GridOptions{});
	ASSERT_EQ(back.size(), 2u);
	for (size_t i = 0; i < 2; ++i)
	{
		const GridVector &a = map[i], &b = back[i];
		EXPECT_NEAR(b.start().x, a.start().x, 5e-4);  // the 1 mm lattice
		EXPECT_NEAR(b.end().y, a.end().y, 5e-4);
		EXPECT_EQ(b.cols(), a.cols());
		EXPECT_EQ(b.id, a.id);
		EXPECT_EQ(b.scanIndex, a.scanIndex);
		EXPECT_EQ(b.state, a.state);
		EXPECT_EQ(b.mergedCount, a.mergedCount);
		EXPECT_NEAR(b.timestamp, a.timestamp, 0.005);
		EXPECT_NEAR(b.totalOccupy(), a.totalOccupy(), 5e-4 * a.totalOccupy());  // Algorithm 2's totals
		EXPECT_NEAR(b.totalVisit(), a.totalVisit(), 5e-4 * a.totalVisit());
		EXPECT_NEAR(b.totalPoints(), a.totalPoints(), 5e-4 * a.totalPoints());
		for (int r = 0; r < a.rows(); ++r)
			for (int k = 0; k < a.cols(); ++k)
			{
				const GridCell &x = a.cell(r, k), &y = b.cell(r, k);
				EXPECT_NEAR(y.occupancy(0.5), x.occupancy(0.5), 1e-3);  // Eq. 6's ratio
				EXPECT_EQ(y.n_acc > 0, x.n_acc > 0);
				if (x.n_acc > 0)
				{
					const TPoint2D p = a.cellMeanPoint(r, k), q = b.cellMeanPoint(r, k);
					EXPECT_NEAR(p.x, q.x, 1.5e-3);
					EXPECT_NEAR(p.y, q.y, 1.5e-3);
				}
			}
	}
	EXPECT_EQ(back[0].cell(0, 0).n_visit, 0.f);  // an uncovered cell stays without counts
	// Eq. 6 at points along the walls
	for (double u = 0.05; u < 3; u += 0.1)
		EXPECT_NEAR(gridvector::OccupancyConversion::occupancyAt(back, TPoint2D(u, 0.1)),
					gridvector::OccupancyConversion::occupancyAt(map, TPoint2D(u, 0.1)), 1e-3);
}

TEST(CompactMap, IsSmallerThanTheFloatCells)
{
	std::vector<GridVector> map{wall(0, 0, 10, 0, 5.f)};
	const size_t floats = map[0].cells().size() * sizeof(GridCell);
	const CompactMap c = CompactMap::encode(map);
	EXPECT_LT(c.bytes().size() * 2, floats);
	EXPECT_EQ(c.memoryBytes(), sizeof(CompactMap) + c.bytes().size());
}

TEST(CompactMap, LargeCountsAreScaledNotSaturated)
{
	std::vector<GridVector> map{wall(0, 0, 1, 0, 1e6f)};
	const auto back = CompactMap::encode(map).decode(gridvector::GridOptions{});
	EXPECT_NEAR(back[0].totalVisit(), map[0].totalVisit(), 5e-4 * map[0].totalVisit());
	EXPECT_TRUE(std::isfinite(back[0].totalVisit()));
}

TEST(CompactMap, CorruptOrForeignBuffersAreErrors)
{
	const CompactMap c = CompactMap::encode({wall(0, 0, 2, 0, 5.f)});
	const std::vector<uint8_t> bytes = c.bytes();
	for (size_t cut = 0; cut < bytes.size(); ++cut)
		EXPECT_THROW(CompactMap::fromBytes(std::vector<uint8_t>(bytes.begin(), bytes.begin() + cut))
						 .decode(gridvector::GridOptions{}),
					 std::runtime_error)
			<< cut;
	std::vector<uint8_t> tail = bytes;
	tail.push_back(0);
	EXPECT_THROW(CompactMap::fromBytes(tail).decode(gridvector::GridOptions{}), std::runtime_error);
	gridvector::GridOptions wide;
	wide.halfWidth = 2;
	EXPECT_THROW(CompactMap::fromBytes(bytes).decode(wide), std::runtime_error);
	for (size_t pos = 0; pos < bytes.size(); ++pos)  // any byte overwritten: an error or a map, never a crash
	{
		std::vector<uint8_t> bad = bytes;
		bad[pos] ^= 0xff;
		try
		{
			CompactMap::fromBytes(bad).decode(gridvector::GridOptions{});
		}
		catch (const std::runtime_error&)
		{}
	}
	EXPECT_TRUE(CompactMap::encode({}).decode(gridvector::GridOptions{}).empty());
}
