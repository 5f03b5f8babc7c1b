#include <gridvector/Version.h>

#include <mrpt/version.h>

#include "gridvector_git_describe.h"  // GV_GIT_DESCRIBE, written by cmake/GitDescribe.cmake at build time

namespace gridvector
{
std::string version() { return GV_PROJECT_VERSION; }

std::string gitDescription()
{
	const std::string d = GV_GIT_DESCRIBE;
	return d.empty() ? "unknown" : d;
}

std::string mrptVersion()
{
	const std::string s = MRPT_version_str;  // "MRPT 2.5.8"
	const auto space = s.find(' ');
	return space == std::string::npos ? s : s.substr(space + 1);
}

std::string versionLine(const std::string& program)
{
	return program + " (gridvector " + version() + ", git " + gitDescription() + ", MRPT " + mrptVersion() + ")";
}
}  // namespace gridvector
