// MRPT's own generic checks of a metric map (its unit tests of mrpt-maps and mrpt-slam: serialization,
// class factory, CMultiMetricMap, observation likelihood, ICP classic, MonteCarlo2D), re-run against
// CGridVectorMap, each next to what MRPT's own maps give on the same data.
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/maps/TMetricMapInitializer.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/stock_observations.h>
#include <mrpt/random.h>
#include <mrpt/rtti/CObject.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/slam/CICP.h>
#include <mrpt/slam/CMonteCarloLocalization2D.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "test_scans.h"

using mrpt::maps::CGridVectorMap;
using mrpt::maps::CMultiMetricMap;
using mrpt::poses::CPose2D;
using mrpt::poses::CPose3D;

namespace
{
const std::string kDatasets = GV_MRPT_DATASETS;

/** MRPT's stock scan `i` (mrpt::obs::stock_observations, the scans of MRPT's ICP test). */
mrpt::obs::CObservation2DRangeScan stockScan(int i)
{
	mrpt::obs::CObservation2DRangeScan s;
	mrpt::obs::stock_observations::example2DRangeScan(s, i);
	return s;
}

CGridVectorMap mapOfStockScan0()
{
	CGridVectorMap m;
	m.insertObservation(stockScan(0));
	return m;
}

CMultiMetricMap multiMapFrom(const std::string& iniText)
{
	mrpt::config::CConfigFileMemory ini(iniText);
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(ini, "MetricMap");
	CMultiMetricMap mm;
	mm.setListOfMaps(inits);
	return mm;
}
}  // namespace

// --- mrpt-maps serializations_unittest: every map class written and read back through an archive ---
TEST(MrptGenericChecks, SerializationRoundTripThroughAnArchive)
{
	const CGridVectorMap a = mapOfStockScan0();
	ASSERT_FALSE(a.isEmpty());
	mrpt::io::CMemoryStream buf;
	auto out = mrpt::serialization::archiveFrom(buf);
	out << a;
	buf.Seek(0);
	auto in = mrpt::serialization::archiveFrom(buf);
	const mrpt::serialization::CSerializable::Ptr o = in.ReadObject();
	ASSERT_TRUE(IS_CLASS(*o, CGridVectorMap));
	const auto& b = dynamic_cast<const CGridVectorMap&>(*o);
	ASSERT_EQ(b.vectors().size(), a.vectors().size());
	for (size_t i = 0; i < a.vectors().size(); ++i)
	{
		// the .gvmap stores endpoints on a 1 mm lattice (CompactMap)
		EXPECT_NEAR(b.vectors()[i].start().x, a.vectors()[i].start().x, 5e-4);
		EXPECT_NEAR(b.vectors()[i].start().y, a.vectors()[i].start().y, 5e-4);
		EXPECT_NEAR(b.vectors()[i].end().x, a.vectors()[i].end().x, 5e-4);
		EXPECT_NEAR(b.vectors()[i].end().y, a.vectors()[i].end().y, 5e-4);
	}
	EXPECT_EQ(b.insertedScans(), a.insertedScans());
	const auto upToLength = [](const std::string& t) { return t.substr(0, t.find("total length")); };
	EXPECT_EQ(upToLength(b.asString()), upToLength(a.asString()));  // the length to CompactMap's 1 mm lattice
}

// --- the class factory and the map registry MRPT's apps create maps through ---
TEST(MrptGenericChecks, ClassFactoryAndMapRegistryKnowTheMap)
{
	const auto* cls = mrpt::rtti::findRegisteredClass("mrpt::maps::CGridVectorMap");
	ASSERT_NE(cls, nullptr);
	const auto obj = mrpt::rtti::classFactory("mrpt::maps::CGridVectorMap");
	ASSERT_TRUE(obj);
	EXPECT_TRUE(IS_CLASS(*obj, CGridVectorMap));
	for (const char* name : {"mrpt::maps::CGridVectorMap", "gridVectorMap"})
	{
		const auto def = mrpt::maps::TMetricMapInitializer::factory(name);
		ASSERT_TRUE(def) << name;
		const auto map = mrpt::maps::internal::TMetricMapTypesRegistry::Instance().factoryMapObjectFromDefinition(*def);
		ASSERT_TRUE(map) << name;
		EXPECT_TRUE(IS_CLASS(*map, CGridVectorMap)) << name;
	}
}

