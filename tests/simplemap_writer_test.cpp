// writeSimplemap (gv-map --simplemap): the scans at their poses as an MRPT CSimpleMap, from which
// a CMultiMetricMap declared in an .ini (pf-localization's [MetricMap]) builds a CGridVectorMap.
#include "test_scans.h"

#include "io/RawlogWriter.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/poses/CPose3DPDF.h>
#include <mrpt/serialization/CArchive.h>

#include <filesystem>

using namespace gridvector::io;
namespace fs = std::filesystem;

namespace
{
std::string tmp(const std::string& name)
{
	return (fs::temp_directory_path() / ("gv_simplemap_test_" + name)).string();
}

/** Scans of an L-shaped room along a path, with no pose for every third scan. */
struct Fixture
{
	LogData log;
	std::vector<std::optional<mrpt::math::TPose2D>> poses;
	Fixture()
	{
		auto walls = gvtest::room(0, 0, 10, 4);
		walls.push_back({3, 2, 5, 2});  // a free-standing wall to break the symmetry
		for (int i = 0; i < 12; ++i)
		{
			const mrpt::math::TPose2D p(1 + 0.6 * i, 1.0 + 0.05 * i, 0.02 * i);
			ScanRecord r;
			r.timestamp = 100 + 0.2 * i;
			r.scan = std::make_shared<mrpt::obs::CObservation2DRangeScan>(gvtest::castScan(p, walls));
			log.scans.push_back(r);
			poses.push_back(i % 3 == 2 ? std::nullopt : std::optional(p));
		}
	}
};

mrpt::maps::CSimpleMap readSimplemap(const std::string& path)
{
	mrpt::io::CFileGZInputStream f(path);
	mrpt::maps::CSimpleMap sm;
	mrpt::serialization::archiveFrom(f) >> sm;
	return sm;
}
}  // namespace

TEST(SimplemapWriter, one_frame_per_posed_scan_with_its_exact_pose)
{
	Fixture fx;
	const std::string path = tmp("frames.simplemap");
	EXPECT_EQ(writeSimplemap(path, fx.log, fx.poses), 8u);
	const auto sm = readSimplemap(path);
	ASSERT_EQ(sm.size(), 8u);
	size_t k = 0;
	for (size_t i = 0; i < fx.poses.size(); ++i)
	{
		if (!fx.poses[i]) continue;
		const auto& [pdf, sf] = sm.get(k++);
		const auto mean = pdf->getMeanVal();
		EXPECT_NEAR(mean.x(), fx.poses[i]->x, 1e-9);
		EXPECT_NEAR(mean.y(), fx.poses[i]->y, 1e-9);
		EXPECT_NEAR(mean.yaw(), fx.poses[i]->phi, 1e-9);
		ASSERT_EQ(sf->size(), 1u);
		const auto scan = sf->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
		ASSERT_TRUE(scan);
		EXPECT_EQ(scan->getScanSize(), fx.log.scans[i].scan->getScanSize());
		EXPECT_EQ(scan->getScanRange(100), fx.log.scans[i].scan->getScanRange(100));
	}
	fs::remove(path);
}

// pf-localization's route: TSetOfMetricMapInitializers from [MetricMap], then
// CMultiMetricMap::loadFromProbabilisticPosesAndObservations(simplemap).
TEST(SimplemapWriter, mrpt_multimetric_map_builds_the_same_grid_vector_map)
{
	Fixture fx;
	const std::string path = tmp("multi.simplemap");
	writeSimplemap(path, fx.log, fx.poses);
	mrpt::config::CConfigFileMemory ini(
		"[MetricMap]\ngridVectorMap_count=1\n[MetricMap_gridVectorMap_00_likelihoodOpts]\nsigma=0.1\n");
	mrpt::maps::TSetOfMetricMapInitializers defs;
	defs.loadFromConfigFile(ini, "MetricMap");
	mrpt::maps::CMultiMetricMap multi;
	multi.setListOfMaps(defs);
	multi.loadFromProbabilisticPosesAndObservations(readSimplemap(path));
	const auto gv = multi.mapByClass<mrpt::maps::CGridVectorMap>();
	ASSERT_TRUE(gv);
	EXPECT_DOUBLE_EQ(gv->likelihoodOptions.sigma, 0.1);

	mrpt::maps::CGridVectorMap direct;
	for (size_t i = 0; i < fx.poses.size(); ++i)
		if (fx.poses[i])
			direct.insertObservation(*fx.log.scans[i].scan,
									 mrpt::poses::CPose3D(fx.poses[i]->x, fx.poses[i]->y, 0, fx.poses[i]->phi, 0, 0));
	EXPECT_EQ(gv->insertedScans(), 8u);
	ASSERT_EQ(gv->vectors().size(), direct.vectors().size());
	EXPECT_GE(gv->vectors().size(), 4u);

	// The multi-map's likelihood (what CMonteCarloLocalization2D calls) prefers the true pose.
	const auto& scan = *fx.log.scans[2].scan;  // a scan that is not in the map
	const mrpt::math::TPose2D truth(1 + 0.6 * 2, 1.0 + 0.05 * 2, 0.04);
	const double atTruth =
		multi.computeObservationLikelihood(scan, mrpt::poses::CPose3D(truth.x, truth.y, 0, truth.phi, 0, 0));
	const double shifted =
		multi.computeObservationLikelihood(scan, mrpt::poses::CPose3D(truth.x + 0.3, truth.y, 0, truth.phi, 0, 0));
	EXPECT_GT(atTruth, shifted + 1.0);
	fs::remove(path);
}

TEST(SimplemapWriter, bad_input_is_an_error_and_leaves_no_file)
{
	Fixture fx;
	const std::string path = tmp("bad.simplemap");
	fs::remove(path);
	auto fewer = fx.poses;
	fewer.pop_back();
	EXPECT_THROW(writeSimplemap(path, fx.log, fewer), std::invalid_argument);
	const std::vector<std::optional<mrpt::math::TPose2D>> none(fx.log.scans.size());
	EXPECT_THROW(writeSimplemap(path, fx.log, none), std::invalid_argument);
	EXPECT_FALSE(fs::exists(path));
	try
	{
		writeSimplemap("/nonexistent-dir/x.simplemap", fx.log, fx.poses);
		FAIL() << "no error for an unwritable path";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/x.simplemap: cannot write"), std::string::npos)
			<< e.what();
	}
}
