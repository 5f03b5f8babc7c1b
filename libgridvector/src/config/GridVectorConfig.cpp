#include <gridvector/GridVectorConfig.h>
#include "io/IniLayout.h"
#include "io/IniValue.h"
#include "io/TextParsing.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace gridvector
{
namespace
{
template <class T>
std::string toText(const T& value)
{
	std::ostringstream os;
	if constexpr (std::is_same_v<T, bool>) os << (value ? "true" : "false");
	else os << value;
	return os.str();
}

template <class Group>
std::set<std::string> keysOf(Group& g)
{
	std::set<std::string> keys;
	g.visit([&](const char* key, auto&, const char*) { keys.insert(key); });
	return keys;
}

/** Every section named `<prefix>_<something>` must be one of ours: a typo in a section name
 * ([gridvector_gird]) would otherwise drop all its keys silently. MRPT matches section names
 * case-insensitively, so this does too. */
void requireKnownSections(const mrpt::config::CConfigFileBase& cfg, const std::string& prefix,
						  const std::vector<std::string>& known, const std::string& sourceName)
{
	const std::string head = io::lowerCase(prefix + "_");
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	for (const auto& s : sections)
	{
		const std::string l = io::lowerCase(s);
		if (l.size() <= head.size() || l.compare(0, head.size(), head) != 0) continue;
		bool ok = false;
		for (const auto& k : known) ok = ok || l.substr(head.size()) == io::lowerCase(k);
		if (ok) continue;
		std::string list;
		for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
		throw std::runtime_error(sourceName + ": unknown section [" + s + "] (the " + prefix + "_ sections are " + list + ")");
	}
}

}  // namespace

void GridVectorConfig::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& cfg, const std::string& prefix,
	const std::string& sourceName, const std::vector<std::string>& otherSections)
{
	std::vector<std::string> known = otherSections;
	visitGroups([&](const char* group, auto&) { known.emplace_back(group); });
	requireKnownSections(cfg, prefix, known, sourceName);
	visitGroups([&](const char* group, auto& g) {
		const std::string section = prefix + "_" + group;
		if (!cfg.sectionExists(section)) return;
		io::requireKnownKeys(cfg, section, keysOf(g), sourceName);
		g.visit([&](const char* key, auto& field, const char*) { io::readIniValue(cfg, section, key, field, sourceName); });
	});
	try
	{
		validate(prefix);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument(sourceName + ": " + e.what());  // "FILE: [section] key = 'value' must be ..."
	}
}

void GridVectorConfig::loadFromFile(const std::string& iniPath, const std::string& prefix)
{
	// read here, not by CConfigFile: it sizes the file by seeking, which fails on pipes (--config <(...))
	if (std::filesystem::is_directory(iniPath)) throw std::runtime_error(iniPath + ": cannot read config file (it is a directory)");
	std::ifstream in(iniPath, std::ios::binary);
	if (!in) throw std::runtime_error(iniPath + ": cannot open config file");
	const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	if (in.bad()) throw std::runtime_error(iniPath + ": cannot read config file (read error)");
	io::requireIniLayout(text, iniPath);
	mrpt::config::CConfigFileMemory cfg(text);
	try
	{
		loadFromConfigFile(cfg, prefix, iniPath);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(e.what());  // already names the file
	}
}

void GridVectorConfig::dumpAsIni(std::ostream& out, const std::string& prefix) const
{
	auto& self = const_cast<GridVectorConfig&>(*this);
	self.visitGroups([&](const char* group, auto& g) {
		out << "[" << prefix << "_" << group << "]\n";
		g.visit([&](const char* key, auto& field, const char* doc) {
			out << "; " << doc << "\n" << key << " = " << toText(field) << "\n";
		});
		out << "\n";
	});
}

std::string GridVectorConfig::parameterTableMarkdown(const std::string& prefix)
{
	GridVectorConfig defaults;
	std::ostringstream out;
	out << "| section | key | default | meaning |\n|---|---|---|---|\n";
	defaults.visitGroups([&](const char* group, auto& g) {
		g.visit([&](const char* key, auto& field, const char* doc) {
			out << "| `[" << prefix << "_" << group << "]` | `" << key << "` | "
				<< toText(field) << " | " << doc << " |\n";
		});
	});
	return out.str();
}

namespace
{
template <class T>
bool assignNamed(T& field, double value, const std::string& name)
{
	if constexpr (std::is_same_v<T, double>) field = value;
	else if constexpr (std::is_same_v<T, bool>)
	{
		if (value != 0 && value != 1)
			throw std::invalid_argument(name + " is a bool, got " + toText(value));
		field = value != 0;
	}
	else
	{
		if (!(value == std::floor(value) && std::abs(value) <= 2147483647.0))
			throw std::invalid_argument(name + " is an integer, got " + toText(value));
		field = T(value);
	}
	return true;
}
}  // namespace

std::vector<std::pair<std::string, double>> GridVectorConfig::namedValues() const
{
	std::vector<std::pair<std::string, double>> out;
	auto self = *this;
	self.visitGroups([&](const char* group, auto& g) {
		g.visit([&](const char* key, auto& field, const char*) {
			out.emplace_back(std::string(group) + "." + key, double(field));
		});
	});
	return out;
}

bool GridVectorConfig::setNamedValue(const std::string& name, double value)
{
	bool found = false;
	visitGroups([&](const char* group, auto& g) {
		if (found || name.compare(0, std::strlen(group), group) != 0 || name.size() <= std::strlen(group) ||
			name[std::strlen(group)] != '.')
			return;
		const std::string key = name.substr(std::strlen(group) + 1);
		g.visit([&](const char* k, auto& field, const char*) {
			if (!found && key == k) found = assignNamed(field, value, name);
		});
	});
	return found;
}

std::string GridVectorConfig::toJson() const
{
	std::ostringstream out;
	out << "{";
	auto self = *this;
	const char* groupSep = "";
	self.visitGroups([&](const char* group, auto& g) {
		out << groupSep << "\"" << group << "\": {";
		groupSep = ", ";
		const char* sep = "";
		g.visit([&](const char* key, auto& field, const char*) {
			out << sep << "\"" << key << "\": ";
			if constexpr (std::is_same_v<std::decay_t<decltype(field)>, bool>) out << (field ? "true" : "false");
			else if (std::isfinite(double(field))) out << io::shortestText(double(field));
			else out << "null";  // JSON has no inf/nan
			sep = ", ";
		});
		out << "}";
	});
	out << "}";
	return out.str();
}

}  // namespace gridvector
