// [GeneralConfiguration] of graphslam-engine .ini files: gv-graphslam's output keys and MRPT's
// engine keys, read strictly before the engine reads them with read_bool / read_int.
#include "graphslam/EngineOptions.h"

#include <gtest/gtest.h>
#include <mrpt/config/CConfigFile.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <stdexcept>

#include "graphslam_ini_files.h"

using gridvector::graphslam::EngineOptions;

namespace
{
std::string loadError(const std::string& text)
{
	try
	{
		EngineOptions().load(mrpt::config::CConfigFileMemory(text), "a.ini");
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(EngineOptions, EveryGraphslamIniMrptAndWeShipLoadsWithMrptsValues)
{
	const auto files = gvtest::graphslamIniFiles();
	ASSERT_GE(files.size(), 7u) << "MRPT's graphslam-engine .ini files not found in " << gvtest::mrptGraphslamIniDir;
	for (const auto& path : files)
	{
		const mrpt::config::CConfigFile c(path);
		EngineOptions o;
		const EngineOptions d;
		ASSERT_NO_THROW(o.load(c, path)) << path;
		const char* s = EngineOptions::section;
		EXPECT_EQ(o.outputDir, c.read_string(s, "output_dir_fname", d.outputDir)) << path;
		EXPECT_EQ(o.saveGraph, c.read_bool(s, "save_graph", d.saveGraph)) << path;
		EXPECT_EQ(o.graphName, c.read_string(s, "save_graph_fname", d.graphName)) << path;
		EXPECT_EQ(o.saveMap, c.read_bool(s, "save_map", d.saveMap)) << path;
		EXPECT_EQ(o.mapName, c.read_string(s, "save_map_fname", d.mapName)) << path;
		EXPECT_EQ(o.userDecidesAboutOutputDir,
				  c.read_bool(s, "user_decides_about_output_dir", d.userDecidesAboutOutputDir))
			<< path;
		EXPECT_EQ(o.classVerbosity, c.read_int(s, "class_verbosity", d.classVerbosity)) << path;
		EXPECT_EQ(o.lcMinNodeIdDiff, c.read_int(s, "LC_min_nodeid_diff", d.lcMinNodeIdDiff)) << path;
	}
}

TEST(EngineOptions, ValuesMrptWouldMisreadAreRefused)
{
	// MRPT's read_bool gives false for "ture", read_int 3 for "3O" and 1 for "1.5"
	EXPECT_EQ(loadError("[GeneralConfiguration]\nsave_graph = ture\n"),
			  "a.ini: [GeneralConfiguration] save_graph = 'ture' is not true or false");
	EXPECT_EQ(loadError("[GeneralConfiguration]\nsave_map = of\n"),
			  "a.ini: [GeneralConfiguration] save_map = 'of' is not true or false");
	EXPECT_EQ(loadError("[GeneralConfiguration]\nLC_min_nodeid_diff = 3O\n"),
			  "a.ini: [GeneralConfiguration] LC_min_nodeid_diff = '3O' is not an integer");
	EXPECT_EQ(loadError("[GeneralConfiguration]\nclass_verbosity = 1.5\n"),
			  "a.ini: [GeneralConfiguration] class_verbosity = '1.5' is not an integer");
	EXPECT_EQ(loadError("[GeneralConfiguration]\nuser_decides_about_output_dir = maybe\n"),
			  "a.ini: [GeneralConfiguration] user_decides_about_output_dir = 'maybe' is not true or false");
	// out of range: MRPT's engine would run with them (a negative loop-closure distance makes every edge one)
	EXPECT_EQ(loadError("[GeneralConfiguration]\nLC_min_nodeid_diff = -5\n"),
			  "a.ini: [GeneralConfiguration] LC_min_nodeid_diff = '-5' must be >= 1");
	EXPECT_EQ(loadError("[GeneralConfiguration]\nclass_verbosity = 9\n"),
			  "a.ini: [GeneralConfiguration] class_verbosity = '9' must be in 0..3");
	// MRPT's keys this does not read stay MRPT's (the section is shared)
	EXPECT_EQ(
		loadError("[GeneralConfiguration]\nsave_3DScene_fname = x.3DScene\nground_truth_file_format = rgbd_TUM\n"), "");
}

TEST(EngineOptions, ValuesEndAsInMrptsGraphslamFiles)
{
	EngineOptions o;
	o.load(mrpt::config::CConfigFileMemory("[GeneralConfiguration]\nsave_graph = false // no graph\nsave_map = 0;\n"
										   "LC_min_nodeid_diff= 50\nclass_verbosity = 2 ; warn\n"
										   "output_dir_fname = out/gs\nsave_map_fname = grid\n"),
		   "a.ini");
	EXPECT_FALSE(o.saveGraph);
	EXPECT_FALSE(o.saveMap);
	EXPECT_EQ(o.lcMinNodeIdDiff, 50);
	EXPECT_EQ(o.classVerbosity, 2);
	EXPECT_EQ(o.outputDir, "out/gs");
	EXPECT_EQ(o.mapName, "grid");
	EXPECT_EQ(o.graphName, "output_graph.graph");  // absent: the default MRPT's app uses
	EXPECT_TRUE(o.userDecidesAboutOutputDir == false);
}
