#include "map/OccupancyConversion.h"
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/CMultiMetricMap.h>
#include <mrpt/opengl/CSetOfObjects.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include "test_scans.h"

using mrpt::maps::CGridVectorMap;
using mrpt::math::TPose2D;

namespace
{
const auto kRoom = gvtest::room(-3, -2, 5, 3);

mrpt::obs::CObservation2DRangeScan scanAt(const TPose2D& p) { return gvtest::castScan(p, kRoom, {}, 361, M_PI); }

/** A CMultiMetricMap as MRPT's apps make one: from the map section "[map]" of an .ini text. */
mrpt::maps::CMultiMetricMap multiMapFrom(const std::string& iniText)
{
	mrpt::config::CConfigFileMemory ini(iniText);
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(ini, "map");
	mrpt::maps::CMultiMetricMap mm;
	mm.setListOfMaps(inits);
	return mm;
}

/** The message of the exception multiMapFrom(iniText) throws ("" if none). */
std::string iniError(const std::string& iniText)
{
	try
	{
		multiMapFrom(iniText);
	}
	catch (const std::exception& e)
	{
		return e.what();
	}
	return "";
}

CGridVectorMap mapOfRoom()
{
	CGridVectorMap m;
	for (int k = 0; k < 4; ++k)
	{
		const TPose2D p(0.5 * k, 0.2, 0.4 + 0.8 * k);
		m.insertObservation(scanAt(p), mrpt::poses::CPose3D(mrpt::poses::CPose2D(p)));
	}
	return m;
}
}  // namespace

TEST(CGridVectorMap, CreatedFromMultiMetricMapIniByShortName)
{
	mrpt::config::CConfigFileMemory ini(
		"[map]\ngridVectorMap_count = 1\npointsMap_count = 1\n"
		"[map_gridVectorMap_00_grid]\nresolution = 0.05\n"
		"[map_gridVectorMap_00_likelihoodOpts]\nsigma = 0.1\n");
	mrpt::maps::TSetOfMetricMapInitializers inits;
	inits.loadFromConfigFile(ini, "map");
	mrpt::maps::CMultiMetricMap mm;
	mm.setListOfMaps(inits);
	auto gv = mm.mapByClass<CGridVectorMap>();
	ASSERT_TRUE(gv);
	EXPECT_DOUBLE_EQ(gv->config().grid.resolution, 0.05);
	EXPECT_DOUBLE_EQ(gv->likelihoodOptions.sigma, 0.1);
	mm.insertObservation(scanAt(TPose2D(0, 0, 0)));
	EXPECT_FALSE(gv->isEmpty());
}

TEST(CGridVectorMap, UnknownIniKeyIsRejected)
{
	mrpt::config::CConfigFileMemory ini(
		"[map]\ngridVectorMap_count = 1\n[map_gridVectorMap_00_grid]\nresolushun = 0.05\n");
	mrpt::maps::TSetOfMetricMapInitializers inits;
	EXPECT_THROW(inits.loadFromConfigFile(ini, "map"), std::exception);
}

TEST(CGridVectorMap, MisspeltSectionOfTheMapIsRejectedMrptsOwnAccepted)
{
	// [map_gridVectorMap_00_gird] used to be passed over: its keys silently took their defaults
	const std::string e = iniError("[map]\ngridVectorMap_count = 1\n[map_gridVectorMap_00_gird]\nresolution = 0.05\n");
	EXPECT_NE(e.find("unknown section [map_gridVectorMap_00_gird]"), std::string::npos) << e;
	// MRPT's [<prefix>_creationOpts] (TMapGenericParams) is the map's own and is honoured
	auto mm = multiMapFrom(
		"[map]\ngridVectorMap_count = 1\n[map_gridVectorMap_00_creationOpts]\nenableObservationInsertion = false\n");
	mm.insertObservation(scanAt(TPose2D(0, 0, 0)));
	EXPECT_TRUE(mm.mapByClass<CGridVectorMap>()->isEmpty());
}

