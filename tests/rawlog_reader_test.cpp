// MRPT rawlog reader (both formats, gzip or not) and the CARMEN -> rawlog
// converter, checked against MRPT's own CRawlog.
#include "io/AtomicFile.h"
#include "io/FileBytes.h"
#include <gridvector/io/LogReader.h>
#include "io/RawlogReader.h"
#include "io/RawlogWriter.h"

#include <gtest/gtest.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CRawlog.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>

using namespace gridvector::io;
namespace fs = std::filesystem;

namespace
{
const std::string kSena = std::string(GV_MRPT_DATASETS) + "/2006-01ENE-21-SENA_Telecom Faculty_one_loop_only.rawlog";
const std::string kLocalization = std::string(GV_MRPT_DATASETS) + "/localization_demo.rawlog";
const std::string kIntel = std::string(GV_SHARED_DIR) + "/data/intel-corrected.log.gz";

std::string tmp(const std::string& name) { return (fs::temp_directory_path() / ("gv_rawlog_test_" + name)).string(); }

/** Every 2D scan in a rawlog, as MRPT itself loads it. */
std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> mrptScans(const std::string& path, size_t* entries = nullptr)
{
	mrpt::obs::CRawlog raw;
	EXPECT_TRUE(raw.loadFromRawLogFile(path));
	if (entries) *entries = raw.size();
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> out;
	for (size_t i = 0; i < raw.size(); i++)
	{
		if (raw.getType(i) == mrpt::obs::CRawlog::etSensoryFrame)
		{
			for (const auto& o : *raw.getAsObservations(i))
				if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(o)) out.push_back(s);
		}
		else if (raw.getType(i) == mrpt::obs::CRawlog::etObservation)
			if (auto s = std::dynamic_pointer_cast<mrpt::obs::CObservation2DRangeScan>(raw.getAsObservation(i)))
				out.push_back(s);
	}
	return out;
}

void expectSameScan(const mrpt::obs::CObservation2DRangeScan& a, const mrpt::obs::CObservation2DRangeScan& b)
{
	ASSERT_EQ(a.getScanSize(), b.getScanSize());
	EXPECT_FLOAT_EQ(a.aperture, b.aperture);
	EXPECT_FLOAT_EQ(a.maxRange, b.maxRange);
	EXPECT_EQ(a.rightToLeft, b.rightToLeft);
	EXPECT_NEAR(a.sensorPose.yaw(), b.sensorPose.yaw(), 1e-12);
	EXPECT_EQ(a.timestamp, b.timestamp);
	for (size_t i = 0; i < a.getScanSize(); i++)
	{
		EXPECT_EQ(a.getScanRange(i), b.getScanRange(i));
		EXPECT_EQ(a.getScanRangeValidity(i), b.getScanRangeValidity(i));
	}
}

std::string errorOf(const std::string& path)
{
	try
	{
		readLog(path);
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "no error";
}

void writeBytes(const std::string& path, const std::vector<char>& b, size_t n)
{
	writeFileAtomically(path, [&](std::ostream& os) { os.write(b.data(), std::streamsize(n)); });
}
}  // namespace

TEST(RawlogReader, SensoryFrameFormatMatchesMrpt)
{
	const LogData d = readLog(kSena);  // gzip-compressed, actions + sensory frames
	const auto ref = mrptScans(kSena);
	ASSERT_EQ(d.scans.size(), ref.size());
	ASSERT_EQ(d.scans.size(), 225u);
	for (size_t i = 0; i < d.scans.size(); i++)
	{
		expectSameScan(*d.scans[i].scan, *ref[i]);
		EXPECT_NEAR(d.scans[i].timestamp, mrpt::Clock::toDouble(ref[i]->timestamp), 1e-6);
		EXPECT_TRUE(d.scans[i].hasOdometry);
		EXPECT_FALSE(d.scans[i].hasLogPose);
		if (i)
		{
			EXPECT_GT(d.scans[i].timestamp, d.scans[i - 1].timestamp);
		}
	}
	EXPECT_NE(d.summary.find("actions+sensory-frames format"), std::string::npos);
	// odometry is the running sum of the robot-movement actions
	mrpt::obs::CRawlog raw;
	raw.loadFromRawLogFile(kSena);
	mrpt::poses::CPose2D sum;
	size_t frame = 0;
	for (size_t i = 0; i < raw.size(); i++)
		if (raw.getType(i) == mrpt::obs::CRawlog::etActionCollection)
		{
			auto m = raw.getAsAction(i)->getActionByClass<mrpt::obs::CActionRobotMovement2D>();
			if (m) sum = sum + m->rawOdometryIncrementReading;
		}
		else if (raw.getType(i) == mrpt::obs::CRawlog::etSensoryFrame)
		{
			EXPECT_NEAR(d.scans[frame].odometry.x, sum.x(), 1e-9);
			EXPECT_NEAR(d.scans[frame].odometry.y, sum.y(), 1e-9);
			EXPECT_NEAR(d.scans[frame].odometry.phi, sum.phi(), 1e-9);
			frame++;
		}
	EXPECT_EQ(frame, 225u);
	const LogData l = readLog(kLocalization);
	EXPECT_EQ(l.scans.size(), 37u);
}

