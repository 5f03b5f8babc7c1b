#include <gridvector/GridVectorConfig.h>
#include <gtest/gtest.h>
#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <type_traits>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using gridvector::GridVectorConfig;

TEST(GridVectorConfig, DefaultsAreThePapers)
{
	GridVectorConfig c;
	EXPECT_DOUBLE_EQ(c.grid.priorOccupy, 0.5);  // Sec. 3.1: prior 1/2 over 1
	EXPECT_DOUBLE_EQ(c.grid.priorVisit, 1.0);
	EXPECT_DOUBLE_EQ(c.grid.resolution, 0.1);  // Table 1 compares with a 10 cm grid
	EXPECT_NO_THROW(c.validate());
}

// One set of defaults: gv-em-slam's measured values are the library's (doc/benchmarks.md).
TEST(GridVectorConfig, DefaultsAreGvEmSlamsMeasuredValues)
{
	const GridVectorConfig c;
	EXPECT_EQ(c.extraction.minPoints, 3);
	EXPECT_DOUBLE_EQ(c.extraction.minLength, 0.12);
	EXPECT_DOUBLE_EQ(c.extraction.maxPointGap, 1.0);
	EXPECT_TRUE(c.matcher.stepWithinGates);
	EXPECT_TRUE(c.mstep.overlapReregisterMoved);
	EXPECT_TRUE(c.mstep.sequentialOdometryGuess);
	EXPECT_DOUBLE_EQ(c.posegraph.odometrySigmaXYPerM, 0.06);
}

// Every key: one short help string, a range with finite bounds that holds its default
// (bools: true/false); a help string is said once (estep.static_threshold once carried
// matching.static_threshold's).
TEST(GridVectorConfig, EveryKeyHasOneShortHelpAndAFiniteRangeHoldingItsDefault)
{
	GridVectorConfig c;
	std::set<std::string> helps;
	size_t keys = 0;
	c.visitGroups([&](const char* group, auto& g) {
		g.visit([&](const char* key, auto& field, const char* help, const gridvector::Range& range) {
			const std::string name = std::string(group) + "." + key, h = help;
			++keys;
			EXPECT_FALSE(h.empty()) << name;
			EXPECT_LE(h.size(), 160u) << name << ": " << h;
			EXPECT_TRUE(helps.insert(h).second) << name << ": the same help as another key";
			using T = std::decay_t<decltype(field)>;
			EXPECT_EQ(range.flag, (std::is_same_v<T, bool>)) << name;
			EXPECT_TRUE(std::isfinite(range.lo) && std::isfinite(range.hi) && range.lo < range.hi) << name;
			EXPECT_TRUE(range.contains(double(field))) << name << " = " << double(field) << " not in " << range.text();
		});
	});
	EXPECT_EQ(keys, c.namedValues().size());
	// the Eq. 14 threshold is described as such, not as the ICP's
	std::string estep, matching;
	c.estep.visit([&](const char* k, auto&, const char* h, const gridvector::Range&) {
		if (std::string(k) == "static_threshold") estep = h;
	});
	c.matching.visit([&](const char* k, auto&, const char* h, const gridvector::Range&) {
		if (std::string(k) == "static_threshold") matching = h;
	});
	EXPECT_NE(estep.find("Eq. 14"), std::string::npos) << estep;
	EXPECT_EQ(estep.find("ICP"), std::string::npos) << estep;
	EXPECT_NE(matching.find("ICP"), std::string::npos) << matching;
}

TEST(GridVectorConfig, RangeTextAndBounds)
{
	using gridvector::Range;
	EXPECT_EQ(Range::closed(0, 1).text(), "[0, 1]");
	EXPECT_EQ(Range::above(0, 10).text(), "(0, 10]");
	EXPECT_EQ(Range::open(0, 90).text(), "(0, 90)");
	EXPECT_EQ(Range::boolean().text(), "true/false");
	EXPECT_TRUE(Range::closed(0, 1).contains(0) && Range::closed(0, 1).contains(1));
	EXPECT_FALSE(Range::above(0, 1).contains(0));
	EXPECT_TRUE(Range::above(0, 1).contains(1));
	EXPECT_FALSE(Range::open(0, 1).contains(1));
	EXPECT_FALSE(Range::closed(0, 1).contains(std::nan("")));
}

