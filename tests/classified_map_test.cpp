// ClassifiedMap: the sequential map with the E-step (Eq. 14-15) on what each scan touched.
#include "em_world.h"

#include "online/ClassifiedMap.h"

#include <gtest/gtest.h>

using namespace gridvector;
using emtest::TPose2D;

TEST(ClassifiedMap, WallsStaticAndAnObjectSeenThroughDynamic)
{
	const auto truth = emtest::ringPath(2, 0.5);
	const size_t lap = truth.size() / 2;
	const std::vector<emtest::Wall> board = {{5.0, 1.35, 5.0, 1.95}};  // stands while scan 4 sees it
	ClassifiedMap map;
	auto boardVector = [&]() -> const GridVector* {
		for (const auto& v : map.map().vectors())
			if (std::abs(v.centre().x - 5.0) < 0.1 && v.centre().y > 1.3 && v.centre().y < 2.0) return &v;
		return nullptr;
	};
	for (size_t t = 0; t <= 4; ++t)
	{
		auto walls = emtest::corridorWorld();
		if (t >= 4) walls.insert(walls.end(), board.begin(), board.end());
		EXPECT_GT(map.insert(truth[t], emtest::observe(walls, truth[t], 6.0, unsigned(t))), 0u);
	}
	ASSERT_NE(boardVector(), nullptr);
	EXPECT_EQ(map.stateOf(*boardVector()), VectorState::Static);  // seen once: its own hits
	for (size_t t = lap; t <= lap + 8; ++t) map.insert(truth[t], emtest::observe(emtest::corridorWorld(), truth[t], 6.0, unsigned(t)));
	ASSERT_NE(boardVector(), nullptr);
	EXPECT_EQ(map.stateOf(*boardVector()), VectorState::Dynamic);
	// every vector classified; most of the walls static (em_world's scans see walls through others, which
	// makes those stretches dynamic: no occlusion)
	double staticLen = 0, len = 0;
	for (const auto& v : map.map().vectors())
	{
		EXPECT_NE(map.piecesOf(v.id), nullptr);
		len += v.length();
		staticLen += map.stateOf(v) == VectorState::Static ? v.length() : 0;
	}
	EXPECT_GT(staticLen, 0.5 * len);
	size_t dynamicChildren = 0;
	for (const auto& c : map.children()) dynamicChildren += c.state == VectorState::Dynamic;
	EXPECT_GT(dynamicChildren, 0u);
}
