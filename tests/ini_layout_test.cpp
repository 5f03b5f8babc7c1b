// io::requireIniLayout: what MRPT's .ini reader would pass over silently is an error; MRPT's own
// comment styles, and every graphslam-engine .ini MRPT ships, are not.
#include "io/IniLayout.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <stdexcept>

#include "graphslam_ini_files.h"

using gridvector::io::requireIniLayout;

namespace
{
std::string layoutError(const std::string& text)
{
	try
	{
		requireIniLayout(text, "a.ini");
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(IniLayout, MrptsCommentStylesAreComments)
{
	EXPECT_EQ(layoutError("//------\n// Config file\n//\n; x\n# y\n\n[s]\na = 1 // m\n"), "");
	EXPECT_EQ(layoutError("  // indented\n\t//\n[s]\n"), "");
}

TEST(IniLayout, KeysOutsideASectionAndUnclosedHeadersAreRefused)
{
	EXPECT_EQ(layoutError("// header\nfoo = 1\n[s]\n"), "a.ini:2: 'foo = 1' is outside any [section]");
	EXPECT_EQ(layoutError("/ half a comment\n[s]\n"), "a.ini:1: '/ half a comment' is outside any [section]");
	EXPECT_EQ(layoutError("[s\na = 1\n"), "a.ini:1: section header without ']'");
}

TEST(IniLayout, EveryGraphslamIniMrptShipsPasses)
{
	const auto files = gvtest::graphslamIniFiles();
	ASSERT_GE(files.size(), 7u) << "MRPT's graphslam-engine .ini files not found in " << gvtest::mrptGraphslamIniDir;
	for (const auto& path : files)
	{
		std::ifstream in(path);
		std::stringstream text;
		text << in.rdbuf();
		EXPECT_NO_THROW(requireIniLayout(text.str(), path)) << path;
	}
}
