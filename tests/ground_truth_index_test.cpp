// gv-graphslam -g: the ground truth MRPT 2.5's CGraphSlamEngine indexes without bounds checks,
// checked before the run (empty file, unread format) and followed step by step (short file).
#include "graphslam/GroundTruthIndex.h"
#include "io/AtomicFile.h"

#include <mrpt/config/CConfigFileMemory.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>

using namespace gridvector;
using namespace gridvector::graphslam;
namespace fs = std::filesystem;

namespace
{
std::string tmp(const std::string& n)
{
	return (fs::temp_directory_path() / ("gv_ground_truth_index_test_" + n)).string();
}

std::string errorOf(const std::function<void()>& f)
{
	try
	{
		f();
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "(no error)";
}

std::string write(const std::string& name, const std::string& text)
{
	const std::string p = tmp(name);
	io::writeFileAtomically(p, [&](std::ostream& os) { os << text; });
	return p;
}
}  // namespace

TEST(GroundTruthFile, CountsPosesAndRefusesAnEmptyFile)
{
	const std::string ok = write("ok.txt", "1000 0 0 0\n1000.2 0.1 0 0.01\r\n");
	EXPECT_EQ(checkGroundTruthFile(ok), 2u);
	// an empty file passed the line check and the engine's SLAM metric read m_GT_poses[0]: a segfault
	const std::string empty = write("empty.txt", "");
	EXPECT_EQ(errorOf([&] { checkGroundTruthFile(empty); }), empty + ": no ground-truth poses");
	const std::string bad = write("bad.txt", "1000 0 0 0\n1000.2 0.1 0\n");
	EXPECT_EQ(errorOf([&] { checkGroundTruthFile(bad); }),
			  bad + ":2: ground-truth lines must be 't x y theta' (4 numbers separated by spaces)");
	for (const auto& p : {ok, empty, bad}) fs::remove(p);
}

TEST(GroundTruthFile, OnlyTheFormatTheEngineReads)
{
	mrpt::config::CConfigFileMemory none(std::string("[GeneralConfiguration]\noutput_dir_fname = x\n"));
	EXPECT_NO_THROW(requireNavSimulGroundTruth(none, "a.ini"));  // the engine's default
	mrpt::config::CConfigFileMemory nav(std::string("[GeneralConfiguration]\nground_truth_file_format = navsimul\n"));
	EXPECT_NO_THROW(requireNavSimulGroundTruth(nav, "a.ini"));
	// any other value left the ground truth unread and the metric indexed an empty vector: a segfault
	mrpt::config::CConfigFileMemory foo(std::string("[GeneralConfiguration]\nground_truth_file_format = foo\n"));
	EXPECT_EQ(errorOf([&] { requireNavSimulGroundTruth(foo, "a.ini"); }),
			  "a.ini: [GeneralConfiguration] ground_truth_file_format = 'foo': MRPT 2.5's graphslam engine reads "
			  "ground truth (-g) as NavSimul only");
	mrpt::config::CConfigFileMemory tum(std::string("[GeneralConfiguration]\nground_truth_file_format = RGBD_TUM\n"));
	EXPECT_THROW(requireNavSimulGroundTruth(tum, "a.ini"), std::runtime_error);
}

TEST(GroundTruthIndex, ObservationOnlyRawlogReadsOnePosePerTwoEntries)
{
	// gv-carmen2rawlog's format: ODOMETRY, FLASER per scan; entries are counted from 1 once read
	const auto run = [](size_t poses, size_t scans) {
		GroundTruthIndex gt("gt.txt", poses);
		for (size_t entry = 1; entry <= 2 * scans; ++entry)
		{
			gt.beforeStep("r.rawlog", entry);
			gt.afterStep(true, entry);
		}
		return gt.index();
	};
	EXPECT_EQ(run(20, 20), 20u);  // one pose per scan is enough
	EXPECT_EQ(errorOf([&] { run(19, 20); }),
			  "gt.txt: 19 ground-truth poses, the engine reads pose 20 at entry 39 of r.rawlog (one pose per scan)");
	// one pose: "1 ground-truth pose", not "1 ground-truth poses"
	EXPECT_EQ(errorOf([&] { run(1, 20); }),
			  "gt.txt: 1 ground-truth pose, the engine reads pose 2 at entry 3 of r.rawlog (one pose per scan)");
}

TEST(GroundTruthIndex, ActionObservationRawlogReadsOnePosePerStep)
{
	GroundTruthIndex gt("gt.txt", 3);
	for (size_t step = 1; step <= 3; ++step)
	{
		gt.beforeStep("r.rawlog", 2 * step);
		gt.afterStep(false, 2 * step);  // odd or even, a pair advances the index
	}
	EXPECT_EQ(gt.index(), 3u);
	EXPECT_THROW(gt.beforeStep("r.rawlog", 8), std::runtime_error);
}
