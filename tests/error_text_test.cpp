#include "io/ErrorText.h"
#include <gtest/gtest.h>
#include <mrpt/core/exceptions.h>

TEST(ErrorText, PlainMessagesPassThroughOnOneLine)
{
	EXPECT_EQ(gridvector::oneLineError(std::string("a\n  b\tc")), "a b c");
}

TEST(ErrorText, MrptExceptionsKeepOnlyTheMessage)
{
	try
	{
		THROW_EXCEPTION("the root cause");
	}
	catch (const std::exception& e)
	{
		const std::string s = gridvector::oneLineError(e);
		EXPECT_EQ(s.find('\n'), std::string::npos);
		EXPECT_NE(s.find("the root cause"), std::string::npos);
		EXPECT_EQ(s.find("Call stack"), std::string::npos);
		EXPECT_EQ(s.find("Location"), std::string::npos);
	}
}

TEST(ErrorText, LongMessagesAreCut) { EXPECT_EQ(gridvector::oneLineError(std::string(1000, 'x'), 50).size(), 50u); }

TEST(ErrorText, BracketedPrefixesAreKeptButFramesDropped)
{
	EXPECT_EQ(gridvector::oneLineError(std::string("[CGraphSlamEngine] my.ini: bad key\n[0 ] 0x7f001\n[12] foo")),
			  "[CGraphSlamEngine] my.ini: bad key");
}

TEST(ErrorText, ControlBytesOfACorruptFileDoNotReachTheTerminal)
{
	EXPECT_EQ(gridvector::oneLineError(std::string("class 'a\x1b[2J\x01z' is not registered")),
			  "class 'a?[2J?z' is not registered");
}

TEST(ErrorText, StrayHighBytesOfACorruptFileAreReplacedButUtf8NamesKept)
{
	// gv-map-info on binary garbage: MRPT quotes the "class name" it read, high bytes raw
	EXPECT_EQ(gridvector::oneLineError(std::string("class '\xa5M\xca\x18%0' for file 'caf\xc3\xa9.gvmap'")),
			  "class '?M??%0' for file 'caf\xc3\xa9.gvmap'");
	EXPECT_EQ(gridvector::oneLineError(std::string("cut \xe2\x82")), "cut ??");  // a truncated sequence
}