TEST(CGridVectorMap, MrptsOwnSectionNamesCarryTheMapsKeys)
{
	// as for COccupancyGridMap2D: the layout in creationOpts, what insertion uses in insertOpts
	const auto mm = multiMapFrom(
		"[map]\ngridVectorMap_count = 1\n"
		"[map_gridVectorMap_00_creationOpts]\nresolution = 0.05\nhalf_width = 2\nenableSaveAs3DObject = false\n"
		"[map_gridVectorMap_00_insertOpts]\nsplit_threshold = 0.03\nmin_points = 5\nhit_band = 0.04\n"
		"merge_on_insert = false\n"
		"[map_gridVectorMap_00_likelihoodOpts]\nsigma = 0.08\n");
	const auto gv = mm.mapByClass<CGridVectorMap>();
	ASSERT_TRUE(gv);
	EXPECT_DOUBLE_EQ(gv->config().grid.resolution, 0.05);
	EXPECT_EQ(gv->config().grid.halfWidth, 2);
	EXPECT_FALSE(gv->genericMapParams.enableSaveAs3DObject);
	EXPECT_DOUBLE_EQ(gv->config().extraction.splitThreshold, 0.03);
	EXPECT_EQ(gv->config().extraction.minPoints, 5);
	EXPECT_DOUBLE_EQ(gv->config().map.hitBand, 0.04);
	EXPECT_FALSE(gv->config().map.mergeOnInsert);
	EXPECT_DOUBLE_EQ(gv->likelihoodOptions.sigma, 0.08);
	// each section takes only its groups' keys, each key once, in its range
	const std::string head = "[map]\ngridVectorMap_count = 1\n";
	EXPECT_NE(iniError(head + "[map_gridVectorMap_00_insertOpts]\nresolution = 0.05\n")
				  .find("unknown key 'resolution' in section [map_gridVectorMap_00_insertOpts]"),
			  std::string::npos);
	EXPECT_NE(iniError(head + "[map_gridVectorMap_00_insertOpts]\nmaxDistanceInsertion = 15\n")
				  .find("unknown key 'maxDistanceInsertion' in section [map_gridVectorMap_00_insertOpts]"),
			  std::string::npos);
	EXPECT_NE(iniError(head + "[map_gridVectorMap_00_creationOpts]\nresolution = 0.05\n"
							  "[map_gridVectorMap_00_grid]\nresolution = 0.1\n")
				  .find("[map_gridVectorMap_00_creationOpts] resolution is also set in [map_gridVectorMap_00_grid]"),
			  std::string::npos);
	EXPECT_NE(iniError(head + "[map_gridVectorMap_00_creationOpts]\nresolution = 5\n")
				  .find("[map_gridVectorMap_00_creationOpts] resolution = '5' must be in (0, 1]"),
			  std::string::npos);
	EXPECT_NE(iniError(head + "[map_gridVectorMap_00_insertOpts]\nmin_points = three\n")
				  .find("[map_gridVectorMap_00_insertOpts] min_points = 'three' is not an integer"),
			  std::string::npos);
	// a grid's likelihood-field names say which of ours they are
	EXPECT_NE(iniError(head + "[map_gridVectorMap_00_likelihoodOpts]\nLF_stdHit = 0.2\n")
				  .find("LF_stdHit is COccupancyGridMap2D's key; this map's is sigma"),
			  std::string::npos);
}

TEST(CGridVectorMap, LikelihoodOptionsAreReadStrictly)
{
	for (const char* bad : {"sigma = abc", "sigma = 0", "decimation = 2.5", "zRandom = 1", "maxCorrDistance = nan"})
	{
		const std::string e = iniError(
			std::string("[map]\ngridVectorMap_count = 1\n[map_gridVectorMap_00_likelihoodOpts]\n") + bad + "\n");
		const std::string key(bad, std::strchr(bad, ' '));
		EXPECT_NE(e.find("[map_gridVectorMap_00_likelihoodOpts] " + key + " = "), std::string::npos)
			<< bad << ": " << e;
	}
	// the whole message: who read it, section, key, the text and what it should be
	EXPECT_NE(
		iniError("[map]\ngridVectorMap_count = 1\n[map_gridVectorMap_00_likelihoodOpts]\nzRandom = 1\n")
			.find(
				"CGridVectorMap config: [map_gridVectorMap_00_likelihoodOpts] zRandom = '1' is not a number in [0,1)"),
		std::string::npos);
	EXPECT_NE(iniError("[map]\ngridVectorMap_count = 1\n[map_gridVectorMap_00_likelihoodOpts]\ndecimation = 0\n")
				  .find("[map_gridVectorMap_00_likelihoodOpts] decimation = '0' is not an integer in [1,1000000]"),
			  std::string::npos);
	EXPECT_NE(iniError("[map]\ngridVectorMap_count = 1\n[map_gridVectorMap_00_likelihoodOpts]\nsgima = 1\n")
				  .find("CGridVectorMap config: unknown key 'sgima' in section [map_gridVectorMap_00_likelihoodOpts]"),
			  std::string::npos);
	// valid values are taken
	const auto mm = multiMapFrom(
		"[map]\ngridVectorMap_count = 1\n[map_gridVectorMap_00_likelihoodOpts]\nsigma = 0.07\nmaxCorrDistance = 0.4\n"
		"zRandom = 0\ndecimation = 3\n");
	const auto& lo = mm.mapByClass<CGridVectorMap>()->likelihoodOptions;
	EXPECT_DOUBLE_EQ(lo.sigma, 0.07);
	EXPECT_DOUBLE_EQ(lo.maxCorrDistance, 0.4);
	EXPECT_DOUBLE_EQ(lo.zRandom, 0);
	EXPECT_EQ(lo.decimation, 3);
}

