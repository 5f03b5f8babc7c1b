// CGridVectorMap's const members from several threads at once: every thread gets exactly the
// single-threaded answers (likelihoods, matching pairs, squared distances, matching ratios, text,
// occupancy grid, visualisation, saved files), as the const = safe-to-share contract promises.
#include <gtest/gtest.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <array>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include "corridor_map.h"

using mrpt::maps::CGridVectorMap;
using mrpt::maps::CSimplePointsMap;
using mrpt::math::TPose2D;
using mrpt::poses::CPose2D;

namespace
{
/** What one thread asks the map: scans at poses (likelihood, ICP-style matching) and points (nearest). */
struct Queries
{
	std::vector<TPose2D> poses;
	std::vector<mrpt::obs::CObservation2DRangeScan> scans;
	std::vector<CSimplePointsMap> points;
	std::vector<mrpt::math::TPoint2D> probes;  //!< squareDistanceToClosestCorrespondence, some far off the map
};

Queries corridorQueries()
{
	Queries q;
	auto walls = gvtest::corridorWorld();
	walls.push_back({4, 0, 4, -0.9});
	for (int k = 0; k < 12; ++k)
	{
		const TPose2D truth(1.2 + 7.5 * k / 11, 0.9 + 0.2 * std::cos(k), 0.4 * std::sin(0.7 * k));
		q.poses.push_back(TPose2D(truth.x + 0.05 * std::sin(k), truth.y - 0.04, truth.phi + 0.02));
		q.scans.push_back(gvtest::scanOf(truth, walls, {}, 500 + unsigned(k)));
		q.points.push_back(gvtest::scanPoints(q.scans.back()));
	}
	for (double x = -3; x <= 13; x += 1.7)
		for (double y = -6; y <= 4; y += 1.3) q.probes.emplace_back(x, y);
	q.probes.emplace_back(80.0, -60.0);  // farther than every vector: the index query wider than the map
	return q;
}

mrpt::maps::TMatchingParams gate(double d, bool closest, bool unique)
{
	mrpt::maps::TMatchingParams p;
	p.maxDistForCorrespondence = float(d);
	p.maxAngularDistForCorrespondence = 0.02f;
	p.onlyKeepTheClosest = closest;
	p.onlyUniqueRobust = unique;
	return p;
}

/** Every answer of the const queries, compared exactly (same code, same inputs: same bits). */
struct Answers
{
	std::vector<double> likelihoods;
	std::vector<std::vector<std::array<float, 7>>> pairs;  //!< per call: global xyz, local xyz, error
	std::vector<std::vector<std::array<uint32_t, 2>>> indices;  //!< per call: globalIdx, localIdx
	std::vector<float> sums, ratios, sqrDists;
	std::string text;
	std::vector<mrpt::maps::COccupancyGridMap2D::cellType> grid;
	std::vector<size_t> lines;
	bool operator==(const Answers& o) const
	{
		return likelihoods == o.likelihoods && pairs == o.pairs && indices == o.indices && sums == o.sums &&
			   ratios == o.ratios && sqrDists == o.sqrDists && text == o.text && grid == o.grid && lines == o.lines;
	}
};

void matchInto(const CGridVectorMap& map, const CSimplePointsMap& pts, const TPose2D& x,
			   const mrpt::maps::TMatchingParams& params, Answers& a)
{
	mrpt::tfest::TMatchingPairList pairs;
	mrpt::maps::TMatchingExtraResults extra;
	map.determineMatching2D(&pts, CPose2D(x), pairs, params, extra);
	auto& ps = a.pairs.emplace_back();
	auto& is = a.indices.emplace_back();
	for (const auto& m : pairs)
	{
		ps.push_back(
			{m.global.x, m.global.y, m.global.z, m.local.x, m.local.y, m.local.z, m.errorSquareAfterTransformation});
		is.push_back({m.globalIdx, m.localIdx});
	}
	a.sums.push_back(extra.sumSqrDist);
	a.ratios.push_back(extra.correspondencesRatio);
}

Answers ask(const CGridVectorMap& map, const Queries& q, bool withGrid)
{
	Answers a;
	for (size_t k = 0; k < q.poses.size(); ++k)
	{
		a.likelihoods.push_back(
			map.computeObservationLikelihood(q.scans[k], mrpt::poses::CPose3D(CPose2D(q.poses[k]))));
		matchInto(map, q.points[k], q.poses[k], gate(0.3, true, false), a);
		matchInto(map, q.points[k], q.poses[k], gate(0.3, false, false), a);
		matchInto(map, q.points[k], q.poses[k], gate(0.5, true, true), a);
		a.ratios.push_back(map.compute3DMatchingRatio(&q.points[k], mrpt::poses::CPose3D(CPose2D(q.poses[k])), {}));
	}
	for (const auto& p : q.probes)
		a.sqrDists.push_back(map.squareDistanceToClosestCorrespondence(float(p.x), float(p.y)));
	a.text = map.asString();
	if (withGrid) a.grid = map.getAsOccupancyGrid().getRawMap();
	mrpt::opengl::CSetOfObjects viz;
	map.getVisualizationInto(viz);
	for (const auto& o : viz)
		if (const auto* l = dynamic_cast<const mrpt::opengl::CSetOfLines*>(o.get()))
			a.lines.push_back(l->getLineCount());
	return a;
}

std::string bytesOf(const std::filesystem::path& p)
{
	std::ifstream in(p, std::ios::binary);
	return std::string(std::istreambuf_iterator<char>(in), {});
}

/** The files the save* members write under `prefix`, their bytes. */
std::vector<std::string> savedFiles(const CGridVectorMap& map, const std::string& prefix)
{
	map.saveMetricMapRepresentationToFile(prefix);
	map.saveToFile(prefix + ".gvmap");
	std::vector<std::string> out;
	for (const char* s : {"_vectors.txt", "_vectors.svg", "_occupancy.png"}) out.push_back(bytesOf(prefix + s));
	out.push_back(bytesOf(prefix + ".gvmap"));
	return out;
}
}  // namespace

