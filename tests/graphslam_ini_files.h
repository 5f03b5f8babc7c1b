// The graphslam-engine .ini files the option readers must load as MRPT does: ours and MRPT's.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace gvtest
{
inline const char* mrptGraphslamIniDir = "/usr/share/mrpt/config_files/graphslam-engine";

/** share/gridvector/graphslam-gridvector.ini, then every .ini in MRPT's graphslam-engine config folder. */
inline std::vector<std::string> graphslamIniFiles()
{
	std::vector<std::string> files = {std::string(GV_SOURCE_DIR) + "/share/gridvector/graphslam-gridvector.ini"};
	if (std::filesystem::is_directory(mrptGraphslamIniDir))
		for (const auto& f : std::filesystem::directory_iterator(mrptGraphslamIniDir))
			if (f.path().extension() == ".ini") files.push_back(f.path().string());
	return files;
}
}  // namespace gvtest
