// ClassifiedMap: the batch E-step's map (Eq. 8's full product, Eq. 14-15) built scan by scan.
#include "em_world.h"

#include "estep/EStep.h"
#include "map/GlobalMap.h"
#include "online/ClassifiedMap.h"

#include <gtest/gtest.h>

using namespace gridvector;
using emtest::TPose2D;

namespace
{
const std::vector<emtest::Wall> kBoard = {{5.0, 1.35, 5.0, 1.95}};
bool onBoard(const GridVector& v) { return std::abs(v.centre().x - 5.0) < 0.1 && v.centre().y > 1.3 && v.centre().y < 2.0; }

std::vector<LocalScan> scansOf(const std::vector<TPose2D>& poses, size_t boardFrom, size_t boardTo)
{
	std::vector<LocalScan> out;
	for (size_t t = 0; t < poses.size(); ++t)
	{
		auto walls = emtest::corridorWorld();
		if (t >= boardFrom && t <= boardTo) walls.insert(walls.end(), kBoard.begin(), kBoard.end());
		out.push_back(emtest::observe(walls, poses[t], 6.0, unsigned(t)));
		out.back().scanIndex = int64_t(t);
	}
	return out;
}
}  // namespace

// After any number of scans the map is GlobalMap::buildPerScan's of those scans, cell for cell, and
// every vector's pieces are EStep::run's: the live verdicts are the batch E-step's.
TEST(ClassifiedMap, EqualsTheBatchEStepAfterEveryScan)
{
	const auto truth = emtest::ringPath(2, 0.5);
	const auto scans = scansOf(truth, 4, 14);
	const GridVectorConfig cfg;
	const EStep estep(cfg.estep, cfg.grid);
	ClassifiedMap map(cfg);
	for (size_t t = 0; t < truth.size(); ++t)
	{
		map.insert(truth[t], scans[t]);
		if (t % 9 != 4 && t + 1 != truth.size()) continue;
		const std::vector<TPose2D> poses(truth.begin(), truth.begin() + long(t + 1));
		const std::vector<LocalScan> sc(scans.begin(), scans.begin() + long(t + 1));
		const auto batch = GlobalMap::buildPerScan(poses, sc, cfg);
		ASSERT_EQ(map.perScan().size(), batch.size()) << t;
		for (size_t k = 0; k < batch.size(); ++k)
		{
			const GridVector &a = map.perScan()[k], &b = batch[k];
			ASSERT_EQ(a.id, b.id);
			ASSERT_EQ(a.scanIndex, b.scanIndex);
			ASSERT_EQ(a.cells().size(), b.cells().size());
			for (size_t c = 0; c < a.cells().size(); ++c)
			{
				ASSERT_EQ(a.cells()[c].n_occupy, b.cells()[c].n_occupy) << "scan " << t << " vector " << k;
				ASSERT_EQ(a.cells()[c].n_visit, b.cells()[c].n_visit) << "scan " << t << " vector " << k;
			}
		}
		const EStepResult e = estep.run(batch);
		const auto kids = map.children();
		ASSERT_EQ(kids.size(), e.children.size()) << t;
		for (size_t k = 0; k < kids.size(); ++k)
		{
			EXPECT_EQ(kids[k].id, e.children[k].id);
			EXPECT_EQ(kids[k].state, e.children[k].state);
			EXPECT_EQ(kids[k].cols(), e.children[k].cols());
		}
	}
}

// The board stands while scans 4..6 see it; the scans before saw the wall behind its place, the
// second lap sees through it again: dynamic then, the walls mostly static throughout.
TEST(ClassifiedMap, WallsStaticAndAnObjectSeenThroughDynamic)
{
	const auto truth = emtest::ringPath(2, 0.5);
	const size_t lap = truth.size() / 2;
	const auto scans = scansOf(truth, 4, 6);
	ClassifiedMap map;
	for (size_t t = 0; t <= 6; ++t) EXPECT_GT(map.insert(truth[t], scans[t]), 0u);
	for (size_t t = lap; t <= lap + 8; ++t) map.insert(truth[t], scans[t]);
	size_t board = 0;
	double staticLen = 0, len = 0;
	for (const auto& v : map.perScan())
	{
		EXPECT_NE(map.piecesOf(v.id), nullptr);
		if (onBoard(v) && v.length() > 0.3)
		{
			++board;
			EXPECT_EQ(map.stateOf(v), VectorState::Dynamic) << "board vector of scan " << v.scanIndex;
		}
		len += v.length();
		staticLen += map.stateOf(v) == VectorState::Static ? v.length() : 0;
	}
	EXPECT_GT(board, 0u);
	EXPECT_GT(staticLen, 0.5 * len);
	size_t dynamicChildren = 0;
	for (const auto& c : map.children()) dynamicChildren += c.state == VectorState::Dynamic;
	EXPECT_GT(dynamicChildren, 0u);
}