TEST(MapConcurrency, ConstQueriesFromEightThreadsGiveTheSingleThreadedAnswers)
{
	gridvector::GridVectorConfig cfg;
	cfg.matching.staticThreshold = 0.5;  // the door's and the trolley's early columns are not static stretches
	const CGridVectorMap map = gvtest::corridorMap(cfg);
	ASSERT_GE(map.vectors().size(), 12u);
	const Queries q = corridorQueries();
	const Answers want = ask(map, q, true);
	ASSERT_GT(want.pairs[0].size(), 100u);  // the queries do find correspondences
	Answers wantNoGrid = want;
	wantNoGrid.grid.clear();
	const auto dir = std::filesystem::temp_directory_path() / ("gv_map_concurrency_" + std::to_string(::getpid()));
	std::filesystem::create_directories(dir);
	const std::vector<std::string> wantFiles = savedFiles(map, (dir / "single").string());

	constexpr int kThreads = 8, kRounds = 12;
	std::atomic<int> wrong{0}, wrongFiles{0}, failed{0};
	std::vector<std::thread> threads;
	for (int t = 0; t < kThreads; ++t)
		threads.emplace_back([&, t] {
			try
			{
				for (int r = 0; r < kRounds; ++r)
				{
					const bool withGrid = r == t % kRounds;  // one occupancy grid per thread, at different rounds
					if (!(ask(map, q, withGrid) == (withGrid ? want : wantNoGrid))) ++wrong;
				}
				if (savedFiles(map, (dir / ("thread" + std::to_string(t))).string()) != wantFiles) ++wrongFiles;
			}
			catch (...)
			{
				++failed;
			}
		});
	for (auto& th : threads) th.join();
	std::filesystem::remove_all(dir);
	EXPECT_EQ(failed.load(), 0);
	EXPECT_EQ(wrong.load(), 0) << "of " << kThreads * kRounds << " rounds, each " << q.poses.size() << " poses";
	EXPECT_EQ(wrongFiles.load(), 0);
}