TEST(RawlogReader, RoundTripThroughBothFormatsAndMrptCRawlog)
{
	const LogData intel = readLog(kIntel);
	for (auto format : {RawlogFormat::Observations, RawlogFormat::SensoryFrames})
		for (bool compress : {true, false})
		{
			SCOPED_TRACE(std::string(format == RawlogFormat::Observations ? "obs" : "sf") +
						 (compress ? " gz" : " plain"));
			const std::string path = tmp("intel.rawlog");
			writeRawlog(path, intel, {format, compress});
			EXPECT_EQ(isGzipFile(path), compress);
			// MRPT reads it: one odometry + one scan per CARMEN scan, or action + frame pairs
			size_t entries = 0;
			const auto ref = mrptScans(path, &entries);
			EXPECT_EQ(entries, 2 * intel.scans.size());
			ASSERT_EQ(ref.size(), intel.scans.size());
			for (size_t i = 0; i < ref.size(); i += 37)
			{
				expectSameScan(*ref[i], *intel.scans[i].scan);
				EXPECT_NEAR(mrpt::Clock::toDouble(ref[i]->timestamp), intel.scans[i].timestamp, 1e-6);
				EXPECT_NEAR(ref[i]->aperture, 179 * M_PI / 180, 1e-6);
			}
			// and so do we, with the same odometry (sf: relative to the first scan)
			const LogData back = readLog(path);
			ASSERT_EQ(back.scans.size(), intel.scans.size());
			const mrpt::poses::CPose2D o0(intel.scans[0].odometry), b0(back.scans[0].odometry);
			for (size_t i = 0; i < back.scans.size(); i += 13)
			{
				EXPECT_NEAR(back.scans[i].timestamp, intel.scans[i].timestamp, 1e-6);
				const auto a = mrpt::poses::CPose2D(intel.scans[i].odometry) - o0;
				const auto b = mrpt::poses::CPose2D(back.scans[i].odometry) - b0;
				EXPECT_NEAR(a.x(), b.x(), 1e-6);
				EXPECT_NEAR(a.y(), b.y(), 1e-6);
				EXPECT_NEAR(a.phi(), b.phi(), 1e-6);
			}
			if (format == RawlogFormat::Observations)
			{
				EXPECT_NEAR(back.scans[5].odometry.x, intel.scans[5].odometry.x, 1e-9);
			}
			fs::remove(path);
		}
}

