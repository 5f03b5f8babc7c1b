// Eq. 8 over a whole trajectory: the product vector by vector equals ScanWipe scan by scan, bit for bit.
#include "map/GlobalMap.h"
#include "extraction/VectorExtractor.h"
#include "map/WipeProduct.h"

#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>

#include "test_scans.h"

using namespace gridvector;
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

namespace
{
/** Per-scan vectors m_{i,t} of a trajectory through a room with a pillar
 * (corners share rays, the pillar's sides occlude the walls), the ranges of
 * each scan, and the sensor positions. */
struct PerScan
{
	std::vector<GridVector> map;
	std::vector<size_t> first;
	std::vector<TPoint2D> sensors;
};

PerScan roomTrajectory(size_t scans, double roomOffsetEvery = 0)
{
	PerScan p;
	const VectorExtractor ex;
	for (size_t t = 0; t < scans; ++t)
	{
		const double ox = roomOffsetEvery > 0 && t % 2 ? roomOffsetEvery : 0.0;  // odd scans: a room far away
		auto walls = gvtest::room(ox - 4, -3, ox + 4, 3);
		const auto pillar = gvtest::room(ox + 1, 0.5, ox + 1.6, 1.1);
		walls.insert(walls.end(), pillar.begin(), pillar.end());
		const TPose2D pose(ox - 2.5 + 0.35 * double(t), -1.0 + 0.1 * double(t), 0.4 * double(t));
		LocalScan l = ex.extract(gvtest::castScan(pose, walls));
		p.first.push_back(p.map.size());
		p.sensors.push_back(GlobalMap::sensorPosition(pose, l));
		for (const auto& v : l.vectors) p.map.push_back(v.compose(pose));
	}
	p.first.push_back(p.map.size());
	return p;
}

/** The reference: ScanWipe::apply scan by scan, each scan leaving its own vectors out. */
ScanWipe::Stats scanByScan(const PerScan& p, std::vector<GridVector>& map, bool beams)
{
	VectorIndex index(2.0);
	for (size_t i = 0; i < map.size(); ++i) index.insert(uint32_t(i), Box2D::of(map[i]));
	ScanWipe wiper(0.05, beams);
	ScanWipe::Stats total;
	for (size_t t = 0; t + 1 < p.first.size(); ++t)
	{
		std::vector<ScanWipe::Segment> segs;
		for (size_t i = p.first[t]; i < p.first[t + 1]; ++i) segs.push_back(ScanWipe::segmentOf(map[i]));
		const auto st = wiper.apply(p.sensors[t], segs, map, index, [&](size_t, uint32_t s) {
			return s >= p.first[t] && s < p.first[t + 1] ? WipePart::Outside : WipePart::Hit;
		});
		total.triangles += st.triangles, total.candidates += st.candidates;
		total.vectorsTouched += st.vectorsTouched, total.cellsHit += st.cellsHit;
		total.cellsVisited += st.cellsVisited;
	}
	return total;
}

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }
}  // namespace

TEST(WipeProduct, SameCellsAndCountsAsScanByScanInBothWeightings)
{
	const PerScan p = roomTrajectory(14);
	ASSERT_GT(p.map.size(), 40u);
	for (const bool beams : {false, true})
	{
		SCOPED_TRACE(beams ? "per beam" : "per cell");
		std::vector<GridVector> ref = p.map, got = p.map;
		const ScanWipe::Stats a = scanByScan(p, ref, beams);
		const ScanWipe::Stats b = WipeProduct(0.05, beams, 0.5).apply(p.sensors, p.first, got);
		EXPECT_EQ(a.triangles, b.triangles);
		EXPECT_EQ(a.vectorsTouched, b.vectorsTouched);
		EXPECT_EQ(a.cellsHit, b.cellsHit);
		EXPECT_EQ(a.cellsVisited, b.cellsVisited);
		EXPECT_GT(b.cellsHit, 1000u);
		size_t differ = 0, changed = 0;
		for (size_t i = 0; i < ref.size(); ++i)
			for (size_t c = 0; c < ref[i].cells().size(); ++c)
			{
				const GridCell &x = ref[i].cells()[c], &y = got[i].cells()[c];
				differ += !sameBits(x.n_occupy, y.n_occupy) || !sameBits(x.n_visit, y.n_visit);
				changed += !sameBits(y.n_visit, p.map[i].cells()[c].n_visit);
			}
		EXPECT_EQ(differ, 0u);
		EXPECT_GT(changed, 1000u);  // the product did update the map
	}
}

