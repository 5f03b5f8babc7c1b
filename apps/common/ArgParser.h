// Command-line parsing for the tools, over CLI11 (CLI::App parses, a CLI::Formatter prints the
// option table): declared options only, every problem is one clear line
// ("prog: unknown option --x (see --help)"); runTool is the main() they share.
#pragma once

#include <functional>
#include <iosfwd>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace CLI
{
class App;
}

namespace gridvector::io
{
/** A command-line usage error (tools exit with status 2). */
struct UsageError : std::runtime_error
{
	using std::runtime_error::runtime_error;
};

class ArgParser
{
   public:
	ArgParser(std::string program, std::string synopsis);

	/** What an option's `def` says of an option the tool cannot run without: --help shows "(required)". */
	static constexpr const char* kRequired = "\x01required";

	/** --name VALUE (also --name=VALUE). `def`: what the tool does without the option, which --help
	 * prints after the help as "(default: DEF)", e.g. shortestText of the value the tool then uses,
	 * "none" or a phrase; kRequired for "(required)". Every option states one (tests/integration/help.sh). */
	void option(const std::string& name, const std::string& valueName, const std::string& help, const std::string& def);
	/** --name without a value. */
	void flag(const std::string& name, const std::string& help);

	/** Throws UsageError; returns false if --help or --version was given (nothing to run). */
	bool parse(int argc, const char* const* argv);
	std::string usage() const;
	const std::string& program() const { return program_; }

	bool has(const std::string& name) const { return values_.count(name) > 0; }
	std::string get(const std::string& name, const std::string& def = "") const;
	double getDouble(const std::string& name, double def) const;
	long getInt(const std::string& name, long def, long lo, long hi) const;
	const std::vector<std::string>& positional() const { return positional_; }
	/** Throws UsageError unless there are between lo and hi positional arguments. */
	void requirePositional(size_t lo, size_t hi) const;
	[[noreturn]] void fail(const std::string& msg) const;

   private:
	struct Spec
	{
		std::string name, valueName, help;  //!< help with "(default: DEF)" or "(required)" for an option
		bool takesValue;
	};
	std::unique_ptr<CLI::App> app(std::vector<std::string>& positional) const;

	std::string program_, synopsis_;
	std::vector<Spec> specs_;  //!< in declaration order, the order of --help
	std::map<std::string, std::string> values_;
	std::vector<std::string> positional_;
};

/** A tool's main(): args.parse(argc, argv), then body().
 *  --help: args.usage() on out, 0; --version: versionLine(program) on out, 0. Otherwise body()'s
 *  return value, except for an exception, reported as one line on err (every tool's convention):
 *  a UsageError "PROG: problem (see --help)", 2; any other "PROG: FILE: problem" (MRPT's
 *  exceptions by their message alone, without the backtrace), 1. */
int runTool(ArgParser& args, int argc, const char* const* argv, const std::function<int()>& body, std::ostream& out,
			std::ostream& err);
/** The same on std::cout and std::cerr. */
int runTool(ArgParser& args, int argc, const char* const* argv, const std::function<int()>& body);

}  // namespace gridvector::io
