// The [gridvector_*] parameter groups as read by the graphslam-engine deciders.
#pragma once

#include <gridvector/GridVectorConfig.h>

#include <mrpt/config/CConfigFileBase.h>

#include <string>

namespace gridvector::graphslam
{
/** Loads every [gridvector_<group>] section of an engine .ini; any problem
 * (unknown key, value out of range) throws std::runtime_error("SOURCE: ..."). */
GridVectorConfig loadRegistrationConfig(const mrpt::config::CConfigFileBase& cfg, const std::string& sourceName);

/** Throws std::runtime_error("PATH: cannot open config file") if PATH does not exist. */
void requireConfigFile(const std::string& path);
}  // namespace gridvector::graphslam