TEST(GridVectorConfig, LoadsKeysFromIniSections)
{
	mrpt::config::CConfigFileMemory ini(
		"[gridvector_extraction]\nsplit_threshold = 0.07\nmin_points = 9\n"
		"[gridvector_grid]\nhalf_width = 3\n[gridvector_map]\nmerge_on_insert = false\n");
	GridVectorConfig c;
	c.loadFromConfigFile(ini);
	EXPECT_DOUBLE_EQ(c.extraction.splitThreshold, 0.07);
	EXPECT_EQ(c.extraction.minPoints, 9);
	EXPECT_EQ(c.grid.halfWidth, 3);
	EXPECT_FALSE(c.map.mergeOnInsert);
	EXPECT_DOUBLE_EQ(c.grid.resolution, 0.1);  // untouched keys keep defaults
}

TEST(GridVectorConfig, UnknownKeyIsAnErrorNamingFileSectionAndKey)
{
	mrpt::config::CConfigFileMemory ini("[gridvector_grid]\nresolutoin = 0.05\n");
	GridVectorConfig c;
	try
	{
		c.loadFromConfigFile(ini, "gridvector", "my.ini");
		FAIL() << "no exception";
	}
	catch (const std::runtime_error& e)
	{
		const std::string msg = e.what();
		EXPECT_NE(msg.find("my.ini"), std::string::npos);
		EXPECT_NE(msg.find("resolutoin"), std::string::npos);
		EXPECT_NE(msg.find("[gridvector_grid]"), std::string::npos);
	}
}

