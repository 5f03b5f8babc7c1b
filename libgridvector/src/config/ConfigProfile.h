// gridvector: named parameter profiles — the library defaults and the defaults an app embeds
// (gv-em-slam's EmSlam::defaultConfig()), with the reason for every key where they differ.
#pragma once

#include <gridvector/GridVectorConfig.h>

#include <map>
#include <string>
#include <vector>

namespace gridvector
{
struct ConfigProfile
{
	std::string name;  //!< "library", "em-slam"
	std::string description;
	GridVectorConfig config;
	std::map<std::string, std::string> reasons;  //!< "group.key" -> why this profile differs from the library default
};

/** One key where a profile differs from the library defaults. */
struct ProfileDifference
{
	std::string key;  //!< "group.key"
	double library = 0, profile = 0;
	std::string reason;
};

/** Every profile, "library" first. */
const std::vector<ConfigProfile>& configProfiles();
/** Throws std::invalid_argument naming the known profiles if there is no such profile. */
const ConfigProfile& configProfile(const std::string& name);
/** The keys where p differs from GridVectorConfig{}; throws std::logic_error if one has no reason
 * (an undocumented override is a bug), or if a reason names a key that does not differ. */
std::vector<ProfileDifference> profileDifferences(const ConfigProfile& p);
/** Markdown table: `[section] key`, library default, this profile, why (doc/parameters.md). */
std::string profileTableMarkdown(const ConfigProfile& p, const std::string& prefix = "gridvector");

}  // namespace gridvector
