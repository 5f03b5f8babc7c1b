// gv-config: print and validate gridvector's parameters (GridVectorConfig{}: the defaults every tool runs with).
//   gv-config --ini              a complete configuration as an .ini file (each key's help and range above it)
//   gv-config --markdown         the parameter table of doc/parameters.md (default, range, meaning)
//   gv-config --check FILE.ini   load and validate a file (unknown keys and values out of range are errors)
//   gv-config --json             every key with its value, range and help as JSON
#include <gridvector/GridVectorConfig.h>
#include "common/ArgParser.h"

#include <iostream>
#include <string>

using namespace gridvector;

int main(int argc, char** argv)
{
	io::ArgParser args("gv-config", "--ini | --markdown | --json | --check FILE.ini");
	args.flag("ini", "print the configuration as an .ini file (every key, with its meaning and range)");
	args.flag("markdown", "print the parameter table of doc/parameters.md");
	args.flag("json", "print every key with its value, range and meaning as JSON");
	args.option("check", "FILE.ini", "load and validate FILE.ini (unknown keys and bad values are errors)", "none");
	return io::runTool(args, argc, argv, [&] {
		args.requirePositional(0, 0);
		const int modes =
			int(args.has("ini")) + int(args.has("markdown")) + int(args.has("json")) + int(args.has("check"));
		if (modes != 1) args.fail("give exactly one of --ini, --markdown, --json, --check");
		GridVectorConfig cfg;
		if (args.has("ini"))
			cfg.dumpAsIni(std::cout);
		else if (args.has("json"))
			std::cout << cfg.parametersJson() << "\n";
		else if (args.has("markdown"))
			std::cout << GridVectorConfig::parameterTableMarkdown();
		else
		{
			cfg.loadFromFile(args.get("check"));
			std::cout << args.get("check") << ": OK\n";
		}
		return 0;
	});
}