// --- mrpt-maps CMultiMetricMap_unittest: made from an .ini, copied deep, moved, observations inserted ---
TEST(MrptGenericChecks, InsideACMultiMetricMapFromAnIni)
{
	const auto m1 = multiMapFrom(
		"[MetricMap]\ngridVectorMap_count = 1\npointsMap_count = 1\n"
		"[MetricMap_gridVectorMap_00_creationOpts]\nresolution = 0.05\n"
		"[MetricMap_gridVectorMap_00_insertOpts]\nsplit_threshold = 0.03\n"
		"[MetricMap_gridVectorMap_00_likelihoodOpts]\ndecimation = 4\n");
	ASSERT_EQ(m1.maps.size(), 2u);
	EXPECT_TRUE(m1.isEmpty());
	const auto gv = m1.mapByClass<CGridVectorMap>();
	ASSERT_TRUE(gv);
	EXPECT_DOUBLE_EQ(gv->config().grid.resolution, 0.05);
	EXPECT_DOUBLE_EQ(gv->config().extraction.splitThreshold, 0.03);
	EXPECT_EQ(gv->likelihoodOptions.decimation, 4);
	const auto scan = stockScan(0);
	m1.mapByClass<CGridVectorMap>()->insertObservation(scan);
	EXPECT_FALSE(m1.isEmpty());
	// deep copy
	CMultiMetricMap m2 = m1;
	const size_t n = gv->vectors().size();
	m1.mapByClass<CGridVectorMap>()->clear();
	EXPECT_EQ(m2.mapByClass<CGridVectorMap>()->vectors().size(), n);
	EXPECT_TRUE(m1.mapByClass<CGridVectorMap>()->isEmpty());
	// move
	const CMultiMetricMap m3 = std::move(m2);
	EXPECT_EQ(m3.mapByClass<CGridVectorMap>()->vectors().size(), n);
	// the multi-map's likelihood is the sum of its maps' (MRPT's CMultiMetricMap)
	const double l = m3.computeObservationLikelihood(scan, CPose3D());
	EXPECT_NEAR(l,
				m3.mapByClass<CGridVectorMap>()->computeObservationLikelihood(scan, CPose3D()) +
					m3.mapByClass<mrpt::maps::CSimplePointsMap>()->computeObservationLikelihood(scan, CPose3D()),
				1e-9 * std::abs(l));
}

// --- the observation likelihood: largest at the pose the map was made from, falling off around it ---
TEST(MrptGenericChecks, LikelihoodIsLargestAtTheTruePose)
{
	const CGridVectorMap m = mapOfStockScan0();
	const auto scan = stockScan(0);
	ASSERT_TRUE(m.canComputeObservationLikelihood(scan));
	const double atTruth = m.computeObservationLikelihood(scan, CPose3D());
	for (const CPose2D& off :
		 {CPose2D(0.1, 0, 0), CPose2D(0, 0.1, 0), CPose2D(-0.1, 0.05, 0), CPose2D(0, 0, 0.05), CPose2D(0.3, -0.2, 0.1)})
		EXPECT_LT(m.computeObservationLikelihood(scan, CPose3D(off)), atTruth) << off;
	// further off, less likely
	EXPECT_LT(m.computeObservationLikelihood(scan, CPose3D(CPose2D(0.2, 0, 0))),
			  m.computeObservationLikelihood(scan, CPose3D(CPose2D(0.05, 0, 0))));
}

// --- mrpt-slam CICP_unittest: stock scan 1 aligned to stock scan 0 by ICP classic, with MRPT's options ---
namespace
{
struct IcpRun
{
	CPose2D pose;
	unsigned iterations = 0;
	double goodness = 0;
};

IcpRun icpClassic(const mrpt::maps::CMetricMap& reference)
{
	mrpt::maps::CSimplePointsMap m2;
	m2.insertObservation(stockScan(1));
	mrpt::slam::CICP icp;
	icp.options.ICP_algorithm = mrpt::slam::icpClassic;
	icp.options.maxIterations = 100;
	icp.options.thresholdAng = mrpt::DEG2RAD(10.0);
	icp.options.thresholdDist = 0.75;
	icp.options.ALFA = 0.5;
	icp.options.smallestThresholdDist = 0.05;
	icp.options.doRANSAC = false;
	mrpt::slam::CICP::TReturnInfo info;
	const auto pdf = icp.Align(&reference, &m2, CPose2D(0.8, 0, 0), info);
	return {pdf->getMeanVal(), info.nIterations, info.goodness};
}
}  // namespace

