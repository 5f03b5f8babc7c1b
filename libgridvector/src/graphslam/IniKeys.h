// Reading decider options from graphslam-engine .ini sections, key lists walked once.
#pragma once

#include "io/IniValue.h"

#include <mrpt/config/CConfigFileBase.h>

#include <algorithm>
#include <cctype>
#include <ostream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace gridvector::graphslam
{
namespace detail
{
/** The text of a decider key as MRPT writes its graphslam .ini files: a value may end in
 * ';' ("1.5;") or be followed by "// comment" (CConfigFile::readString cuts " //" and its
 * read_double / read_int stop at the first non-digit); " ; comment" / " # comment" as elsewhere. */
inline std::string valueText(const mrpt::config::CConfigFileBase& c, const std::string& s, const char* k)
{
	std::string v = io::iniValueText(c, s, k);
	v = v.substr(0, std::min(v.find(';'), v.find("//")));
	while (!v.empty() && std::isspace(static_cast<unsigned char>(v.back()))) v.pop_back();
	return v;
}
/** Reads a present key strictly (io/IniValue.h): "0.o5" is an error, not 0. */
template <class T>
void readKey(const mrpt::config::CConfigFileBase& c, const std::string& s, const char* k, T& f,
			 const std::string& source)
{
	if (c.keyExists(s, k)) io::readIniText(valueText(c, s, k), s, k, f, source);
}
inline void printValue(std::ostream& o, bool v) { o << (v ? "true" : "false"); }
template <class T>
void printValue(std::ostream& o, const T& v)
{
	o << v;
}
}  // namespace detail

/** Reads every key a visitor lists from `section` (missing keys keep their
 * defaults; a value that is not its key's type is an error "source: [s] k = 'text' is not ..."). With `strict`, a key
 * present in the section but not listed is an error "source: unknown key 'k' in section [s]" (a typo must not fall back
 * silently to a default). Sections shared with MRPT's own deciders are read
 * non-strict: they legitimately hold keys meant for other deciders. */
template <class Visit>
void readSection(const mrpt::config::CConfigFileBase& cfg, const std::string& section, bool strict,
				 const std::string& source, Visit&& visit)
{
	if (strict)
	{
		std::set<std::string> known;
		visit([&](const char* key, auto&, const char*) { known.insert(key); });
		io::requireKnownKeys(cfg, section, known, source);
	}
	visit([&](const char* key, auto& field, const char*) { detail::readKey(cfg, section, key, field, source); });
}

/** "key = value ; doc" lines of a section, as an .ini fragment. */
template <class Visit>
void dumpSection(std::ostream& out, const std::string& section, Visit&& visit)
{
	out << "[" << section << "]\n";
	visit([&](const char* key, auto& field, const char* doc) {
		out << key << " = ";
		detail::printValue(out, field);
		out << "  ; " << doc << "\n";
	});
}

/** Markdown table rows "| [section] | key | default | meaning |". */
template <class Visit>
void markdownRows(std::ostream& out, const std::string& section, Visit&& visit)
{
	visit([&](const char* key, auto& field, const char* doc) {
		out << "| `[" << section << "]` | `" << key << "` | ";
		detail::printValue(out, field);
		out << " | " << doc << " |\n";
	});
}

/** Throws "source: [section] key = 'value' why" unless ok. */
template <class T>
void require(bool ok, const std::string& source, const std::string& section, const char* key, const T& value,
			 const std::string& why)
{
	if (ok) return;
	std::ostringstream v;
	detail::printValue(v, value);
	throw std::runtime_error(source + ": [" + section + "] " + key + " = '" + v.str() + "' " + why);
}

}  // namespace gridvector::graphslam
