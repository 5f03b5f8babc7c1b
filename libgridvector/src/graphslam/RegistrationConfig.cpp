#include "graphslam/RegistrationConfig.h"

#include <mrpt/system/filesystem.h>

#include <stdexcept>

namespace gridvector::graphslam
{
GridVectorConfig loadRegistrationConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& sourceName)
{
	GridVectorConfig out;
	try
	{
		out.loadFromConfigFile(cfg, "gridvector", sourceName);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(e.what());  // names the source
	}
	return out;
}

void requireConfigFile(const std::string& path)
{
	if (!mrpt::system::fileExists(path)) throw std::runtime_error(path + ": cannot open config file");
}
}  // namespace gridvector::graphslam