TEST(WipeProduct, ScansReachOnlyOtherScansVectorsNearThem)
{
	// Even scans in one room, odd scans in a copy 100 m away.
	const PerScan p = roomTrajectory(6, 100.0);
	std::vector<GridVector> got = p.map;
	WipeProduct(0.05, false, 2.0).apply(p.sensors, p.first, got);
	for (size_t t = 0; t + 1 < p.first.size(); ++t)
	{
		double before = 0, after = 0;
		for (size_t i = p.first[t]; i < p.first[t + 1]; ++i)
		{
			// per cell, n_visit counts the scans that reached the cell: at most the other two of its room
			for (size_t c = 0; c < got[i].cells().size(); ++c)
				EXPECT_LE(got[i].cells()[c].n_visit - p.map[i].cells()[c].n_visit, 2.0f) << i;
			before += p.map[i].totalVisit(), after += got[i].totalVisit();
		}
		EXPECT_GT(after, before + 50) << t;  // ... which do reach its walls
	}
}

// Scan 1 sees scan 0's wall 0.2 m further away. At map.hit_band (0.05 m) it sees through scan 0's vector; from a
// scanner whose noise allowance is 0.3 m (ScanWipe::hitBandFor) the same cells are its hits.
TEST(WipeProduct, AScansNoiseWidensItsHitBand)
{
	const GridOptions grid;
	PerScan p;
	p.map = {GridVector({1, 1.0}, {-1, 1.0}, grid), GridVector({1, 1.2}, {-1, 1.2}, grid)};
	p.first = {0, 1, 2};
	p.sensors = {{0, 0}, {0, 0}};
	auto occupied = [](const GridVector& v) {
		double n = 0;
		for (const auto& c : v.cells()) n += c.n_occupy;
		return n;
	};
	GridVectorConfig cfg;
	cfg.map.hitBand = 0.05;
	LocalScan noisy;
	noisy.rangeSigma = 0.1;  // x break_noise_sigmas 3
	EXPECT_EQ(ScanWipe::hitBandFor(cfg, LocalScan{}), 0.05);
	EXPECT_DOUBLE_EQ(ScanWipe::hitBandFor(cfg, noisy), 0.3);
	std::vector<GridVector> narrow = p.map, wide = p.map;
	WipeProduct(0.05, false, 2.0).apply(p.sensors, p.first, narrow);
	WipeProduct(0.05, false, 2.0).apply(p.sensors, p.first, wide, {0.05, ScanWipe::hitBandFor(cfg, noisy)});
	EXPECT_EQ(occupied(narrow[0]), occupied(p.map[0]));  // seen through: visits only
	EXPECT_GT(narrow[0].totalVisit(), p.map[0].totalVisit());
	EXPECT_GT(occupied(wide[0]), occupied(p.map[0]) + 10);  // hit, row by row
	EXPECT_THROW(WipeProduct(0.05, false, 2.0).apply(p.sensors, p.first, wide, {0.05}), std::invalid_argument);
}

TEST(WipeProduct, RejectsRangesThatDoNotCoverTheMap)
{
	PerScan p = roomTrajectory(2);
	p.first.back() -= 1;
	EXPECT_THROW(WipeProduct(0.05, false, 2.0).apply(p.sensors, p.first, p.map), std::invalid_argument);
}