TEST(CGridVectorMap, SerializedInsideAMultiMetricMap)
{
	auto a = multiMapFrom(
		"[map]\ngridVectorMap_count = 1\npointsMap_count = 1\n[map_gridVectorMap_00_grid]\nresolution = 0.05\n");
	for (int k = 0; k < 3; ++k)
	{
		const TPose2D p(0.5 * k, 0.2, 0.4 + 0.8 * k);
		a.insertObservation(scanAt(p), mrpt::poses::CPose3D(mrpt::poses::CPose2D(p)));
	}
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << a;
	buf.Seek(0);
	mrpt::maps::CMultiMetricMap b;
	arch >> b;
	const auto ga = a.mapByClass<CGridVectorMap>(), gb = b.mapByClass<CGridVectorMap>();
	ASSERT_TRUE(gb);
	EXPECT_DOUBLE_EQ(gb->config().grid.resolution, 0.05);
	EXPECT_EQ(gb->insertedScans(), 3u);
	ASSERT_EQ(gb->vectors().size(), ga->vectors().size());
	for (size_t i = 0; i < ga->vectors().size(); ++i)  // endpoints on CompactMap's 1 mm lattice
	{
		EXPECT_NEAR(gb->vectors()[i].start().x, ga->vectors()[i].start().x, 5e-4);
		EXPECT_NEAR(gb->vectors()[i].start().y, ga->vectors()[i].start().y, 5e-4);
	}
}

TEST(CGridVectorMap, InsertedVectorsAreInGlobalCoordinates)
{
	CGridVectorMap m;
	EXPECT_TRUE(m.isEmpty());
	const TPose2D p(1.0, -0.5, 0.7);
	EXPECT_TRUE(m.insertObservation(scanAt(p), mrpt::poses::CPose3D(mrpt::poses::CPose2D(p))));
	ASSERT_FALSE(m.isEmpty());
	for (const auto& v : m.vectors())
	{
		// Every vector lies on one of the room's walls (x = -3, x = 5, y = -2, y = 3).
		const auto c = v.centre();
		const double d = std::min({std::abs(c.x + 3), std::abs(c.x - 5), std::abs(c.y + 2), std::abs(c.y - 3)});
		EXPECT_LT(d, 0.02);
		EXPECT_EQ(v.scanIndex, 0);
	}
	EXPECT_EQ(m.insertedScans(), 1u);
	m.clear();
	EXPECT_TRUE(m.isEmpty());
	EXPECT_EQ(m.insertedScans(), 0u);
}

TEST(CGridVectorMap, IgnoresObservationsItCannotUse)
{
	CGridVectorMap m;
	mrpt::obs::CObservation2DRangeScan empty;
	m.insertObservation(empty);
	EXPECT_TRUE(m.isEmpty());
}

