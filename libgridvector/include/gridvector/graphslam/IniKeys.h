// Reading decider options from graphslam-engine .ini sections, key lists walked once.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <ostream>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace gridvector::graphslam
{
namespace detail
{
inline void readKey(const mrpt::config::CConfigFileBase& c, const std::string& s, const char* k, double& f)
{
	f = c.read_double(s, k, f);
}
inline void readKey(const mrpt::config::CConfigFileBase& c, const std::string& s, const char* k, int& f)
{
	f = c.read_int(s, k, f);
}
inline void readKey(const mrpt::config::CConfigFileBase& c, const std::string& s, const char* k, bool& f)
{
	f = c.read_bool(s, k, f);
}
inline void printValue(std::ostream& o, bool v) { o << (v ? "true" : "false"); }
template <class T>
void printValue(std::ostream& o, const T& v)
{
	o << v;
}
}  // namespace detail

/** Reads every key a visitor lists from `section` (missing keys keep their
 * defaults). With `strict`, a key present in the section but not listed is an
 * error "source: unknown key 'k' in section [s]" (a typo must not fall back
 * silently to a default). Sections shared with MRPT's own deciders are read
 * non-strict: they legitimately hold keys meant for other deciders. */
template <class Visit>
void readSection(const mrpt::config::CConfigFileBase& cfg, const std::string& section, bool strict,
				 const std::string& source, Visit&& visit)
{
	if (strict && cfg.sectionExists(section))
	{
		std::set<std::string> known;
		visit([&](const char* key, auto&, const char*) { known.insert(key); });
		std::vector<std::string> present;
		cfg.getAllKeys(section, present);
		for (const auto& k : present)
			if (!known.count(k))
				throw std::runtime_error(source + ": unknown key '" + k + "' in section [" + section + "]");
	}
	visit([&](const char* key, auto& field, const char*) { detail::readKey(cfg, section, key, field); });
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

/** Throws "source: [section] what" unless ok. */
inline void require(bool ok, const std::string& source, const std::string& section, const std::string& what)
{
	if (!ok) throw std::runtime_error(source + ": [" + section + "] " + what);
}

}  // namespace gridvector::graphslam
