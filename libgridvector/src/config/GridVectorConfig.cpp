#include <gridvector/GridVectorConfig.h>
#include "io/FileBytes.h"
#include "io/IniKeyLines.h"
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
	if constexpr (std::is_same_v<T, bool>)
		return value ? "true" : "false";
	else if constexpr (std::is_floating_point_v<T>)
		return io::shortestText(value);
	else
		return std::to_string(value);
}

template <class Group>
std::set<std::string> keysOf(Group& g)
{
	std::set<std::string> keys;
	g.visit([&](const char* key, auto&, const char*, const Range&) { keys.insert(key); });
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
		throw std::runtime_error(sourceName + ": unknown section [" + s + "] (the " + prefix + "_ sections are " +
								 list + ")");
	}
}

/** Longest .ini line: a key and a number are a few dozen bytes. */
constexpr size_t kMaxConfigLineBytes = size_t(64) << 10;
}  // namespace

void GridVectorConfig::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& prefix,
										  const std::string& sourceName, const std::vector<std::string>& otherSections)
{
	std::vector<std::string> known = otherSections;
	visitGroups([&](const char* group, auto&) { known.emplace_back(group); });
	requireKnownSections(cfg, prefix, known, sourceName);
	visitGroups([&](const char* group, auto& g) {
		const std::string section = prefix + "_" + group;
		if (!cfg.sectionExists(section)) return;
		io::requireKnownKeys(cfg, section, keysOf(g), sourceName);
		g.visit([&](const char* key, auto& field, const char*, const Range&) {
			io::readIniValue(cfg, section, key, field, sourceName);
		});
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
	// read here, not by CConfigFile: it sizes the file by seeking, which fails on pipes (--config <(...));
	// at most kMaxConfigBytes, in lines of at most 64 KiB (a config from /dev/zero stops at once)
	if (std::filesystem::is_directory(iniPath))
		throw std::runtime_error(iniPath + ": cannot read config file (it is a directory)");
	io::ReadLimits limits;
	limits.maxBytes = io::kMaxConfigBytes;
	limits.onHead = [](std::string_view) { return kMaxConfigLineBytes; };
	const std::vector<char> bytes = io::readFileBytes(iniPath, nullptr, limits);
	const std::string text(bytes.begin(), bytes.end());
	io::requireIniLayout(text, iniPath);
	io::requireKeyValueLines(text, iniPath);
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
		g.visit([&](const char* key, auto& field, const char* doc, const Range& range) {
			out << "; " << doc << " " << range.text() << "\n" << key << " = " << toText(field) << "\n";
		});
		out << "\n";
	});
}

std::string GridVectorConfig::parameterTableMarkdown(const std::string& prefix)
{
	GridVectorConfig defaults;
	std::ostringstream out;
	out << "| section | key | default | range | meaning |\n|---|---|---|---|---|\n";
	defaults.visitGroups([&](const char* group, auto& g) {
		g.visit([&](const char* key, auto& field, const char* doc, const Range& range) {
			out << "| `[" << prefix << "_" << group << "]` | `" << key << "` | " << toText(field) << " | "
				<< range.text() << " | " << doc << " |\n";
		});
	});
	return out.str();
}

