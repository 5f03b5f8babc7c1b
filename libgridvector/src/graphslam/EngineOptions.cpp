#include "graphslam/EngineOptions.h"
#include "graphslam/IniKeys.h"

namespace gridvector::graphslam
{
void EngineOptions::load(const mrpt::config::CConfigFileBase& cfg, const std::string& source)
{
	readSection(cfg, section, false, source, [&](auto&& v) { visit(v); });
	require(classVerbosity >= 0 && classVerbosity <= 3, source, section, "class_verbosity", classVerbosity,
			"must be in 0..3");
	require(lcMinNodeIdDiff >= 1, source, section, "LC_min_nodeid_diff", lcMinNodeIdDiff, "must be >= 1");
	outputDir = cfg.read_string(section, "output_dir_fname", outputDir);
	graphName = cfg.read_string(section, "save_graph_fname", graphName);
	mapName = cfg.read_string(section, "save_map_fname", mapName);
}

}  // namespace gridvector::graphslam
