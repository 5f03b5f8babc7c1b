#include "io/ErrorText.h"
#include <gridvector/Version.h>
#include "common/ArgParser.h"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <iostream>

namespace gridvector::io
{
namespace
{
/** --help's column of the option help: "  --name VALUE" padded to it, a longer one alone on its line. */
constexpr size_t kHelpColumn = 26;
/** What CLI11 records for a value option given without its value: each takes 0 or 1 values, so
 * that the problem is reported in the tools' words ("needs a value") rather than CLI11's. */
constexpr const char* kNoValue = "\x02no value";
/** What CLI11 records for a flag given as --name: anything else is a value it takes none of. */
constexpr const char* kFlagGiven = "\x03given";

/** --help: "usage: PROG SYNOPSIS", "options:", one row per option as CLI11 lays it out. */
class OptionTable : public CLI::Formatter
{
   public:
	OptionTable() { column_width(kHelpColumn); }
	std::string make_help(const CLI::App* app, std::string, CLI::AppFormatMode) const override
	{
		std::string out = "usage: " + app->get_name() + " " + app->get_description() + "\n\noptions:\n";
		for (const CLI::Option* o : app->get_options([](const CLI::Option* o) { return !o->get_positional(); }))
			out += make_option(o, false);
		return out;
	}
	std::string make_option_name(const CLI::Option* o, bool) const override { return "--" + o->get_lnames().front(); }
	std::string make_option_opts(const CLI::Option* o) const override
	{
		return o->get_items_expected_max() > 0 ? " " + o->get_type_name() : "";
	}
};
}  // namespace

ArgParser::ArgParser(std::string program, std::string synopsis)
	: program_(std::move(program)), synopsis_(std::move(synopsis))
{
	flag("help", "show this help and exit");
	flag("version", "print the version (gridvector, git, MRPT) and exit");
}

void ArgParser::option(const std::string& name, const std::string& valueName, const std::string& help,
					   const std::string& def)
{
	specs_.push_back({name, valueName, help + (def == kRequired ? " (required)" : " (default: " + def + ")"), true});
}

void ArgParser::flag(const std::string& name, const std::string& help) { specs_.push_back({name, "", help, false}); }

void ArgParser::fail(const std::string& msg) const { throw UsageError(program_ + ": " + msg + " (see --help)"); }

/** The declared options as a CLI::App: unknown ones and the positionals kept for parse() to judge. */
std::unique_ptr<CLI::App> ArgParser::app(std::vector<std::string>& positional) const
{
	auto app = std::make_unique<CLI::App>(synopsis_, program_);
	app->set_help_flag();  // --help is an ordinary flag here: runTool answers it
	app->allow_extras();
	app->formatter(std::make_shared<OptionTable>());
	for (const Spec& s : specs_)
		if (s.takesValue)
			app->add_option("--" + s.name, s.help)
				->type_name(s.valueName)
				->expected(0, 1)
				->default_str(kNoValue)
				->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
		else
			app->add_flag("--" + s.name + "{" + kFlagGiven + "}", s.help);
	app->add_option("positional", positional);
	return app;
}

bool ArgParser::parse(int argc, const char* const* argv)
{
	const auto cli = app(positional_);
	try
	{
		cli->parse(argc, argv);
	}
	catch (const CLI::ParseError& e)
	{
		fail(e.what());
	}
	for (const std::string& a : cli->remaining())
		if (a != "--") fail("unknown option " + a.substr(0, a.find('=')));
	for (const Spec& s : specs_)
	{
		const CLI::Option* o = cli->get_option("--" + s.name);
		if (o->count() == 0) continue;
		const std::string v = s.takesValue ? o->as<std::string>() : "";
		if (s.takesValue && v == kNoValue) fail("option --" + s.name + " needs a value " + s.valueName);
		for (const std::string& r : o->results())
			if (!s.takesValue && r != kFlagGiven) fail("option --" + s.name + " takes no value");
		values_[s.name] = v;
	}
	return !has("help") && !has("version");
}

std::string ArgParser::usage() const
{
	std::vector<std::string> unused;
	return app(unused)->help();
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