namespace
{
template <class T>
bool assignNamed(T& field, double value, const std::string& name)
{
	if constexpr (std::is_same_v<T, double>)
		field = value;
	else if constexpr (std::is_same_v<T, bool>)
	{
		if (value != 0 && value != 1) throw std::invalid_argument(name + " is a bool, got " + toText(value));
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
		g.visit([&](const char* key, auto& field, const char*, const Range&) {
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
		g.visit([&](const char* k, auto& field, const char*, const Range&) {
			if (!found && key == k) found = assignNamed(field, value, name);
		});
	});
	return found;
}

namespace
{
template <class T>
std::string jsonValue(const T& field)
{
	if constexpr (std::is_same_v<T, bool>)
		return field ? "true" : "false";
	else if (std::isfinite(double(field)))
		return io::shortestText(double(field));
	else
		return "null";  // JSON has no inf/nan
}

std::string jsonString(const std::string& s)
{
	std::string out = "\"";
	for (char ch : s)
	{
		if (ch == '"' || ch == '\\') out += '\\';
		out += ch;
	}
	return out + "\"";
}

/** {"group": {"key": ENTRY(key, field, help, range), ...}, ...} */
template <class Entry>
std::string jsonOf(GridVectorConfig self, Entry&& entry)
{
	std::ostringstream out;
	out << "{";
	const char* groupSep = "";
	self.visitGroups([&](const char* group, auto& g) {
		out << groupSep << "\"" << group << "\": {";
		groupSep = ", ";
		const char* sep = "";
		g.visit([&](const char* key, auto& field, const char* doc, const Range& range) {
			out << sep << "\"" << key << "\": " << entry(field, doc, range);
			sep = ", ";
		});
		out << "}";
	});
	out << "}";
	return out.str();
}
}  // namespace

std::string GridVectorConfig::toJson() const
{
	return jsonOf(*this, [](const auto& field, const char*, const Range&) { return jsonValue(field); });
}

std::string GridVectorConfig::parametersJson() const
{
	return jsonOf(*this, [](const auto& field, const char* doc, const Range& range) {
		return "{\"value\": " + jsonValue(field) + ", \"range\": " + jsonString(range.text()) +
			   ", \"help\": " + jsonString(doc) + "}";
	});
}

std::string Range::text() const
{
	if (flag) return "true/false";
	return std::string(loOpen ? "(" : "[") + io::shortestText(lo) + ", " + io::shortestText(hi) + (hiOpen ? ")" : "]");
}

namespace
{
/** The finest grid-vector and occupancy cell [m]: a 2D scanner's range noise is about 1 cm. */
constexpr double kMinResolution = 0.01;
const char* const kFinest = "must be >= 0.01 (finer cells outgrow memory)";

/** "[<prefix>_<group>] key = 'value' must be ...". */
template <class T>
void require(const std::string& section, const char* key, T value, bool ok, const std::string& why)
{
	if (!ok) throw std::invalid_argument("[" + section + "] " + key + " = '" + toText(value) + "' " + why);
}

/** A minimum above its maximum: `key`'s value must not be below (or, strict, must be above) `loKey`'s. */
template <class T>
void notBelow(const std::string& section, const char* key, T value, const char* loKey, T lo, bool strict = false)
{
	require(section, key, value, strict ? value > lo : value >= lo,
			std::string(strict ? "must be > " : "must be >= ") + loKey + " (" + toText(lo) + ")");
}
template <class T>
void notAbove(const std::string& section, const char* key, T value, const char* hiKey, T hi)
{
	require(section, key, value, value <= hi, std::string("must be <= ") + hiKey + " (" + toText(hi) + ")");
}
}  // namespace

void GridVectorConfig::validate(const std::string& prefix) const
{
	// every key finite and in its visit() range
	const_cast<GridVectorConfig&>(*this).visitGroups([&](const char* group, auto& g) {
		const std::string section = prefix + "_" + group;
		g.visit([&](const char* key, auto& field, const char*, const Range& range) {
			using T = std::decay_t<decltype(field)>;
			if constexpr (std::is_floating_point_v<T>)
				require(section, key, field, std::isfinite(field), "must be finite");
			if constexpr (!std::is_same_v<T, bool>)
				require(section, key, field, range.contains(double(field)), "must be in " + range.text());
		});
	});
	// a minimum above its maximum
	const std::string g = prefix + "_grid", m = prefix + "_matcher", d = prefix + "_doors";
	notAbove(g, "prior_occupy", grid.priorOccupy, "prior_visit", grid.priorVisit);
	notAbove(m, "gate_psi_final_deg", matcher.gatePsiFinalDeg, "gate_psi_initial_deg", matcher.gatePsiInitialDeg);
	notAbove(m, "gate_rho_final", matcher.gateRhoFinal, "gate_rho_initial", matcher.gateRhoInitial);
	notBelow(d, "max_door_length", doors.maxDoorLength, "min_door_length", doors.minDoorLength);
	// the finest cells: below them a map's grids and cell indices outgrow memory (1e-6: 3.5 GB on 11 scans)
	require(g, "resolution", grid.resolution, grid.resolution >= kMinResolution, kFinest);
	require(prefix + "_occupancy", "resolution", occupancy.resolution, occupancy.resolution >= kMinResolution, kFinest);
}

}  // namespace gridvector