TEST(MrptGenericChecks, IcpClassicAlignsMrptsStockScansAsAGridAndAPointsMapDo)
{
	const CPose2D good(0.820, 0.084, mrpt::DEG2RAD(8.73));  // MRPT's test's answer
	mrpt::maps::COccupancyGridMap2D grid(-10, 10, -10, 10, 0.05);
	grid.insertObservation(stockScan(0));
	mrpt::maps::CSimplePointsMap points;
	points.insertObservation(stockScan(0));
	const IcpRun g = icpClassic(grid), p = icpClassic(points), v = icpClassic(mapOfStockScan0());
	std::printf(
		"ICP classic: grid %u iterations goodness %.3f error %.4f m; points map %u, %.3f, %.4f m; "
		"grid-vector map %u, %.3f, %.4f m\n",
		g.iterations, g.goodness, g.pose.distanceTo(good), p.iterations, p.goodness, p.pose.distanceTo(good),
		v.iterations, v.goodness, v.pose.distanceTo(good));
	EXPECT_NEAR(v.pose.distanceTo(good), 0, 0.02);
	EXPECT_LT(v.iterations, 100u) << "stopped by the iteration cap";
	EXPECT_LE(v.iterations, std::max(g.iterations, p.iterations) * 3 / 2);
	EXPECT_GE(v.goodness, 0.9 * std::min(g.goodness, p.goodness));
}

