#include "io/JsonFile.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

using namespace gridvector;

TEST(JsonFile, KeysInInsertionOrderAsDumpTwoGivesThem)
{
	nlohmann::ordered_json j;
	j["zeta"] = 1;
	j["alpha"] = {{"b", true}, {"a", nullptr}};
	j["mid"] = 0.25;
	EXPECT_EQ(io::jsonText(j),
			  "{\n  \"zeta\": 1,\n  \"alpha\": {\n    \"b\": true,\n    \"a\": null\n  },\n  \"mid\": 0.25\n}\n");
}

TEST(JsonFile, NonFiniteIsNullAndBadUtf8IsReplaced)
{
	nlohmann::ordered_json j;
	j["nan"] = std::nan("");
	j["inf"] = -std::numeric_limits<double>::infinity();
	j["name"] = std::string("caf\xe9\tlog \"1\"\\");  // Latin-1 byte, tab, quote, backslash
	const std::string text = io::jsonText(j);
	EXPECT_NE(text.find("\"nan\": null"), std::string::npos) << text;
	EXPECT_NE(text.find("\"inf\": null"), std::string::npos) << text;
	EXPECT_NE(text.find("\"name\": \"caf\xef\xbf\xbd\\tlog \\\"1\\\"\\\\\""), std::string::npos) << text;
	const auto back = nlohmann::json::parse(text);
	EXPECT_TRUE(back["nan"].is_null());
	EXPECT_EQ(back["name"], "caf\xef\xbf\xbd\tlog \"1\"\\");
}

TEST(JsonFile, WrittenAtomically)
{
	const std::string path = ::testing::TempDir() + "/json_file_test.json";
	nlohmann::ordered_json j = {{"n", 3}};
	io::writeJsonFile(path, j);
	std::ifstream in(path);
	std::stringstream ss;
	ss << in.rdbuf();
	EXPECT_EQ(ss.str(), io::jsonText(j));
	std::remove(path.c_str());
	try
	{
		io::writeJsonFile(::testing::TempDir() + "/no/such/dir/x.json", j);
		FAIL() << "wrote into a missing directory";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("x.json: cannot write"), std::string::npos) << e.what();
	}
}