TEST(RawlogReader, TruncatedOrCorruptFilesAreErrors)
{
	const LogData intel = readLog(kIntel);
	const std::string plain = tmp("plain.rawlog");
	writeRawlog(plain, intel, {RawlogFormat::Observations, false});
	const std::vector<char> bytes = readFileBytes(plain);
	const std::string cut = tmp("cut.rawlog");
	writeBytes(cut, bytes, bytes.size() / 2 + 7);  // inside some object
	const std::string e = errorOf(cut);
	EXPECT_EQ(e.rfind(cut + ": entry ", 0), 0u) << e;
	EXPECT_NE(e.find("truncated or corrupt rawlog"), std::string::npos) << e;

	std::vector<char> garbage = bytes;
	for (size_t i = bytes.size() / 3; i < bytes.size() / 3 + 4000; i++) garbage[i] = char(0xA5);
	const std::string bad = tmp("bad.rawlog");
	writeBytes(bad, garbage, garbage.size());
	EXPECT_EQ(errorOf(bad).rfind(bad + ": entry ", 0), 0u) << errorOf(bad);

	std::ifstream in(kSena, std::ios::binary);
	std::vector<char> gz((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	const std::string cutGz = tmp("cut_gz.rawlog");
	writeBytes(cutGz, gz, gz.size() - 100);
	EXPECT_EQ(errorOf(cutGz), cutGz + ": truncated or corrupt gzip data (CRC/length trailer mismatch)");
	for (const auto& p : {plain, cut, bad, cutGz}) fs::remove(p);
}

namespace
{
/** Three scans of 181 beams at 2 m, odometry at the origin. */
LogData threeScans()
{
	LogData log;
	for (int k = 0; k < 3; k++)
	{
		ScanRecord r;
		r.timestamp = 1000 + 0.2 * k;
		r.scan = mrpt::obs::CObservation2DRangeScan::Create();
		r.scan->aperture = float(M_PI);
		r.scan->maxRange = 30;
		r.scan->resizeScan(181);
		for (size_t i = 0; i < 181; i++) r.scan->setScanRange(i, 2.0f), r.scan->setScanRangeValidity(i, true);
		r.scan->timestamp = mrpt::Clock::fromDouble(r.timestamp);
		r.hasOdometry = true;
		log.scans.push_back(r);
	}
	return log;
}
}  // namespace

TEST(RawlogReader, ZeroBeamScanIsAnErrorAndTimeGoingBackIsAWarning)
{
	LogData log = threeScans();
	std::swap(log.scans[1].timestamp, log.scans[2].timestamp);  // out of order
	std::swap(log.scans[1].scan->timestamp, log.scans[2].scan->timestamp);
	const std::string unsorted = tmp("unsorted.rawlog");
	writeRawlog(unsorted, log, {RawlogFormat::Observations, false});
	const LogData back = readLog(unsorted);
	ASSERT_EQ(back.scans.size(), 3u);
	EXPECT_NE(back.summary.find("warning: 1 scan timestamp does not increase"), std::string::npos) << back.summary;

	log.scans[2].scan->resizeScan(0);  // a scanner that returned nothing
	const std::string empty = tmp("empty_scan.rawlog");
	writeRawlog(empty, log, {RawlogFormat::Observations, false});
	EXPECT_EQ(errorOf(empty), empty + ": entry 6: 2D scan with 0 beams");
	for (const auto& p : {unsorted, empty}) fs::remove(p);
}

TEST(RawlogReader, NoScansSaysWhatTheRawlogHolds)
{
	// MRPT's range-bearing and range-only SLAM samples: sensory frames without a 2D laser
	const std::string kf = std::string(GV_MRPT_DATASETS) + "/kf-slam_demo.rawlog";
	const LogData d = readLog(kf);
	EXPECT_TRUE(d.scans.empty());
	EXPECT_EQ(d.contents.format, LogContents::Format::Rawlog);
	EXPECT_EQ(d.contents.actionSets, 250u);
	EXPECT_EQ(d.contents.sensoryFrames, 250u);
	EXPECT_TRUE(d.contents.movementActions);
	try
	{
		requireScans(d);
		ADD_FAILURE() << "no error";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()),
				  kf + ": no laser scans (actions+sensory-frames format (250 action sets, 250 sensory "
					   "frames); odometry from robot-movement actions, 250 "
					   "mrpt::obs::CObservationBearingRange ignored)");
	}
	// observation-only, odometry objects and nothing else
	LogContents c;
	c.format = LogContents::Format::Rawlog;
	c.observations = 7;
	c.odometryRecords = 7;
	EXPECT_EQ(describeContents(c), "observation-only format (7 observations); odometry from 7 odometry observations");
	c.odometryRecords = 0;
	c.ignored["scans of other sensors"] = 3;
	EXPECT_EQ(describeContents(c),
			  "observation-only format (7 observations); no odometry, 3 scans of other sensors ignored");
}

TEST(Carmen2Rawlog, ToolWritesRawlogsMrptCanRead)
{
	const std::string bin = std::string(GV_BIN_DIR) + "/gv-carmen2rawlog";
	if (!fs::exists(bin)) GTEST_SKIP() << bin << " not built";
	const std::string out = tmp("tool.rawlog"), log = tmp("tool.txt");
	ASSERT_EQ(std::system(("'" + bin + "' '" + kIntel + "' '" + out + "' --format sf > '" + log + "' 2>&1").c_str()),
			  0);
	size_t entries = 0;
	const auto scans = mrptScans(out, &entries);
	EXPECT_EQ(scans.size(), 910u);
	EXPECT_EQ(entries, 2 * 910u);
	std::ifstream l(log);
	std::string line;
	std::getline(l, line);
	EXPECT_NE(line.find("910 scans (910 FLASER)"), std::string::npos) << line;
	// bad usage and bad input: exit status 2 and 1, one line on stderr
	EXPECT_EQ(WEXITSTATUS(std::system(("'" + bin + "' a b --format xyz 2>'" + log + "'").c_str())), 2);
	EXPECT_EQ(WEXITSTATUS(std::system(("'" + bin + "' /no/such.log '" + out + "' 2>'" + log + "'").c_str())), 1);
	std::ifstream e(log);
	std::getline(e, line);
	EXPECT_EQ(line, "gv-carmen2rawlog: /no/such.log: cannot read (No such file or directory)");
	fs::remove(out);
	fs::remove(log);
}

