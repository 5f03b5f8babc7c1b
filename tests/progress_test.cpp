// io::Progress: the progress line's text (stage, percent, ETA).
#include "io/Progress.h"

#include <gtest/gtest.h>

using gridvector::io::Progress;

TEST(Progress, LineShowsStagePercentAndEta)
{
	// a quarter done after 10 s: 30 s left
	EXPECT_EQ(Progress::line("iteration 2: registering", 0.25, 10.0), "iteration 2: registering:  25.0%, ETA 30 s");
	EXPECT_EQ(Progress::line("gv-map 455/910", 0.5, 3.0), "gv-map 455/910:  50.0%, ETA 3 s");
}

TEST(Progress, NoEtaBeforeAnEstimateOrWhenDone)
{
	EXPECT_EQ(Progress::line("reading", 0.01, 1.0), "reading:   1.0%");
	EXPECT_EQ(Progress::line("reading", 1.0, 5.0), "reading: 100.0%");
	EXPECT_EQ(Progress::line("", 0.5, 1.0), " 50.0%, ETA 1 s");
}

TEST(Progress, QuietOrNoTerminalDrawsNothing)
{
	Progress quiet("x", true);
	EXPECT_FALSE(quiet.enabled());
	quiet.show("x", 3, 10);  // must not throw or write
	quiet.done();
}
