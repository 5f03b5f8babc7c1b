// gv-config: print and validate gridvector's parameters.
//   gv-config --ini [--profile NAME]             a complete configuration as an .ini file
//   gv-config --markdown [--profile NAME]        the parameter table of doc/parameters.md
//                                                (with a profile: where it differs from the library, and why)
//   gv-config --check FILE.ini [--profile NAME]  load and validate a file over the profile (unknown keys are errors)
//   gv-config --json [--profile NAME]            every key and value as JSON (as report.json records it)
// Profiles: library (GridVectorConfig{}, the default), em-slam (gv-em-slam's built-in defaults).
#include "config/ConfigProfile.h"
#include "common/ArgParser.h"

#include <iostream>
#include <string>

using namespace gridvector;

int main(int argc, char** argv)
{
	io::ArgParser args("gv-config", "--ini | --markdown | --json | --check FILE.ini   [--profile NAME]");
	args.flag("ini", "print the configuration as an .ini file (every key, with its meaning)");
	args.flag("markdown", "print the parameter table of doc/parameters.md (with --profile: the differences)");
	args.flag("json", "print every key and value as JSON");
	args.option("check", "FILE.ini", "load and validate FILE.ini (unknown keys and bad values are errors)", "none");
	args.option("profile", "NAME", "library (GridVectorConfig{}) or em-slam (gv-em-slam's defaults)", "library");
	return io::runTool(
		args, argc, argv,
		[&] {
			args.requirePositional(0, 0);
			const int modes = int(args.has("ini")) + int(args.has("markdown")) + int(args.has("json")) +
							  int(args.has("check"));
			if (modes != 1) args.fail("give exactly one of --ini, --markdown, --json, --check");
			const bool profileGiven = args.has("profile");
			const ConfigProfile* profile = nullptr;
			try
			{
				profile = &configProfile(args.get("profile", "library"));
			}
			catch (const std::invalid_argument& e)
			{
				args.fail(e.what());
			}
			GridVectorConfig cfg = profile->config;
			if (args.has("ini")) cfg.dumpAsIni(std::cout);
			else if (args.has("json")) std::cout << cfg.toJson() << "\n";
			else if (args.has("markdown"))
				std::cout << (profileGiven ? profileTableMarkdown(*profile) : GridVectorConfig::parameterTableMarkdown());
			else
			{
				cfg.loadFromFile(args.get("check"));
				std::cout << args.get("check") << ": OK\n";
			}
			return 0;
		});
}
