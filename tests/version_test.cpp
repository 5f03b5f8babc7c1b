// gridvector::version() and the --version every tool shares through io::runTool.
#include <gridvector/Version.h>
#include "common/ArgParser.h"

#include <gtest/gtest.h>

#include <regex>
#include <sstream>

using namespace gridvector;

TEST(Version, ProjectVersionIsSemantic)
{
	EXPECT_TRUE(std::regex_match(version(), std::regex(R"(\d+\.\d+\.\d+)"))) << version();
	EXPECT_TRUE(std::regex_match(mrptVersion(), std::regex(R"(2\.\d+\.\d+)"))) << mrptVersion();
	EXPECT_FALSE(gitDescription().empty());
	EXPECT_EQ(gitDescription().find_first_of(" \n\t"), std::string::npos) << gitDescription();
}

TEST(Version, LineNamesProgramLibraryGitAndMrpt)
{
	EXPECT_EQ(versionLine("gv-x"),
			  "gv-x (gridvector " + version() + ", git " + gitDescription() + ", MRPT " + mrptVersion() + ")");
}

TEST(RunTool, VersionPrintsOneLineOnStdoutAndReturnsZero)
{
	io::ArgParser args("gv-x", "[ARG]");
	const char* argv[] = {"gv-x", "--version"};
	std::ostringstream out, err;
	bool ran = false;
	const int status = io::runTool(
		args, 2, argv, [&] { return ran = true, 3; }, out, err);
	EXPECT_EQ(status, 0);
	EXPECT_FALSE(ran);
	EXPECT_EQ(out.str(), versionLine("gv-x") + "\n");
	EXPECT_EQ(err.str(), "");
	EXPECT_NE(args.usage().find("--version"), std::string::npos) << args.usage();
}

TEST(RunTool, HelpWinsOverVersion)
{
	io::ArgParser args("gv-x", "[ARG]");
	const char* argv[] = {"gv-x", "--version", "--help"};
	std::ostringstream out, err;
	EXPECT_EQ(io::runTool(
				  args, 3, argv, [] { return 3; }, out, err),
			  0);
	EXPECT_EQ(out.str(), args.usage());
}
