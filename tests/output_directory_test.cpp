// io::OutputDirectory: checked before the work, created only to write, removed again if the run wrote nothing.
#include "io/AtomicFile.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>

namespace fs = std::filesystem;
using gridvector::io::OutputDirectory;

namespace
{
struct TempDir
{
	fs::path path = fs::temp_directory_path() /
					("gv_outdir_test_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) + "_" +
					 ::testing::UnitTest::GetInstance()->current_test_info()->name());
	TempDir() { fs::create_directories(path); }
	~TempDir() { fs::remove_all(path); }
	std::string operator/(const std::string& s) const { return (path / s).string(); }
};
}  // namespace

TEST(OutputDirectory, CheckingCreatesNothing)
{
	TempDir t;
	{
		OutputDirectory d(t / "a/b/c");
		EXPECT_FALSE(fs::exists(t / "a"));
	}
	EXPECT_FALSE(fs::exists(t / "a"));
}

TEST(OutputDirectory, UnwritablePlacesFailBeforeTheWork)
{
	TempDir t;
	std::ofstream(t / "file") << "x";
	try
	{
		OutputDirectory d(t / "file/out");
		FAIL() << "no error for a directory below a file";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()), t / "file/out" + ": cannot write (Not a directory)");
	}
	EXPECT_THROW(OutputDirectory(t / "file"), std::runtime_error);
	EXPECT_NO_THROW(OutputDirectory(t.path.string()));
	EXPECT_NO_THROW(OutputDirectory(t / "new/"));
}

TEST(OutputDirectory, CreatedButUnusedDirectoriesAreRemoved)
{
	TempDir t;
	fs::create_directories(t / "a");
	{
		OutputDirectory d(t / "a/b/c/");
		EXPECT_EQ(d.create(), t / "a/b/c/");
		EXPECT_TRUE(fs::is_directory(t / "a/b/c"));
	}  // a failed run: nothing written
	EXPECT_FALSE(fs::exists(t / "a/b"));
	EXPECT_TRUE(fs::is_directory(t / "a"));  // existed before: kept
}

TEST(OutputDirectory, DirectoriesWithOutputsAreKept)
{
	TempDir t;
	{
		OutputDirectory d(t / "a/b");
		std::ofstream(d.create() + "/out.txt") << "result";
	}
	EXPECT_TRUE(fs::exists(t / "a/b/out.txt"));
}

TEST(WritableFile, FailsAsTheAtomicWriteWouldButCreatesNothing)
{
	using gridvector::io::AtomicFile;
	using gridvector::io::checkWritableFile;
	TempDir t;
	std::ofstream(t / "file") << "x";
	fs::create_directories(t / "dir");
	for (const std::string& bad : {t / "file/out.log", t / "nodir/out.log", t / "dir"})
	{
		std::string checked, written;
		try
		{
			checkWritableFile(bad);
		}
		catch (const std::runtime_error& e)
		{
			checked = e.what();
		}
		try
		{
			AtomicFile f(bad);
		}
		catch (const std::runtime_error& e)
		{
			written = e.what();
		}
		EXPECT_FALSE(checked.empty()) << bad;
		EXPECT_EQ(checked, written) << bad;
	}
	EXPECT_NO_THROW(checkWritableFile(t / "new.log"));
	EXPECT_NO_THROW(checkWritableFile(t / "file"));  // replaced atomically
	EXPECT_FALSE(fs::exists(t / "new.log"));
	EXPECT_FALSE(fs::exists(t / "nodir"));
	EXPECT_EQ(std::distance(fs::directory_iterator(t.path), fs::directory_iterator{}), 2);  // file, dir: no temporary
}

TEST(OutputDirectory, APreviousRunsMarkerIsRemovedBeforeAnyOutput)
{
	TempDir t;
	fs::create_directories(t / "out");
	std::ofstream(t / "out/report.json") << "{}";
	std::ofstream(t / "out/trajectory.txt") << "old";
	OutputDirectory d(t / "out", "report.json");
	EXPECT_EQ(d.markerPath(), t / "out/report.json");
	EXPECT_TRUE(fs::exists(t / "out/report.json")) << "checking the directory removes nothing";
	d.create();
	EXPECT_FALSE(fs::exists(t / "out/report.json")) << "a half-rewritten set must not look complete";
	EXPECT_TRUE(fs::exists(t / "out/trajectory.txt")) << "only the marker goes";
	// no marker: nothing removed
	std::ofstream(t / "out/report.json") << "{}";
	OutputDirectory(t / "out").create();
	EXPECT_TRUE(fs::exists(t / "out/report.json"));
	EXPECT_EQ(OutputDirectory(t / "out").markerPath(), "");
}

TEST(OutputDirectory, AMarkerThatIsADirectoryIsAnError)
{
	TempDir t;
	fs::create_directories(t / "out/report.json");
	OutputDirectory d(t / "out", "report.json");
	try
	{
		d.create();
		FAIL() << "no error for a directory where the marker goes";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()), t / "out/report.json" + ": cannot write (it is a directory)");
	}
}
