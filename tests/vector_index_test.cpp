// Spatial hash over vector boxes: queries equal brute force through inserts, moves and removals,
// and stay the same when several threads query at once.
#include "map/VectorIndex.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <random>
#include <thread>

using namespace gridvector;

TEST(VectorIndex, BoxOfCoversTheWholeGridBand)
{
	GridOptions g;
	g.resolution = 0.1;
	g.halfWidth = 1;
	const GridVector v({0, 0}, {2, 0}, g);
	const Box2D b = Box2D::of(v);
	EXPECT_NEAR(b.minX, 0, 1e-12);
	EXPECT_NEAR(b.maxX, 2.0, 1e-12);
	EXPECT_NEAR(b.minY, -0.15, 1e-12);
	EXPECT_NEAR(b.maxY, 0.15, 1e-12);
}

TEST(VectorIndex, QueryMatchesBruteForce)
{
	std::mt19937 rng(3);
	std::uniform_real_distribution<double> U(-50, 50), L(0, 6);
	VectorIndex idx(2.0);
	std::vector<Box2D> boxes(500);
	std::vector<bool> live(500, false);
	auto randomBox = [&] {
		const double x = U(rng), y = U(rng);
		return Box2D{x, y, x + L(rng), y + L(rng)};
	};
	for (uint32_t i = 0; i < 500; ++i)
	{
		boxes[i] = randomBox();
		idx.insert(i, boxes[i]);
		live[i] = true;
	}
	for (uint32_t i = 0; i < 500; i += 3)  // remove a third, move a third
	{
		idx.remove(i);
		live[i] = false;
		if (i + 1 < 500)
		{
			boxes[i + 1] = randomBox();
			idx.insert(i + 1, boxes[i + 1]);
		}
	}
	EXPECT_EQ(idx.size(), size_t(std::count(live.begin(), live.end(), true)));
	for (int q = 0; q < 300; ++q)
	{
		Box2D qb = randomBox();
		if (q % 50 == 0) qb = {-1e4, -1e4, 1e4, 1e4};  // wider than the map
		std::vector<uint32_t> got;
		idx.query(qb, got);
		std::sort(got.begin(), got.end());
		std::vector<uint32_t> want;
		for (uint32_t i = 0; i < 500; ++i)
			if (live[i] && boxes[i].intersects(qb)) want.push_back(i);
		EXPECT_EQ(got, want) << q;
	}
}

TEST(VectorIndex, NegativeAndLargeCoordinates)
{
	VectorIndex idx(1.0);
	idx.insert(0, {-1e5, -1e5, -1e5 + 1, -1e5 + 1});
	idx.insert(1, {1e5, 1e5, 1e5 + 1, 1e5 + 1});
	std::vector<uint32_t> out;
	idx.query({-1e5 - 0.5, -1e5 - 0.5, -1e5 + 0.5, -1e5 + 0.5}, out);
	ASSERT_EQ(out.size(), 1u);
	EXPECT_EQ(out[0], 0u);
	EXPECT_THROW(VectorIndex(0.0), std::invalid_argument);
}

// A grazing wipe triangle's box can span kilometres (csail: 122 km x 37 km at 2 m buckets,
// 1.1e9 buckets); such boxes are listed once, and queries still find exactly the intersecting slots.
TEST(VectorIndex, HugeAndNonFiniteBoxesAreFoundWithoutBucketing)
{
	VectorIndex idx(2.0);
	const Box2D huge{-2000.0, -40000.0, 120437.0, 36793.0};
	idx.insert(0, {0, 0, 1, 1});
	idx.insert(1, huge);
	idx.insert(2, {std::nan(""), 0, 1, 1});
	idx.insert(3, {5e4, 5e4, 5e4 + 1, 5e4 + 1});
	EXPECT_EQ(idx.size(), 4u);
	std::vector<uint32_t> out;
	idx.query({0.5, 0.5, 0.6, 0.6}, out);
	std::sort(out.begin(), out.end());
	EXPECT_EQ(out, (std::vector<uint32_t>{0, 1}));
	out.clear();
	idx.query({1e5, 3e4, 1e5 + 1, 3e4 + 1}, out);  // inside the huge box only
	EXPECT_EQ(out, (std::vector<uint32_t>{1}));
	out.clear();
	idx.query({-1e6, -1e6, 1e6, 1e6}, out);  // wider than the map: every finite box once
	std::sort(out.begin(), out.end());
	EXPECT_EQ(out, (std::vector<uint32_t>{0, 1, 3}));
	idx.remove(1);
	idx.remove(2);
	out.clear();
	idx.query({1e5, 3e4, 1e5 + 1, 3e4 + 1}, out);
	EXPECT_TRUE(out.empty());
	idx.insert(1, {0.2, 0.2, 0.3, 0.3});  // the slot moves back into the buckets
	out.clear();
	idx.query({0.25, 0.25, 0.26, 0.26}, out);
	std::sort(out.begin(), out.end());
	EXPECT_EQ(out, (std::vector<uint32_t>{0, 1}));
	EXPECT_EQ(idx.size(), 3u);
}

// query() writes nothing in the index: threads querying one index at once get exactly the answers
// (slots and their order) of the same queries made one after the other.
TEST(VectorIndex, QueriesFromSeveralThreadsAtOnceGiveTheSingleThreadedAnswers)
{
	std::mt19937 rng(7);
	std::uniform_real_distribution<double> U(-30, 30), L(0, 5);
	VectorIndex idx(2.0);
	for (uint32_t i = 0; i < 400; ++i)
	{
		const double x = U(rng), y = U(rng);
		idx.insert(i, {x, y, x + L(rng), y + L(rng)});
	}
	idx.insert(400, {-1e5, -1e5, 1e5, 1e5});  // a wide box, listed once
	std::vector<Box2D> queries;
	for (int q = 0; q < 200; ++q)
	{
		const double x = U(rng), y = U(rng);
		queries.push_back(q % 40 == 0 ? Box2D{-1e4, -1e4, 1e4, 1e4} : Box2D{x, y, x + L(rng), y + L(rng)});
	}
	std::vector<std::vector<uint32_t>> want(queries.size());
	for (size_t q = 0; q < queries.size(); ++q) idx.query(queries[q], want[q]);
	std::atomic<int> wrong{0};
	std::vector<std::thread> threads;
	for (int t = 0; t < 6; ++t)
		threads.emplace_back([&] {
			std::vector<uint32_t> got;
			for (int round = 0; round < 50; ++round)
				for (size_t q = 0; q < queries.size(); ++q)
				{
					got.clear();
					idx.query(queries[q], got);
					wrong += got != want[q];
				}
		});
	for (auto& th : threads) th.join();
	EXPECT_EQ(wrong.load(), 0);
}