namespace
{
std::string loadError(const std::string& iniText, const std::string& source = "my.ini")
{
	mrpt::config::CConfigFileMemory ini(iniText);
	GridVectorConfig c;
	try
	{
		c.loadFromConfigFile(ini, "gridvector", source);
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "";
}

/** What loading `iniText` under `prefix` from `source` throws (any exception), "" if nothing. */
std::string loadFailure(const std::string& iniText, const std::string& prefix = "gridvector",
						const std::string& source = "my.ini")
{
	try
	{
		GridVectorConfig().loadFromConfigFile(mrpt::config::CConfigFileMemory(iniText), prefix, source);
	}
	catch (const std::exception& e)
	{
		return e.what();
	}
	return "";
}

std::string fileLoadError(const std::string& iniText)
{
	const std::string path = testing::TempDir() + "gv_layout_test.ini";
	std::ofstream(path) << iniText;
	GridVectorConfig c;
	std::string msg;
	try
	{
		c.loadFromFile(path);
	}
	catch (const std::runtime_error& e)
	{
		msg = e.what();
	}
	std::remove(path.c_str());
	return msg.empty() ? msg : msg.substr(msg.find("gv_layout_test.ini"));
}
}  // namespace

TEST(GridVectorConfig, MisspeltSectionIsAnErrorNamingIt)
{
	// [gridvector_gird] would drop its keys silently: every [gridvector_...] section must be a group
	EXPECT_EQ(loadError("[gridvector_gird]\nresolution = 0.05\n"),
			  "my.ini: unknown section [gridvector_gird] (the gridvector_ sections are extraction, grid, map, estep, "
			  "matcher, posegraph, mstep, doors, occupancy, matching)");
	// MRPT matches section names case-insensitively: so do we, and other programs' sections pass
	EXPECT_EQ(
		loadError("[GridVector_Grid]\nresolution = 0.05\n[gv_sim]\nseed = 3\n[GridVectorNRD]\nuse_odometry = true\n"),
		"");
	GridVectorConfig c;
	c.loadFromConfigFile(mrpt::config::CConfigFileMemory("[GridVector_Grid]\nresolution = 0.05\n"));
	EXPECT_DOUBLE_EQ(c.grid.resolution, 0.05);
	// a caller's own sections under the prefix are named to it
	mrpt::config::CConfigFileMemory map("[m_00_grid]\nresolution = 0.05\n[m_00_likelihoodOpts]\nsigma = 1\n");
	EXPECT_NO_THROW(c.loadFromConfigFile(map, "m_00", "map", {"likelihoodOpts"}));
	EXPECT_THROW(c.loadFromConfigFile(map, "m_00", "map"), std::runtime_error);
}

TEST(GridVectorConfig, FileWithKeysOutsideSectionsOrABrokenHeaderIsAnError)
{
	EXPECT_EQ(fileLoadError("; gridvector\nresolution = 0.05\n[gridvector_grid]\nhalf_width = 2\n"),
			  "gv_layout_test.ini:2: 'resolution = 0.05' is outside any [section]");
	EXPECT_EQ(fileLoadError("[gridvector_grid\nresolution = 0.05\n"),
			  "gv_layout_test.ini:1: section header without ']'");
	EXPECT_EQ(fileLoadError("# comment\n\n  [gridvector_grid] ; c\n\tresolution = 0.05\n"), "");
	// a binary file's bytes are quoted as \xHH, at most 40 of them (they reached the terminal raw)
	EXPECT_EQ(fileLoadError("\x01\xff\x1b[2Jab = 1 and a line longer than forty bytes\n"),
			  "gv_layout_test.ini:1: '\\x01\\xff\\x1b[2Jab = 1 and a line longer than fort...' is outside any "
			  "[section]");
}

TEST(GridVectorConfig, OutOfRangeValueIsRejected)
{
	mrpt::config::CConfigFileMemory ini("[gridvector_grid]\nresolution = -1\n");
	GridVectorConfig c;
	EXPECT_THROW(c.loadFromConfigFile(ini), std::invalid_argument);
}

// A key set from code to inf or NaN (the .ini reader refuses both) is refused by validate(),
// naming the key: map.hit_band = inf passed "> 0" and made every wipe triangle degenerate.
TEST(GridVectorConfig, NonFiniteValueSetFromCodeIsRejected)
{
	GridVectorConfig c;
	c.map.hitBand = std::numeric_limits<double>::infinity();
	try
	{
		c.validate();
		FAIL() << "inf accepted";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_EQ(std::string(e.what()), "[gridvector_map] hit_band = 'inf' must be finite");
	}
	GridVectorConfig d;
	d.doors.maxCornerGap = std::nan("");
	EXPECT_THROW(d.validate(), std::invalid_argument);
	EXPECT_NO_THROW(GridVectorConfig().validate());
}

// Every key has a range; a value outside it is refused at load time, one line naming the file,
// section, key, value and why: negative counts, zero windows, shares outside [0,1], a minimum
// above its maximum (a representative set, one per kind and group).
TEST(GridVectorConfig, OutOfRangeValuesAreErrorsNamingFileSectionKeyValueAndWhy)
{
	const std::vector<std::pair<std::string, std::string>> bad = {
		{"[gridvector_estep]\nmin_visits = -1\n", "my.ini: [gridvector_estep] min_visits = '-1' must be in [0, 1000]"},
		{"[gridvector_estep]\nstatic_threshold = 1\n",
		 "my.ini: [gridvector_estep] static_threshold = '1' must be in (0, 1)"},
		{"[gridvector_estep]\nfinal_static_threshold = 1.2\n",
		 "my.ini: [gridvector_estep] final_static_threshold = '1.2' must be in [0, 1]"},
		{"[gridvector_extraction]\nmin_range = -0.5\n",
		 "my.ini: [gridvector_extraction] min_range = '-0.5' must be in [0, 10]"},
		{"[gridvector_extraction]\nbreak_angle_deg = 0\n",
		 "my.ini: [gridvector_extraction] break_angle_deg = '0' must be in (0, 90)"},
		{"[gridvector_extraction]\nmax_point_gap = 0\n",
		 "my.ini: [gridvector_extraction] max_point_gap = '0' must be in (0, 10]"},
		{"[gridvector_grid]\nprior_occupy = 2\n",
		 "my.ini: [gridvector_grid] prior_occupy = '2' must be <= prior_visit (1)"},
		{"[gridvector_map]\nmax_rho_diff = -0.1\n",
		 "my.ini: [gridvector_map] max_rho_diff = '-0.1' must be in [0, 10]"},
		{"[gridvector_map]\nmax_direction_diff_deg = 200\n",
		 "my.ini: [gridvector_map] max_direction_diff_deg = '200' must be in [0, 180]"},
		{"[gridvector_matcher]\ngate_rho_final = 1\n",
		 "my.ini: [gridvector_matcher] gate_rho_final = '1' must be <= gate_rho_initial (0.6)"},
		{"[gridvector_matcher]\ndegenerate_ratio = 2\n",
		 "my.ini: [gridvector_matcher] degenerate_ratio = '2' must be in [0, 1]"},
		{"[gridvector_matcher]\nmax_rms = 0\n", "my.ini: [gridvector_matcher] max_rms = '0' must be in (0, 1]"},
		{"[gridvector_posegraph]\nodometry_sigma_xy_min = 0\n",
		 "my.ini: [gridvector_posegraph] odometry_sigma_xy_min = '0' must be in (0, 10]"},
		{"[gridvector_posegraph]\nreject_chi2 = -3\n",
		 "my.ini: [gridvector_posegraph] reject_chi2 = '-3' must be in (0, 1e+09]"},
		{"[gridvector_mstep]\noverlap_run_gap = 0\n",
		 "my.ini: [gridvector_mstep] overlap_run_gap = '0' must be in [1, 1e+06]"},
		{"[gridvector_mstep]\nreconsider_limit = -1\n",
		 "my.ini: [gridvector_mstep] reconsider_limit = '-1' must be in [0, 1000]"},
		{"[gridvector_mstep]\noverlap_min_share = 1.25\n",
		 "my.ini: [gridvector_mstep] overlap_min_share = '1.25' must be in [0, 1]"},
		{"[gridvector_mstep]\nloop_search_min_share = 1.5\n",
		 "my.ini: [gridvector_mstep] loop_search_min_share = '1.5' must be in [0, 1]"},
		{"[gridvector_mstep]\nloop_search_hypotheses = 0\n",
		 "my.ini: [gridvector_mstep] loop_search_hypotheses = '0' must be in [1, 1000]"},
		{"[gridvector_doors]\nmax_door_length = 0.5\n",
		 "my.ini: [gridvector_doors] max_door_length = '0.5' must be >= min_door_length (0.6)"},
		{"[gridvector_doors]\nmin_state_diff_deg = 200\n",
		 "my.ini: [gridvector_doors] min_state_diff_deg = '200' must be in [0, 180]"},
		{"[gridvector_occupancy]\nmargin = -1\n", "my.ini: [gridvector_occupancy] margin = '-1' must be in [0, 100]"},
		// every number that sizes a loop, an allocation or a geometry has an upper bound
		{"[gridvector_mstep]\nmax_iterations = 100000\n",
		 "my.ini: [gridvector_mstep] max_iterations = '100000' must be in [1, 1000]"},
		{"[gridvector_grid]\nresolution = 5\n", "my.ini: [gridvector_grid] resolution = '5' must be in (0, 1]"},
		{"[gridvector_grid]\nresolution = 1e-300\n",
		 "my.ini: [gridvector_grid] resolution = '1e-300' must be >= 0.01 (finer cells outgrow memory)"},
		{"[gridvector_occupancy]\nresolution = 1e-3\n",
		 "my.ini: [gridvector_occupancy] resolution = '0.001' must be >= 0.01 (finer cells outgrow memory)"}};
	for (const auto& [text, expected] : bad) EXPECT_EQ(loadFailure(text), expected);
	mrpt::config::CConfigFileMemory ini(bad[0].first);
	EXPECT_THROW(GridVectorConfig().loadFromConfigFile(ini), std::invalid_argument);
	// a map's sections carry its own prefix
	EXPECT_EQ(loadFailure("[m_00_estep]\nmin_visits = -2\n", "m_00", "map.ini"),
			  "map.ini: [m_00_estep] min_visits = '-2' must be in [0, 1000]");
	// the edges of the ranges are valid
	EXPECT_EQ(loadFailure("[gridvector_estep]\nmin_visits = 0\nfinal_static_threshold = "
						  "1\n[gridvector_matcher]\ngate_rho_final = 0.6\n"
						  "[gridvector_doors]\nmax_door_length = 0.6\n[gridvector_mstep]\nmax_iterations = 1\n"),
			  "");
}

TEST(GridVectorConfig, DumpRoundTripsThroughIni)
{
	GridVectorConfig a;
	a.extraction.minLength = 0.42;
	a.grid.halfWidth = 2;
	a.map.mergeOnInsert = false;
	std::ostringstream os;
	a.dumpAsIni(os);
	mrpt::config::CConfigFileMemory ini(os.str());
	GridVectorConfig b;
	b.loadFromConfigFile(ini);
	EXPECT_DOUBLE_EQ(b.extraction.minLength, 0.42);
	EXPECT_EQ(b.grid.halfWidth, 2);
	EXPECT_FALSE(b.map.mergeOnInsert);
}

TEST(GridVectorConfig, MissingFileIsAClearError)
{
	GridVectorConfig c;
	try
	{
		c.loadFromFile("/nonexistent/dir/x.ini");
		FAIL();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/x.ini"), std::string::npos);
	}
}

TEST(GridVectorConfig, ParameterTableListsEveryKey)
{
	const std::string md = GridVectorConfig::parameterTableMarkdown();
	GridVectorConfig c;
	c.visitGroups([&](const char*, auto& g) {
		g.visit([&](const char* key, auto&, const char*, const gridvector::Range&) {
			EXPECT_NE(md.find(std::string("`") + key + "`"), std::string::npos) << key;
		});
	});
}

TEST(GridVectorConfig, NamedValuesListEveryKeyAndSetThemBack)
{
	GridVectorConfig a;
	a.grid.halfWidth = 3;
	a.map.mergeOnInsert = false;
	a.extraction.minLength = 0.21;
	const auto named = a.namedValues();
	size_t keys = 0;
	a.visitGroups([&](const char*, auto& g) {
		g.visit([&](const char*, auto&, const char*, const gridvector::Range&) { ++keys; });
	});
	ASSERT_EQ(named.size(), keys);
	EXPECT_EQ(named.front().first, "extraction.min_range");
	GridVectorConfig b;
	for (const auto& [name, value] : named) EXPECT_TRUE(b.setNamedValue(name, value)) << name;
	EXPECT_EQ(b.namedValues(), named);
	EXPECT_EQ(b.grid.halfWidth, 3);
	EXPECT_FALSE(b.map.mergeOnInsert);
}

TEST(GridVectorConfig, SetNamedValueRejectsUnknownKeysAndValuesOfTheWrongType)
{
	GridVectorConfig c;
	EXPECT_FALSE(c.setNamedValue("grid.resolutoin", 0.2));
	EXPECT_FALSE(c.setNamedValue("resolution", 0.2));
	EXPECT_FALSE(c.setNamedValue("gridx.resolution", 0.2));
	EXPECT_THROW(c.setNamedValue("grid.half_width", 1.5), std::invalid_argument);
	EXPECT_THROW(c.setNamedValue("map.merge_on_insert", 0.5), std::invalid_argument);
	EXPECT_THROW(c.setNamedValue("grid.half_width", std::nan("")), std::invalid_argument);
	EXPECT_TRUE(c.setNamedValue("occupancy.resolution", 0.25));
	EXPECT_DOUBLE_EQ(c.occupancy.resolution, 0.25);
	EXPECT_DOUBLE_EQ(c.grid.resolution, GridVectorConfig().grid.resolution);  // same key name, other group
}

TEST(GridVectorConfig, JsonHasEveryGroupAndKey)
{
	GridVectorConfig c;
	c.extraction.minLength = 0.12;
	const std::string j = c.toJson();
	EXPECT_EQ(j.front(), '{');
	EXPECT_EQ(j.back(), '}');
	EXPECT_NE(j.find("\"extraction\": {\"min_range\": 0.02,"), std::string::npos) << j;
	EXPECT_NE(j.find("\"min_length\": 0.12,"), std::string::npos) << j;
	EXPECT_NE(j.find("\"merge_on_insert\": true"), std::string::npos) << j;
	for (const auto& [name, value] : c.namedValues())
		EXPECT_NE(j.find("\"" + name.substr(name.find('.') + 1) + "\": "), std::string::npos) << name;
}

TEST(GridVectorConfig, JsonHasNoInfOrNan)
{
	GridVectorConfig c;
	c.extraction.minLength = std::numeric_limits<double>::infinity();
	c.grid.resolution = -std::numeric_limits<double>::infinity();
	c.occupancy.resolution = std::nan("");
	const std::string j = c.toJson();
	EXPECT_NE(j.find("\"min_length\": null,"), std::string::npos) << j;
	for (const char* bad : {"inf", "nan", "Infinity", "NaN"})
		EXPECT_EQ(j.find(std::string(": ") + bad), std::string::npos) << bad << " in " << j;
	for (const char* bad : {": -inf", ": -Infinity"}) EXPECT_EQ(j.find(bad), std::string::npos) << j;
	// every value is a JSON number, true, false or null
	size_t values = 0;
	for (size_t p = j.find("\": "); p != std::string::npos; p = j.find("\": ", p + 1))
	{
		const std::string rest = j.substr(p + 3);
		if (rest[0] == '{') continue;  // a group
		++values;
		const bool literal = rest.rfind("true", 0) == 0 || rest.rfind("false", 0) == 0 || rest.rfind("null", 0) == 0;
		EXPECT_TRUE(literal || std::strchr("-0123456789", rest[0]) != nullptr) << rest.substr(0, 20);
	}
	EXPECT_EQ(values, c.namedValues().size());
	size_t nulls = 0;
	for (size_t p = j.find(": null"); p != std::string::npos; p = j.find(": null", p + 1)) ++nulls;
	EXPECT_EQ(nulls, 3u) << j;
}

TEST(GridVectorConfig, ValuesThatAreNotNumbersAreErrorsNamingSectionKeyAndValue)
{
	const std::vector<std::pair<std::string, std::string>> bad = {
		{"[gridvector_grid]\nresolution = 0.o5\n", "[gridvector_grid] resolution = '0.o5' is not a finite number"},
		{"[gridvector_grid]\nhalf_width = 1.5\n", "[gridvector_grid] half_width = '1.5' is not an integer"},
		{"[gridvector_map]\nmerge_on_insert = ture\n",
		 "[gridvector_map] merge_on_insert = 'ture' is not true or false"},
		{"[gridvector_map]\nmax_rho_diff = nan\n", "'nan' is not a finite number"},
		{"[gridvector_map]\nmax_rho_diff =\n", "max_rho_diff = '' is not a finite number"}};
	for (const auto& [text, expected] : bad)
	{
		mrpt::config::CConfigFileMemory ini(text);
		GridVectorConfig c;
		try
		{
			c.loadFromConfigFile(ini, "gridvector", "my.ini");
			ADD_FAILURE() << "accepted: " << text;
		}
		catch (const std::runtime_error& e)
		{
			EXPECT_NE(std::string(e.what()).find("my.ini: "), std::string::npos) << e.what();
			EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
		}
	}
	mrpt::config::CConfigFileMemory ok(
		"[gridvector_grid]\nresolution = 0.05   ; finer\nhalf_width = 2 # wider\n"
		"[gridvector_map]\nmerge_on_insert = No\n");
	GridVectorConfig c;
	c.loadFromConfigFile(ok, "gridvector", "ok.ini");
	EXPECT_DOUBLE_EQ(c.grid.resolution, 0.05);
	EXPECT_EQ(c.grid.halfWidth, 2);
	EXPECT_FALSE(c.map.mergeOnInsert);
}

// issue 22: a line MRPT would skip is an error; a config from /dev/zero or a FIFO is bounded
TEST(GridVectorConfig, LineWithoutEqualsIsAnErrorNamingTheLine)
{
	EXPECT_EQ(fileLoadError("[gridvector_grid]\nresolution 0.05\n"),
			  "gv_layout_test.ini:2: 'resolution 0.05' is not 'key = value' (MRPT would skip the line)");
	EXPECT_EQ(fileLoadError("; comment\n# comment\n\n[gridvector_grid]\n  resolution = 0.05 ; ok\n"), "");
}

TEST(GridVectorConfig, ConfigFromDevZeroStopsAtTheLineLimit)
{
	GridVectorConfig c;
	try
	{
		c.loadFromFile("/dev/zero");
		FAIL();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()), "/dev/zero:1: line longer than 65536 bytes (the limit)");
	}
	const std::string big = testing::TempDir() + "gv_big.ini";
	{
		std::ofstream f(big);
		f << "[gridvector_grid]\n";
		for (int i = 0; i < 80000; i++) f << "; a comment line that makes the file large\n";
	}
	try
	{
		c.loadFromFile(big);
		FAIL();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()), big + ": larger than 1048576 bytes (the input limit)");
	}
	std::remove(big.c_str());
}