TEST(CGridVectorMap, SerializationRoundTrip)
{
	CGridVectorMap a = mapOfRoom();
	a.likelihoodOptions.sigma = 0.123;
	auto cfg = a.config();
	cfg.extraction.minLength = 0.33;
	a.setConfig(cfg);
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << a;
	buf.Seek(0);
	CGridVectorMap b;
	arch >> b;
	ASSERT_EQ(a.vectors().size(), b.vectors().size());
	EXPECT_EQ(a.insertedScans(), b.insertedScans());
	EXPECT_DOUBLE_EQ(b.likelihoodOptions.sigma, 0.123);
	EXPECT_DOUBLE_EQ(b.config().extraction.minLength, 0.33);
	for (size_t i = 0; i < a.vectors().size(); ++i)
	{
		const auto &va = a.vectors()[i], &vb = b.vectors()[i];
		// CompactMap's precision: endpoints to 0.5 mm, counts to half floats, gravity centres to 1/256 cell
		EXPECT_NEAR(va.start().x, vb.start().x, 5e-4);
		EXPECT_NEAR(va.start().y, vb.start().y, 5e-4);
		EXPECT_NEAR(va.end().x, vb.end().x, 5e-4);
		EXPECT_NEAR(va.end().y, vb.end().y, 5e-4);
		EXPECT_EQ(va.id, vb.id);
		EXPECT_EQ(va.scanIndex, vb.scanIndex);
		ASSERT_EQ(va.cells().size(), vb.cells().size());
		for (size_t k = 0; k < va.cells().size(); ++k)
		{
			EXPECT_NEAR(va.cells()[k].n_occupy, vb.cells()[k].n_occupy, 5e-4 * va.cells()[k].n_occupy);
			EXPECT_NEAR(va.cells()[k].n_visit, vb.cells()[k].n_visit, 5e-4 * va.cells()[k].n_visit);
			EXPECT_NEAR(va.cells()[k].x_acc, vb.cells()[k].x_acc,
						va.cells()[k].n_acc * va.resolution() / 200 + 1e-6);
		}
	}
	// Polymorphic read through MRPT's class registry.
	buf.Seek(0);
	auto obj = arch.ReadObject();
	ASSERT_TRUE(std::dynamic_pointer_cast<CGridVectorMap>(obj));
}

TEST(CGridVectorMap, CorruptStreamThrowsInsteadOfCrashing)
{
	CGridVectorMap a = mapOfRoom();
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << a;
	const size_t n = size_t(buf.getTotalBytesCount());
	mrpt::io::CMemoryStream cut;
	cut.Write(buf.getRawBufferData(), n / 2);
	cut.Seek(0);
	auto arch2 = mrpt::serialization::archiveFrom(cut);
	CGridVectorMap b;
	EXPECT_THROW(arch2 >> b, std::exception);
}

TEST(CGridVectorMap, LikelihoodPeaksAtTheTruePose)
{
	CGridVectorMap m = mapOfRoom();
	const TPose2D truth(0.7, 0.4, 1.1);
	const auto obs = scanAt(truth);
	const double atTruth = m.computeObservationLikelihood(obs, mrpt::poses::CPose3D(mrpt::poses::CPose2D(truth)));
	for (const TPose2D& off : {TPose2D(0.85, 0.4, 1.1), TPose2D(0.7, 0.25, 1.1), TPose2D(0.7, 0.4, 1.2)})
		EXPECT_GT(atTruth, m.computeObservationLikelihood(obs, mrpt::poses::CPose3D(mrpt::poses::CPose2D(off))));
	EXPECT_TRUE(m.canComputeObservationLikelihood(obs));
}

// The likelihood field (CGridVectorMap_likelihood.cpp) looks up each point's vectors through the
// spatial index; it must equal the field over every vector of the map, computed here directly.
TEST(CGridVectorMap, LikelihoodEqualsTheFieldOverEveryVector)
{
	CGridVectorMap m = mapOfRoom();
	const double prior = m.vectors().front().priorRatio();
	for (int decimation : {1, 2, 7})
	{
		m.likelihoodOptions.decimation = decimation;
		const auto& o = m.likelihoodOptions;
		for (const TPose2D& at : {TPose2D(0.7, 0.4, 1.1), TPose2D(-1.5, 1.0, -2.0), TPose2D(3.5, -1.0, 0.3)})
		{
			const auto obs = scanAt(at);
			for (const TPose2D& pose :
				 {at, TPose2D(at.x + 0.12, at.y - 0.05, at.phi + 0.03), TPose2D(at.x - 0.4, at.y, at.phi)})
			{
				double expected = 0;
				const size_t n = obs.getScanSize();
				for (size_t i = 0; i < n; i += size_t(decimation))
				{
					// every beam of the closed room is valid; rightToLeft, aperture pi
					const double a = pose.phi - M_PI / 2 + M_PI * double(i) / double(n - 1), r = obs.getScanRange(i);
					const mrpt::math::TPoint2D p(pose.x + r * std::cos(a), pose.y + r * std::sin(a));
					// MRPT's field: the best vector's Gaussian times its wall row's occupancy at the
					// foot, never below the Gaussian at maxCorrDistance
					double hit = std::exp(-o.maxCorrDistance * o.maxCorrDistance / (2 * o.sigma * o.sigma));
					for (const auto& v : m.vectors())
					{
						const auto g = v.toGridFrame(p);
						const double u = std::clamp(g.x, 0.0, v.length()), d = std::hypot(g.x - u, g.y);
						if (d >= o.maxCorrDistance) continue;
						const int col = std::min(v.cols() - 1, int(u / v.resolution()));
						hit = std::max(hit, v.cell(v.halfWidth(), col).occupancy(prior) *
												std::exp(-d * d / (2 * o.sigma * o.sigma)));
					}
					expected += std::log((1 - o.zRandom) * hit + o.zRandom);
				}
				EXPECT_NEAR(m.computeObservationLikelihood(obs, mrpt::poses::CPose3D(mrpt::poses::CPose2D(pose))),
							expected, 1e-6 * std::abs(expected))
					<< "decimation " << decimation << " pose " << pose.asString();
			}
		}
	}
}