namespace
{
std::vector<char> rawlogBytes(const LogData& log, RawlogFormat format)
{
	const std::string p = tmp("bytes.rawlog");
	writeRawlog(p, log, {format, false});
	const std::vector<char> b = readFileBytes(p);
	fs::remove(p);
	return b;
}

std::string parseError(const std::vector<char>& bytes)
{
	try
	{
		parseRawlog(bytes, "mem.rawlog");
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "no error";
}

/** Overwrites the first little-endian uint32 `from` at or after byte `after` with `to`. */
bool patchU32(std::vector<char>& b, size_t after, uint32_t from, uint32_t to)
{
	for (size_t i = after; i + 4 <= b.size(); i++)
		if (std::memcmp(&b[i], &from, 4) == 0) return std::memcpy(&b[i], &to, 4), true;
	return false;
}
}  // namespace

// issue 22: counts in the bytes are checked before MRPT's deserialisers size anything from them
TEST(RawlogReader, CorruptCountsAreRejectedBeforeMrptAllocates)
{
	for (auto format : {RawlogFormat::Observations, RawlogFormat::SensoryFrames})
	{
		const std::vector<char> good = rawlogBytes(threeScans(), format);
		ASSERT_EQ(parseRawlog(good, "mem.rawlog").scans.size(), 3u);
		for (uint32_t n : {1u << 30, 1u << 28, 100001u})
		{
			std::vector<char> b = good;
			ASSERT_TRUE(patchU32(b, 0, 181, n));
			EXPECT_EQ(parseError(b), "mem.rawlog: entry 2: corrupt rawlog object (the scan's beam count is " +
										 std::to_string(n) + " (at most 100000))");
		}
		std::vector<char> b = good;  // a count that fits the limit but not the bytes left
		ASSERT_TRUE(patchU32(b, b.size() / 2, 181, 90000));
		EXPECT_NE(parseError(b).find("the scan's beam count is 90000: needs 450000 bytes"), std::string::npos)
			<< parseError(b);
	}
	// a sensory frame announcing 2^30 observations; an action with an invalid estimation method
	std::vector<char> sf = rawlogBytes(threeScans(), RawlogFormat::SensoryFrames);
	const std::string frame = "CSensoryFrame";
	const size_t at = std::string(sf.begin(), sf.end()).find(frame);
	ASSERT_NE(at, std::string::npos);
	std::vector<char> b = sf;
	ASSERT_TRUE(patchU32(b, at + frame.size() + 1, 1, 1u << 30));
	EXPECT_NE(parseError(b).find("(the sensory frame's observation count is 1073741824 (at most 10000))"),
			  std::string::npos)
		<< parseError(b);
	const std::string mov = "CActionRobotMovement2D";
	const size_t am = std::string(sf.begin(), sf.end()).find(mov);
	ASSERT_NE(am, std::string::npos);
	b = sf;
	const uint32_t method = 12345;
	std::memcpy(&b[am + mov.size() + 1], &method, 4);  // the int32 right after the version byte
	EXPECT_NE(parseError(b).find("a robot movement's estimation method is 12345 (0 or 1)"), std::string::npos)
		<< parseError(b);
}

TEST(RawlogReader, AbsurdScanGeometryIsAnError)
{
	const auto errorWith = [](auto&& edit) {
		LogData log = threeScans();
		edit(*log.scans[1].scan);
		return parseError(rawlogBytes(log, RawlogFormat::Observations));
	};
	EXPECT_EQ(errorWith([](auto& s) {
				  s.sensorPose.x(std::nan(""));
			  }).rfind("mem.rawlog: entry 4: 2D scan with its sensor at (nan", 0),
			  0u);
	EXPECT_EQ(
		errorWith([](auto& s) { s.sensorPose.y(1e15); }).rfind("mem.rawlog: entry 4: 2D scan with its sensor at", 0),
		0u);
	EXPECT_EQ(errorWith([](auto& s) { s.aperture = 1000; }),
			  "mem.rawlog: entry 4: 2D scan with an aperture of 1000.000000 rad (at most 2 pi)");
	EXPECT_EQ(errorWith([](auto& s) { s.maxRange = 1e9; }).rfind("mem.rawlog: entry 4: 2D scan with a max range of", 0),
			  0u);
	EXPECT_EQ(errorWith([](auto& s) { s.sensorPose.x(0.3); }), "no error");
}

TEST(RawlogReader, DevZeroAndNulBytesStopAtOnce)
{
	try
	{
		readLog("/dev/zero");
		ADD_FAILURE() << "/dev/zero read";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()),
				  "/dev/zero: neither a CARMEN log nor an MRPT rawlog (it starts with a NUL byte)");
	}
}
