// io::counted: a count with its noun in the right number ("1 ground-truth pose", not "1 ground-truth poses").
#include "io/Counted.h"

#include <gtest/gtest.h>

using namespace gridvector;

TEST(Counted, SingularForOneOnly)
{
	EXPECT_EQ(io::counted(0, "scan"), "0 scans");
	EXPECT_EQ(io::counted(1, "scan"), "1 scan");
	EXPECT_EQ(io::counted(2, "ground-truth pose"), "2 ground-truth poses");
	EXPECT_EQ(io::counted(1, "odometry observation"), "1 odometry observation");
}

TEST(Counted, IrregularPluralAndVerb)
{
	EXPECT_EQ(io::counted(1, "entry", "entries"), "1 entry");
	EXPECT_EQ(io::counted(3, "entry", "entries"), "3 entries");
	EXPECT_STREQ(io::agree(1, "does", "do"), "does");
	EXPECT_STREQ(io::agree(4, "does", "do"), "do");
}
