// Parameter profiles: gv-em-slam's embedded defaults, where they differ from the library's, and why.
#include "config/ConfigProfile.h"
#include "em/EmSlam.h"
#include <gtest/gtest.h>

using namespace gridvector;

TEST(ConfigProfile, LibraryProfileIsTheStructDefaults)
{
	const auto& lib = configProfile("library");
	EXPECT_EQ(lib.config.namedValues(), GridVectorConfig().namedValues());
	EXPECT_TRUE(profileDifferences(lib).empty());
	EXPECT_EQ(configProfiles().front().name, "library");
}

TEST(ConfigProfile, EmSlamProfileIsWhatGvEmSlamRunsWithAndEveryDifferenceHasAReason)
{
	const auto& em = configProfile("em-slam");
	EXPECT_EQ(em.config.namedValues(), EmSlam::defaultConfig().namedValues());
	const auto diff = profileDifferences(em);
	ASSERT_FALSE(diff.empty());
	for (const auto& d : diff)
	{
		EXPECT_NE(d.library, d.profile) << d.key;
		EXPECT_GT(d.reason.size(), 20u) << d.key;
	}
	const std::string table = profileTableMarkdown(em);
	EXPECT_EQ(table.rfind("| `[section]` key | library default | em-slam | why |", 0), 0u);
	for (const auto& d : diff)
		EXPECT_NE(table.find("`[gridvector_" + d.key.substr(0, d.key.find('.')) + "] " + d.key.substr(d.key.find('.') + 1) + "`"),
				  std::string::npos)
			<< d.key;
	EXPECT_NE(table.find("| true | false |"), std::string::npos);  // bools as words (map.wipe_counts_beams)
}

TEST(ConfigProfile, AnUndocumentedOverrideIsAnError)
{
	ConfigProfile p = configProfile("em-slam");
	p.config.mstep.sequentialWindow += 1;
	EXPECT_THROW(profileDifferences(p), std::logic_error);
	ConfigProfile q = configProfile("library");
	q.reasons["grid.resolution"] = "a reason for a key that does not differ";
	EXPECT_THROW(profileDifferences(q), std::logic_error);
}

TEST(ConfigProfile, UnknownProfileNamesTheKnownOnes)
{
	try
	{
		configProfile("em_slam");
		FAIL();
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("library, em-slam"), std::string::npos) << e.what();
	}
}
