// Strict reading of .ini values: MRPT's read_double / read_int / read_bool take "abc" and "0.o5"
// as 0, "2.5" as 2 and "ture" as false; these say which file, section, key and text were wrong.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <cstdint>
#include <set>
#include <string>

namespace gridvector::io
{
/** ASCII lower case (MRPT matches section names case-insensitively). */
std::string lowerCase(std::string s);

/** The text of `key` in `section`, without a trailing " ; comment" or " # comment" and
 * without trailing blanks. */
std::string iniValueText(const mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key);

/** The whole text as the type, else false: a finite number; a decimal integer in int's range;
 * true/yes/1 or false/no/0 in any case. */
bool parseIniValue(const std::string& text, double& value);
bool parseIniValue(const std::string& text, int& value);
bool parseIniValue(const std::string& text, bool& value);
bool parseIniValue(const std::string& text, int64_t& value);  //!< a decimal integer in int64_t's range

/** What parseIniValue accepts for T, for messages: "a finite number", "an integer", "true or false". */
template <class T>
const char* iniKindOf();
template <>
const char* iniKindOf<double>();
template <>
const char* iniKindOf<int>();
template <>
const char* iniKindOf<bool>();

/** A check of a parsed value (a range); a nested type so that a lambda converts to it. */
template <class T>
struct IniCheck
{
	using Fn = bool (*)(T);
};

/** Parses `text`, the value of [section] key in `sourceName`, into `field` as readIniValue
 * does (same error, `field` left alone then). For readers that take the text another way. */
template <class T>
void readIniText(const std::string& text, const std::string& section, const std::string& key, T& field,
				 const std::string& sourceName, const std::string& what = {}, typename IniCheck<T>::Fn valid = nullptr);

/** If `key` is in `section`, reads it into `field` strictly. Throws std::runtime_error
 * "<sourceName>: [section] key = 'text' is not <what>" when the text is not a T or `valid`
 * (when given) refuses the value; `what` defaults to iniKindOf<T>(). `field` is left alone then. */
template <class T>
void readIniValue(const mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key, T& field,
				  const std::string& sourceName, const std::string& what = {},
				  typename IniCheck<T>::Fn valid = nullptr);

/** Throws std::runtime_error "<sourceName>: unknown key 'k' in section [section]" for a key of
 * `section` that is not in `known` (a misspelt key would otherwise keep its default silently). */
void requireKnownKeys(const mrpt::config::CConfigFileBase& c, const std::string& section,
					  const std::set<std::string>& known, const std::string& sourceName);
}  // namespace gridvector::io