// --- mrpt-slam CMonteCarloLocalization2D_unittest: pf-localization's loop on MRPT's localization demo ---
namespace
{
/** MRPT's test's answer: the robot's pose at the end of localization_demo.rawlog. */
const CPose2D kDemoEnd(15.904, -10.010, mrpt::DEG2RAD(4.93));

/** The CMultiMetricMap of MRPT's test (its [MetricMap] of montecarlo_test1.ini) with one map of
 * `mapName`'s kind and `sections` below it, built from localization_demo.simplemap. */
CMultiMetricMap::Ptr demoMap(const std::string& mapName, const std::string& sections)
{
	auto mm = std::make_shared<CMultiMetricMap>(multiMapFrom("[MetricMap]\n" + mapName + "_count = 1\n" + sections));
	mrpt::maps::CSimpleMap sm;
	mrpt::io::CFileGZInputStream f(kDatasets + "/localization_demo.simplemap.gz");
	mrpt::serialization::archiveFrom(f) >> sm;
	mm->loadFromProbabilisticPosesAndObservations(sm);
	return mm;
}

/** MRPT's grid as its test sets it up (montecarlo_test1.ini: 6 cm cells, LF_Trun). */
CMultiMetricMap::Ptr demoGrid()
{
	return demoMap(
		"occupancyGrid",
		"[MetricMap_occupancyGrid_00_creationOpts]\nresolution = 0.06\n"
		"[MetricMap_occupancyGrid_00_insertOpts]\nmaxDistanceInsertion = 15\n"
		"maxOccupancyUpdateCertainty = 0.55\nconsiderInvalidRangesAsFreeSpace = 1\n"
		"[MetricMap_occupancyGrid_00_likelihoodOpts]\nlikelihoodMethod = 4\nLF_decimation = 20\n"
		"LF_stdHit = 0.20\nLF_maxCorrsDistance = 0.30\nLF_zHit = 0.95\nLF_zRandom = 0.05\nLF_maxRange = 80\n");
}

/** The grid-vector map with every option at its default. */
CMultiMetricMap::Ptr demoGridVectorMap() { return demoMap("gridVectorMap", ""); }

/** The free space particles start in: the map's own grid for MRPT's, the Eq. 6 grid for ours. */
mrpt::maps::COccupancyGridMap2D freeSpaceOf(const CMultiMetricMap& mm)
{
	if (const auto g = mm.mapByClass<mrpt::maps::COccupancyGridMap2D>()) return *g;
	return mm.mapByClass<CGridVectorMap>()->getAsOccupancyGrid();
}

struct PfEnd
{
	CPose2D mean;
	double covTrace = 0;
	bool passed() const { return (mean - kDemoEnd).norm() < 0.10 && covTrace < 0.01; }  // MRPT's test's bounds
};

/** One run of pf-localization's loop (MRPT's test's options: 40000 initial particles, KLD
 * sampling, standard proposal) over localization_demo.rawlog from uniform free space in
 * x -10..10, y -15..-5, seeded. */
PfEnd localise(const CMultiMetricMap::Ptr& mm, uint32_t seed)
{
	mrpt::random::getRandomGenerator().randomize(seed);
	const size_t particles = 40000;
	mrpt::slam::CMonteCarloLocalization2D pdf(particles);
	pdf.options.metricMap = mm;
	auto& kld = pdf.options.KLD_params;
	kld.KLD_binSize_PHI = mrpt::DEG2RAD(10.0);
	kld.KLD_binSize_XY = 0.10;
	kld.KLD_delta = 0.01;
	kld.KLD_epsilon = 0.01;
	kld.KLD_maxSampleSize = 40000;
	kld.KLD_minSampleSize = 150;
	kld.KLD_minSamplesPerBin = 0;
	mrpt::bayes::CParticleFilter pf;
	pf.m_options.PF_algorithm = mrpt::bayes::CParticleFilter::pfStandardProposal;
	pf.m_options.resamplingMethod = mrpt::bayes::CParticleFilter::prMultinomial;
	pf.m_options.adaptiveSampleSize = true;
	pf.m_options.BETA = 0.5;
	auto grid = freeSpaceOf(*mm);
	pdf.resetUniformFreeSpace(&grid, 0.7, particles, -10, 10, -15, -5, -M_PI, M_PI);
	mrpt::obs::CRawlog rawlog;
	EXPECT_TRUE(rawlog.loadFromRawLogFile(kDatasets + "/localization_demo.rawlog"));
	mrpt::obs::CActionCollection::Ptr action;
	mrpt::obs::CSensoryFrame::Ptr sf;
	size_t entry = 0;
	for (size_t step = 0; entry + 1 < rawlog.size(); ++step)
	{
		if (!rawlog.getActionObservationPair(action, sf, entry)) break;
		if (step > 0) pf.executeOn(pdf, action.get(), sf.get());  // step 0: the initial particles
	}
	const auto [cov, mean] = pdf.getCovarianceAndMean();
	return {mean, cov.trace()};
}

/** Seeds of the comparison; GV_MC2D_SEEDS=n runs seeds 1..n instead of 1..6. */
uint32_t seedCount()
{
	const char* s = std::getenv("GV_MC2D_SEEDS");
	return s ? uint32_t(std::atoi(s)) : 6u;
}
}  // namespace

TEST(MrptGenericChecks, MonteCarlo2DLocalisesOnTheMapAsOftenAsOnMrptsGrid)
{
	if (!std::filesystem::exists(kDatasets + "/localization_demo.rawlog"))
		GTEST_SKIP() << "MRPT's datasets not found in " << kDatasets;
	const auto grid = demoGrid(), vectors = demoGridVectorMap();
	ASSERT_FALSE(vectors->mapByClass<CGridVectorMap>()->isEmpty());
	unsigned gridPassed = 0, vectorsPassed = 0;
	for (uint32_t seed = 1; seed <= seedCount(); ++seed)
	{
		const PfEnd g = localise(grid, seed), v = localise(vectors, seed);
		gridPassed += g.passed();
		vectorsPassed += v.passed();
		std::printf("seed %u: grid %.3f m off, cov trace %.4f; grid-vector map %.3f m off, cov trace %.4f\n", seed,
					(g.mean - kDemoEnd).norm(), g.covTrace, (v.mean - kDemoEnd).norm(), v.covTrace);
	}
	std::printf("MonteCarlo2D passes: MRPT's grid %u, grid-vector map %u of %u seeds\n", gridPassed, vectorsPassed,
				seedCount());
	EXPECT_GE(vectorsPassed, gridPassed);
	EXPECT_GE(vectorsPassed, seedCount() / 2);
}
