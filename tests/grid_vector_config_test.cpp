#include <gridvector/GridVectorConfig.h>
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cstdio>
#include <fstream>
#include <sstream>

using gridvector::GridVectorConfig;

TEST(GridVectorConfig, DefaultsAreThePapers)
{
	GridVectorConfig c;
	EXPECT_DOUBLE_EQ(c.grid.priorOccupy, 0.5);  // Sec. 3.1: prior 1/2 over 1
	EXPECT_DOUBLE_EQ(c.grid.priorVisit, 1.0);
	EXPECT_DOUBLE_EQ(c.grid.resolution, 0.1);  // Table 1 compares with a 10 cm grid
	EXPECT_NO_THROW(c.validate());
}

TEST(GridVectorConfig, LoadsKeysFromIniSections)
{
	mrpt::config::CConfigFileMemory ini(
		"[gridvector_extraction]\nsplit_threshold = 0.07\nmin_points = 9\n"
		"[gridvector_grid]\nhalf_width = 3\n[gridvector_map]\nmerge_on_insert = false\n");
	GridVectorConfig c;
	c.loadFromConfigFile(ini);
	EXPECT_DOUBLE_EQ(c.extraction.splitThreshold, 0.07);
	EXPECT_EQ(c.extraction.minPoints, 9);
	EXPECT_EQ(c.grid.halfWidth, 3);
	EXPECT_FALSE(c.map.mergeOnInsert);
	EXPECT_DOUBLE_EQ(c.grid.resolution, 0.1);  // untouched keys keep defaults
}

TEST(GridVectorConfig, UnknownKeyIsAnErrorNamingFileSectionAndKey)
{
	mrpt::config::CConfigFileMemory ini("[gridvector_grid]\nresolutoin = 0.05\n");
	GridVectorConfig c;
	try
	{
		c.loadFromConfigFile(ini, "gridvector", "my.ini");
		FAIL() << "no exception";
	}
	catch (const std::runtime_error& e)
	{
		const std::string msg = e.what();
		EXPECT_NE(msg.find("my.ini"), std::string::npos);
		EXPECT_NE(msg.find("resolutoin"), std::string::npos);
		EXPECT_NE(msg.find("[gridvector_grid]"), std::string::npos);
	}
}

TEST(GridVectorConfig, OutOfRangeValueIsRejected)
{
	mrpt::config::CConfigFileMemory ini("[gridvector_grid]\nresolution = -1\n");
	GridVectorConfig c;
	EXPECT_THROW(c.loadFromConfigFile(ini), std::invalid_argument);
}

TEST(GridVectorConfig, DumpRoundTripsThroughIni)
{
	GridVectorConfig a;
	a.extraction.minLength = 0.42;
	a.grid.halfWidth = 2;
	a.map.mergeOnInsert = false;
	std::ostringstream os;
	a.dumpAsIni(os);
	mrpt::config::CConfigFileMemory ini(os.str());
	GridVectorConfig b;
	b.loadFromConfigFile(ini);
	EXPECT_DOUBLE_EQ(b.extraction.minLength, 0.42);
	EXPECT_EQ(b.grid.halfWidth, 2);
	EXPECT_FALSE(b.map.mergeOnInsert);
}

TEST(GridVectorConfig, MissingFileIsAClearError)
{
	GridVectorConfig c;
	try
	{
		c.loadFromFile("/nonexistent/dir/x.ini");
		FAIL();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/x.ini"), std::string::npos);
	}
}

TEST(GridVectorConfig, ParameterTableListsEveryKey)
{
	const std::string md = GridVectorConfig::parameterTableMarkdown();
	GridVectorConfig c;
	c.visitGroups([&](const char*, auto& g) {
		g.visit([&](const char* key, auto&, const char*) {
			EXPECT_NE(md.find(std::string("`") + key + "`"), std::string::npos) << key;
		});
	});
}
