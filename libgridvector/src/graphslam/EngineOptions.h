// [GeneralConfiguration] of a graphslam-engine .ini: the keys gv-graphslam reads for its
// outputs (as MRPT's app does), and MRPT's engine keys checked before the engine reads them.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <string>

namespace gridvector::graphslam
{
/** MRPT's engine, deciders and optimizer read this section with read_bool / read_int, which take
 * "ture" as false and "3O" as 3, inside code the project cannot intercept (CGraphSlamEngine's
 * constructor, CICPCriteriaERD, CLevMarqGSO). load() reads the same keys strictly first
 * (io/IniValue.h through IniKeys.h: "FILE: [GeneralConfiguration] save_graph = 'ture' is not
 * true or false"), so a value the engine would misread never reaches it; valid values read the
 * same. Other keys of the section are MRPT's and left to it (the section is shared: not strict). */
struct EngineOptions
{
	static constexpr const char* section = "GeneralConfiguration";

	// read by gv-graphslam for its outputs (MRPT's graphslam-engine app reads them as well)
	std::string outputDir = "graphslam_results";  //!< output_dir_fname (a text: read as MRPT reads it)
	bool saveGraph = true;
	std::string graphName = "output_graph.graph";  //!< save_graph_fname
	bool saveMap = true;
	std::string mapName = "output_map";  //!< save_map_fname
	// read by MRPT's engine (constructor), edge deciders and CLevMarqGSO: checked only
	bool userDecidesAboutOutputDir = false;
	int classVerbosity = 1;
	int lcMinNodeIdDiff = 30;

	template <class V>
	void visit(V&& v)
	{
		v("save_graph", saveGraph, "Write the engine's graph (save_graph_fname) into the output directory");
		v("save_map", saveMap, "Write the engine's occupancy grid (save_map_fname)");
		v("user_decides_about_output_dir", userDecidesAboutOutputDir,
		  "MRPT's engine: ask before reusing the output directory");
		v("class_verbosity", classVerbosity, "MRPT's engine: logger level, 0 debug .. 3 error");
		v("LC_min_nodeid_diff", lcMinNodeIdDiff,
		  "MRPT's edge deciders and CLevMarqGSO: an edge between nodes whose IDs differ by more than this is a loop "
		  "closure");
	}

	/** Reads the section; throws std::runtime_error "source: [GeneralConfiguration] key = 'text' is
	 * not ..." for a value that is not its key's type. */
	void load(const mrpt::config::CConfigFileBase& source, const std::string& sourceName);
};

}  // namespace gridvector::graphslam
