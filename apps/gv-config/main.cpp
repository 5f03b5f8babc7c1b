// gv-config: print gridvector's parameters.
//   gv-config --ini                 default configuration as an .ini file
//   gv-config --markdown            the parameter table of doc/parameters.md
//   gv-config --check FILE.ini      load and validate a file (unknown keys are errors)
#include <gridvector/ErrorText.h>
#include <gridvector/GridVectorConfig.h>

#include <iostream>
#include <string>

int main(int argc, char** argv)
{
	const std::string mode = argc > 1 ? argv[1] : "";
	try
	{
		if (mode == "--ini" && argc == 2)
		{
			gridvector::GridVectorConfig().dumpAsIni(std::cout);
			return 0;
		}
		if (mode == "--markdown" && argc == 2)
		{
			std::cout << gridvector::GridVectorConfig::parameterTableMarkdown();
			return 0;
		}
		if (mode == "--check" && argc == 3)
		{
			gridvector::GridVectorConfig cfg;
			cfg.loadFromFile(argv[2]);
			std::cout << argv[2] << ": OK\n";
			return 0;
		}
	}
	catch (const std::exception& e)
	{
		std::cerr << "gv-config: " << gridvector::oneLineError(e) << "\n";
		return 1;
	}
	std::cerr << "usage: gv-config --ini | --markdown | --check FILE.ini\n";
	return 2;
}
