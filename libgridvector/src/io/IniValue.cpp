// Strict .ini values (IniValue.h): one parser for GridVectorConfig and CGridVectorMap's options.
#include "io/IniValue.h"

#include <cctype>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <vector>

namespace gridvector::io
{
std::string lowerCase(std::string s)
{
	for (char& ch : s) ch = char(std::tolower(static_cast<unsigned char>(ch)));
	return s;
}

std::string iniValueText(const mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key)
{
	std::string v = c.read_string(section, key, "");
	for (const char* mark : {";", "#"})
		for (size_t p = v.find(mark); p != std::string::npos; p = v.find(mark, p + 1))
			if (p > 0 && std::isspace(static_cast<unsigned char>(v[p - 1]))) v.resize(p);
	while (!v.empty() && std::isspace(static_cast<unsigned char>(v.back()))) v.pop_back();
	return v;
}

bool parseIniValue(const std::string& text, double& value)
{
	char* end = nullptr;
	const double x = std::strtod(text.c_str(), &end);
	// decimal only: strtod would take hexadecimal floats ("0x1p3"), which no config writes
	if (text.empty() || *end || !std::isfinite(x) || text.find_first_of("xX") != std::string::npos) return false;
	return value = x, true;
}

bool parseIniValue(const std::string& text, int& value)
{
	char* end = nullptr;
	errno = 0;
	const long x = std::strtol(text.c_str(), &end, 10);
	if (text.empty() || *end || errno == ERANGE || x < INT_MIN || x > INT_MAX) return false;
	return value = int(x), true;
}

bool parseIniValue(const std::string& text, int64_t& value)
{
	char* end = nullptr;
	errno = 0;
	const long long x = std::strtoll(text.c_str(), &end, 10);
	if (text.empty() || *end || errno == ERANGE) return false;
	return value = int64_t(x), true;
}

bool parseIniValue(const std::string& text, bool& value)
{
	const std::string v = lowerCase(text);
	if (v == "true" || v == "yes" || v == "1") return value = true, true;
	if (v == "false" || v == "no" || v == "0") return value = false, true;
	return false;
}

template <>
const char* iniKindOf<double>()
{
	return "a finite number";
}
template <>
const char* iniKindOf<int>()
{
	return "an integer";
}
template <>
const char* iniKindOf<bool>()
{
	return "true or false";
}

template <class T>
void readIniText(const std::string& text, const std::string& section, const std::string& key, T& field,
				 const std::string& sourceName, const std::string& what, typename IniCheck<T>::Fn valid)
{
	T value{};
	if (!parseIniValue(text, value) || (valid && !valid(value)))
		throw std::runtime_error(sourceName + ": [" + section + "] " + key + " = '" + text + "' is not " +
								 (what.empty() ? std::string(iniKindOf<T>()) : what));
	field = value;
}
template void readIniText(const std::string&, const std::string&, const std::string&, double&, const std::string&,
						  const std::string&, bool (*)(double));
template void readIniText(const std::string&, const std::string&, const std::string&, int&, const std::string&,
						  const std::string&, bool (*)(int));
template void readIniText(const std::string&, const std::string&, const std::string&, bool&, const std::string&,
						  const std::string&, bool (*)(bool));

template <class T>
void readIniValue(const mrpt::config::CConfigFileBase& c, const std::string& section, const std::string& key, T& field,
				  const std::string& sourceName, const std::string& what, typename IniCheck<T>::Fn valid)
{
	if (c.keyExists(section, key))
		readIniText(iniValueText(c, section, key), section, key, field, sourceName, what, valid);
}
template void readIniValue(const mrpt::config::CConfigFileBase&, const std::string&, const std::string&, double&,
						   const std::string&, const std::string&, bool (*)(double));
template void readIniValue(const mrpt::config::CConfigFileBase&, const std::string&, const std::string&, int&,
						   const std::string&, const std::string&, bool (*)(int));
template void readIniValue(const mrpt::config::CConfigFileBase&, const std::string&, const std::string&, bool&,
						   const std::string&, const std::string&, bool (*)(bool));

void requireKnownKeys(const mrpt::config::CConfigFileBase& c, const std::string& section,
					  const std::set<std::string>& known, const std::string& sourceName)
{
	if (!c.sectionExists(section)) return;
	std::vector<std::string> present;
	c.getAllKeys(section, present);
	for (const auto& k : present)
		if (!known.count(k))
			throw std::runtime_error(sourceName + ": unknown key '" + k + "' in section [" + section + "]");
}
}  // namespace gridvector::io
