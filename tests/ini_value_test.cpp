// io::IniValue: the strict .ini value reader shared by GridVectorConfig and CGridVectorMap.
#include "io/IniValue.h"
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <stdexcept>
#include <string>

using namespace gridvector::io;

namespace
{
template <class T>
std::string readError(const std::string& value, T& field, const std::string& what = {},
					  typename IniCheck<T>::Fn valid = nullptr)
{
	mrpt::config::CConfigFileMemory ini("[sec]\nkey = " + value + "\n");
	try
	{
		readIniValue(ini, "sec", "key", field, "my.ini", what, valid);
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(IniValue, NumbersAreReadWholeAndFinite)
{
	double d = 7;
	EXPECT_EQ(readError("0.05", d), "");
	EXPECT_DOUBLE_EQ(d, 0.05);
	for (const char* bad : {"0.o5", "abc", "nan", "inf", "1e999", "0.05m"})
	{
		d = 7;
		EXPECT_EQ(readError(bad, d), std::string("my.ini: [sec] key = '") + bad + "' is not a finite number") << bad;
		EXPECT_DOUBLE_EQ(d, 7);  // left alone
	}
	int i = 0;
	EXPECT_EQ(readError("-12", i), "");
	EXPECT_EQ(i, -12);
	for (const char* bad : {"1.5", "2.0", "1e3", "x", "99999999999"})
		EXPECT_EQ(readError(bad, i), std::string("my.ini: [sec] key = '") + bad + "' is not an integer") << bad;
}

TEST(IniValue, BoolsAreTheSixWordsInAnyCase)
{
	bool b = false;
	for (const char* yes : {"true", "YES", "1", "True"})
	{
		b = false;
		EXPECT_EQ(readError(yes, b), "");
		EXPECT_TRUE(b) << yes;
	}
	for (const char* no : {"false", "No", "0"})
	{
		b = true;
		EXPECT_EQ(readError(no, b), "");
		EXPECT_FALSE(b) << no;
	}
	EXPECT_EQ(readError("ture", b), "my.ini: [sec] key = 'ture' is not true or false");
}

TEST(IniValue, TrailingCommentsAndBlanksAreNotPartOfTheValue)
{
	double d = 0;
	EXPECT_EQ(readError("0.25 ; metres", d), "");
	EXPECT_DOUBLE_EQ(d, 0.25);
	EXPECT_EQ(readError("0.5\t# half", d), "");
	EXPECT_DOUBLE_EQ(d, 0.5);
	EXPECT_EQ(readError("0.5#x", d), "my.ini: [sec] key = '0.5#x' is not a finite number");  // no blank: not a comment
}

TEST(IniValue, ACheckRefusesAValueWithTheCallersWords)
{
	double d = 1;
	EXPECT_EQ(readError("-0.5", d, "a number > 0", [](double v) { return v > 0; }),
			  "my.ini: [sec] key = '-0.5' is not a number > 0");
	EXPECT_DOUBLE_EQ(d, 1);
	EXPECT_EQ(readError("abc", d, "a number > 0", [](double v) { return v > 0; }),
			  "my.ini: [sec] key = 'abc' is not a number > 0");
	EXPECT_EQ(readError("2", d, "a number > 0", [](double v) { return v > 0; }), "");
	EXPECT_DOUBLE_EQ(d, 2);
}

TEST(IniValue, AbsentKeyLeavesTheFieldAndUnknownKeysAreNamed)
{
	mrpt::config::CConfigFileMemory ini("[sec]\nsigma = 0.1\nsgima = 0.2\n");
	double d = 3;
	readIniValue(ini, "sec", "other", d, "my.ini");
	EXPECT_DOUBLE_EQ(d, 3);
	EXPECT_NO_THROW(requireKnownKeys(ini, "nosuchsection", {"sigma"}, "my.ini"));
	EXPECT_NO_THROW(requireKnownKeys(ini, "sec", {"sigma", "sgima"}, "my.ini"));
	try
	{
		requireKnownKeys(ini, "sec", {"sigma"}, "my.ini");
		FAIL() << "no exception";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()), "my.ini: unknown key 'sgima' in section [sec]");
	}
}

TEST(IniValue, SixtyFourBitIntegersAreReadWholeAndInRange)
{
	int64_t v = 7;
	EXPECT_TRUE(parseIniValue("9000000000", v));
	EXPECT_EQ(v, 9000000000LL);
	for (const char* bad : {"99999999999999999999", "1.5", "", "12x", "nan"})
	{
		v = 7;
		EXPECT_FALSE(parseIniValue(bad, v)) << bad;
		EXPECT_EQ(v, 7);  // left alone
	}
}