TEST(CGridVectorMap, OccupancyGridIsEq6AtEveryCellCentre)
{
	const CGridVectorMap m = mapOfRoom();
	const auto g = m.getAsOccupancyGrid();
	ASSERT_NEAR(g.getResolution(), m.config().occupancy.resolution, 1e-6);
	size_t known = 0, occupied = 0;
	for (unsigned iy = 0; iy < g.getSizeY(); ++iy)
		for (unsigned ix = 0; ix < g.getSizeX(); ++ix)
		{
			// the cell centre in double precision, as the conversion samples it
			// (idx2x is float: 1e-7 off, the other side of a row boundary when
			// a wall lies exactly on the lattice, as the room's walls do)
			const double res = g.getResolution();
			const mrpt::math::TPoint2D c(g.getXMin() + (ix + 0.5) * res, g.getYMin() + (iy + 0.5) * res);
			const auto [o, v] = gridvector::OccupancyConversion::countsAt(m.vectors(), c);
			if (v <= 0)
			{
				EXPECT_EQ(g.getCell(ix, iy), 0.5f);
				continue;
			}
			++known;
			occupied += o / v > 0.5;
			EXPECT_NEAR(1.0 - g.getCell(ix, iy), o / v, 0.02);  // MRPT stores p(free) as 8-bit log-odds
		}
	EXPECT_GT(known, 100u);
	EXPECT_GT(occupied, 20u);
}

TEST(CGridVectorMap, TextRepresentationAndVisualisation)
{
	CGridVectorMap m = mapOfRoom();
	const std::string prefix = mrpt::system::getTempFileName();
	m.saveMetricMapRepresentationToFile(prefix);
	std::ifstream f(prefix + "_vectors.txt");
	ASSERT_TRUE(f.good());
	std::string line;
	size_t rows = 0;
	while (std::getline(f, line))
		if (!line.empty() && line[0] != '#') ++rows;
	EXPECT_EQ(rows, m.vectors().size());
	std::ifstream svg(prefix + "_vectors.svg");
	std::string svgText((std::istreambuf_iterator<char>(svg)), std::istreambuf_iterator<char>());
	EXPECT_NE(svgText.find("<svg"), std::string::npos);
	EXPECT_NE(svgText.find("<line"), std::string::npos);
	EXPECT_NE(m.asString().find("grid vectors"), std::string::npos);
	// Insertion alone runs no E-step: the summary says the vectors are unclassified, not "0 static, 0 dynamic".
	EXPECT_NE(m.asString().find("(0 static, 0 dynamic, " + std::to_string(m.vectors().size()) + " not classified"),
			  std::string::npos)
		<< m.asString();
	mrpt::maps::COccupancyGridMap2D png;
	EXPECT_TRUE(png.loadFromBitmapFile(prefix + "_occupancy.png", float(m.config().occupancy.resolution)));
	EXPECT_GT(png.getSizeX(), 10u);
	mrpt::opengl::CSetOfObjects o;
	m.getVisualizationInto(o);
	EXPECT_GT(o.size(), 0u);
}

TEST(CGridVectorMap, DefaultConstructedUsesTheDefaultsGvEmSlamRunsWith)
{
	// gv-em-slam, gv-map and gv-graphslam start from GridVectorConfig's defaults (one set of defaults,
	// doc/parameters.md): so does a map made in code or from an .ini without gridvector sections
	const auto defaults = gridvector::GridVectorConfig().namedValues();
	EXPECT_EQ(CGridVectorMap().config().namedValues(), defaults);
	EXPECT_EQ(multiMapFrom("[map]\ngridVectorMap_count = 1\n").mapByClass<CGridVectorMap>()->config().namedValues(),
			  defaults);
}
