#include "mrpt/MrptOptionSections.h"
#include "io/IniValue.h"

#include <set>
#include <stdexcept>
#include <vector>

namespace gridvector
{
namespace
{
/** MRPT's TMapGenericParams keys, which MRPT reads from [<prefix>_creationOpts] itself. */
const std::set<std::string> mrptGenericKeys = {"enableSaveAs3DObject", "enableObservationLikelihood",
											   "enableObservationInsertion"};

/** One MRPT section holding the keys of several groups: `groups` names them (as visitGroups does). */
void readSection(const mrpt::config::CConfigFileBase& source, const std::string& prefix, const std::string& name,
				 const std::set<std::string>& groups, std::set<std::string> known, GridVectorConfig& config,
				 const std::string& from)
{
	const std::string section = prefix + "_" + name;
	if (!source.sectionExists(section)) return;
	config.visitGroups([&](const char* group, auto& g) {
		if (groups.count(group)) g.visit([&](const char* key, auto&, const char*, const Range&) { known.insert(key); });
	});
	io::requireKnownKeys(source, section, known, from);
	config.visitGroups([&](const char* group, auto& g) {
		if (!groups.count(group)) return;
		const std::string grouped = prefix + "_" + group;
		g.visit([&](const char* key, auto& field, const char*, const Range& range) {
			if (!source.keyExists(section, key)) return;
			if (source.keyExists(grouped, key))
				throw std::runtime_error(from + ": [" + section + "] " + key + " is also set in [" + grouped +
										 "]: set it in one of them");
			io::readIniValue(source, section, key, field, from);
			if (!range.flag && !range.contains(double(field)))  // here, to name the section it was read from
				throw std::runtime_error(from + ": [" + section + "] " + key + " = '" +
										 io::iniValueText(source, section, key) + "' must be in " + range.text());
		});
	});
}
}  // namespace

void readMrptOptionSections(const mrpt::config::CConfigFileBase& source, const std::string& prefix,
							GridVectorConfig& config, const std::string& from)
{
	readSection(source, prefix, "creationOpts", {"grid"}, mrptGenericKeys, config, from);
	readSection(source, prefix, "insertOpts", {"extraction", "map"}, {}, config, from);
	try
	{
		config.validate(prefix);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(from + ": " + e.what());
	}
}
}  // namespace gridvector
