#include "io/ErrorText.h"
#include <gridvector/Version.h>
#include "common/ArgParser.h"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>

namespace gridvector::io
{
ArgParser::ArgParser(std::string program, std::string synopsis)
	: program_(std::move(program)), synopsis_(std::move(synopsis))
{
	flag("help", "show this help and exit");
	flag("version", "print the version (gridvector, git, MRPT) and exit");
}

void ArgParser::option(const std::string& name, const std::string& valueName, const std::string& help,
					   const std::string& def)
{
	specs_[name] = {valueName, help, def, true};
	order_.push_back(name);
}

void ArgParser::flag(const std::string& name, const std::string& help)
{
	specs_[name] = {"", help, "", false};
	order_.push_back(name);
}

void ArgParser::fail(const std::string& msg) const { throw UsageError(program_ + ": " + msg + " (see --help)"); }

bool ArgParser::parse(int argc, const char* const* argv)
{
	bool optionsEnded = false;
	for (int i = 1; i < argc; i++)
	{
		const std::string a = argv[i];
		if (optionsEnded || a.size() < 2 || a.compare(0, 2, "--") != 0)
		{
			if (!optionsEnded && a.size() > 1 && a[0] == '-' && !std::isdigit(static_cast<unsigned char>(a[1])))
				fail("unknown option " + a);
			positional_.push_back(a);
			continue;
		}
		if (a == "--")
		{
			optionsEnded = true;
			continue;
		}
		std::string name = a.substr(2), value;
		const auto eq = name.find('=');
		const bool inlineValue = eq != std::string::npos;
		if (inlineValue) value = name.substr(eq + 1), name.resize(eq);
		const auto it = specs_.find(name);
		if (it == specs_.end()) fail("unknown option --" + name);
		if (it->second.takesValue && !inlineValue)
		{
			if (i + 1 >= argc) fail("option --" + name + " needs a value " + it->second.valueName);
			value = argv[++i];
		}
		else if (!it->second.takesValue && inlineValue)
			fail("option --" + name + " takes no value");
		values_[name] = value;
	}
	return !has("help") && !has("version");
}

std::string ArgParser::usage() const
{
	std::ostringstream os;
	os << "usage: " << program_ << " " << synopsis_ << "\n\noptions:\n";
	for (const auto& n : order_)
	{
		const Spec& s = specs_.at(n);
		std::string left = "  --" + n + (s.takesValue ? " " + s.valueName : "");
		if (left.size() < 26) left.resize(26, ' ');
		else left += "\n" + std::string(26, ' ');
		os << left << s.help;
		if (s.takesValue) os << (s.def == kRequired ? " (required)" : " (default: " + s.def + ")");
		os << "\n";
	}
	return os.str();
}

std::string ArgParser::get(const std::string& name, const std::string& def) const
{
	const auto it = values_.find(name);
	return it == values_.end() ? def : it->second;
}

double ArgParser::getDouble(const std::string& name, double def) const
{
	if (!has(name)) return def;
	const std::string s = get(name);
	char* end = nullptr;
	errno = 0;
	const double v = std::strtod(s.c_str(), &end);
	if (s.empty() || *end || !std::isfinite(v) || errno == ERANGE)
		fail("--" + name + " needs a number, got '" + s + "'");
	return v;
}

long ArgParser::getInt(const std::string& name, long def, long lo, long hi) const
{
	if (!has(name)) return def;
	const std::string s = get(name);
	char* end = nullptr;
	errno = 0;
	const long v = std::strtol(s.c_str(), &end, 10);
	if (s.empty() || *end || errno == ERANGE) fail("--" + name + " needs an integer, got '" + s + "'");
	if (v < lo || v > hi)
		fail("--" + name + " must be in " + std::to_string(lo) + ".." + std::to_string(hi) + ", got " + s);
	return v;
}

void ArgParser::requirePositional(size_t lo, size_t hi) const
{
	if (positional_.size() < lo) fail("missing arguments");
	if (positional_.size() > hi) fail("unexpected argument '" + positional_[hi] + "'");
}

namespace
{
/** "PROG: " + message, unless the message already names the program. */
std::string withProgram(const std::string& program, const std::string& message)
{
	const std::string prefix = program + ": ";
	return message.compare(0, prefix.size(), prefix) == 0 ? message : prefix + message;
}
}  // namespace

int runTool(ArgParser& args, int argc, const char* const* argv, const std::function<int()>& body, std::ostream& out,
			std::ostream& err)
{
	try
	{
		if (!args.parse(argc, argv))
		{
			out << (args.has("help") ? args.usage() : versionLine(args.program()) + "\n");
			return 0;
		}
		return body();
	}
	catch (const UsageError& e)
	{
		err << withProgram(args.program(), oneLineError(e)) << "\n";
		return 2;
	}
	catch (const std::exception& e)
	{
		err << withProgram(args.program(), oneLineError(e)) << "\n";
		return 1;
	}
	catch (...)
	{
		err << args.program() << ": unknown error\n";
		return 1;
	}
}

int runTool(ArgParser& args, int argc, const char* const* argv, const std::function<int()>& body)
{
	return runTool(args, argc, argv, body, std::cout, std::cerr);
}

}  // namespace gridvector::io
