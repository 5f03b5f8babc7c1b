// CARMEN reader: real logs, gzip, PARAM handling, beam layout and malformed input.
#include "io/AtomicFile.h"
#include "io/CarmenReader.h"
#include "io/FileBytes.h"
#include <gridvector/io/LogReader.h>
#include "io/NoReturnRange.h"

#include <gtest/gtest.h>
#include <mrpt/maps/CSimplePointsMap.h>

#include <sys/stat.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

using namespace gridvector::io;
namespace fs = std::filesystem;

namespace
{
const std::string kIntel = std::string(GV_SHARED_DIR) + "/data/intel-corrected.log.gz";
const std::string kCsail = std::string(GV_SHARED_DIR) + "/data/csail-corrected.log.gz";
const std::string kFreiburg = std::string(GV_SHARED_DIR) + "/data/freiburg-101-corrected.log.gz";
constexpr double kDeg = M_PI / 180.0;

LogData parse(const std::string& text)
{
	return parseCarmenLog(std::vector<char>(text.begin(), text.end()), "mem.log");
}

std::string flaser(int n, double range, const std::string& tail = "1 2 0.5 3 4 0.25 10.5 host 10.5")
{
	std::string s = "FLASER " + std::to_string(n);
	for (int i = 0; i < n; i++) s += " " + std::to_string(range);
	return s + " " + tail + "\n";
}

/** Without a max-range PARAM equal readings would all be taken for "no return". */
const std::string kMax = "PARAM robot_front_laser_max 80 h 0\n";

std::string errorOf(const std::string& text)
{
	try
	{
		parse(text);
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "no error";
}

/** World angle of beam i of a scan taken at the origin, as MRPT computes it. */
double beamAngle(const mrpt::obs::CObservation2DRangeScan& s, size_t i)
{
	mrpt::maps::CSimplePointsMap m;
	m.insertionOptions.minDistBetweenLaserPoints = 0;
	m.insertObservation(s);
	size_t k = 0;  // index among valid beams
	for (size_t j = 0; j < i; j++) k += s.getScanRangeValidity(j);
	mrpt::math::TPoint2D p;
	m.getPoint(k, p.x, p.y);
	return std::atan2(p.y, p.x);
}

std::string tempPath(const std::string& name)
{
	return (fs::temp_directory_path() / ("gv_carmen_test_" + name)).string();
}
}  // namespace

TEST(CarmenReader, IntelHeadMatchesTheFile)
{
	const LogData d = readLog(kIntel);
	ASSERT_EQ(d.scans.size(), 910u);
	const ScanRecord& r = d.scans.front();
	// FLASER 180 1.23 ... 0.600266 -0.0320327 -0.354665 0.600266 -0.0320327 -0.354665 32.9068 pippo 32.9068
	EXPECT_DOUBLE_EQ(r.timestamp, 32.9068);
	EXPECT_DOUBLE_EQ(d.scans[1].timestamp, 35.1051);
	ASSERT_TRUE(r.hasLogPose && r.hasOdometry);
	EXPECT_NEAR(r.logPose.x, 0.600266, 1e-9);
	EXPECT_NEAR(r.logPose.y, -0.0320327, 1e-9);
	EXPECT_NEAR(r.logPose.phi, -0.354665, 1e-9);
	ASSERT_EQ(r.scan->getScanSize(), 180u);
	EXPECT_FLOAT_EQ(r.scan->getScanRange(0), 1.09f);
	EXPECT_FLOAT_EQ(r.scan->getScanRange(179), 1.23f);
	EXPECT_NEAR(r.scan->aperture, 179 * kDeg, 1e-6);  // 180 beams at 1 deg
	EXPECT_NEAR(r.scan->sensorPose.yaw(), -0.5 * kDeg, 1e-9);  // first beam at -90 deg
	EXPECT_TRUE(r.scan->rightToLeft);
	EXPECT_NEAR(r.scan->maxRange, 81.83, 1e-4);  // no PARAM: the log's "no return" value
	EXPECT_NEAR(mrpt::Clock::toDouble(r.scan->timestamp), r.timestamp, 1e-6);
	// the 81.83 readings are "no return", the others valid
	size_t noReturn = 0, valid = 0;
	for (const auto& s : d.scans)
		for (size_t i = 0; i < s.scan->getScanSize(); i++)
		{
			const bool isMax = s.scan->getScanRange(i) >= 81.8f;
			noReturn += isMax;
			valid += s.scan->getScanRangeValidity(i);
			EXPECT_NE(isMax, s.scan->getScanRangeValidity(i));
		}
	EXPECT_EQ(noReturn, 4172u);
	EXPECT_EQ(valid, 910u * 180u - 4172u);
	EXPECT_NE(d.summary.find("910 FLASER"), std::string::npos);
	EXPECT_NE(d.summary.find("14541 ODOM"), std::string::npos);
	EXPECT_NE(d.summary.find("910 NEFF ignored"), std::string::npos);
}

TEST(CarmenReader, ParamLinesSetResolutionFovAndMaxRange)
{
	const LogData c = readLog(kCsail);  // PARAM resolution 0.5, fov 3.14159 (rad), front_laser_max 50
	ASSERT_EQ(c.scans.size(), 406u);
	EXPECT_EQ(c.scans[0].scan->getScanSize(), 361u);
	EXPECT_NEAR(c.scans[0].scan->aperture, M_PI, 1e-5);
	EXPECT_NEAR(c.scans[0].scan->sensorPose.yaw(), 0.0, 1e-5);
	EXPECT_FLOAT_EQ(c.scans[0].scan->maxRange, 50.f);
	EXPECT_NE(c.summary.find("warning"), std::string::npos);  // its timestamps have 6 digits only

	const LogData f = readLog(kFreiburg);  // resolution 0.5, 360 beams, offset -0.04, max 80.99
	ASSERT_EQ(f.scans.size(), 292u);
	EXPECT_NEAR(f.scans[0].scan->aperture, 179.5 * kDeg, 1e-6);
	EXPECT_NEAR(f.scans[0].scan->sensorPose.x(), -0.04, 1e-9);
	EXPECT_FLOAT_EQ(f.scans[0].scan->maxRange, 80.99f);
	EXPECT_DOUBLE_EQ(f.scans[0].timestamp, 158.415);
}

TEST(CarmenReader, BeamLayoutFollowsCarmen)
{
	// 180 beams, no PARAM: 1 deg from -90 to +89
	LogData d = parse(kMax + flaser(180, 5.0));
	ASSERT_EQ(d.scans.size(), 1u);
	auto& s180 = *d.scans[0].scan;
	EXPECT_NEAR(beamAngle(s180, 0), -90 * kDeg, 1e-5);
	EXPECT_NEAR(beamAngle(s180, 179), 89 * kDeg, 1e-5);
	// 181 beams: -90..+90; 361: 0.5 deg; 360: -90..+89.5
	EXPECT_NEAR(parse(kMax + flaser(181, 5.0)).scans[0].scan->aperture, M_PI, 1e-6);
	auto s361 = parse(kMax + flaser(361, 5.0)).scans[0].scan;
	EXPECT_NEAR(beamAngle(*s361, 1), -89.5 * kDeg, 1e-5);
	EXPECT_NEAR(beamAngle(*s361, 360), 90 * kDeg, 1e-5);
	auto s360 = parse(kMax + flaser(360, 5.0)).scans[0].scan;
	EXPECT_NEAR(beamAngle(*s360, 0), -90 * kDeg, 1e-5);
	EXPECT_NEAR(beamAngle(*s360, 359), 89.5 * kDeg, 1e-5);
	// PARAM resolution + fov in degrees (as mkbench writes it) + offsets + flipped
	const std::string params =
		"PARAM laser_front_laser_resolution 0.5 h 0\nPARAM laser_front_laser_fov 90 h 0\n"
		"PARAM robot_front_laser_max 20 h 0\nPARAM robot_frontlaser_offset 0.3 h 0\n"
		"PARAM laser_front_laser_flipped 1 h 0\n";
	auto p = parse(params + flaser(181, 5.0)).scans[0].scan;
	EXPECT_NEAR(p->aperture, 90 * kDeg, 1e-6);
	EXPECT_FLOAT_EQ(p->maxRange, 20.f);
	EXPECT_NEAR(p->sensorPose.x(), 0.3, 1e-12);
	EXPECT_FALSE(p->rightToLeft);
	// flipped: beam 0 looks to the left (+45 deg), seen from the laser
	mrpt::obs::CObservation2DRangeScan centred = *p;
	centred.sensorPose = mrpt::poses::CPose3D(0, 0, 0, p->sensorPose.yaw(), 0, 0);
	EXPECT_NEAR(beamAngle(centred, 0), 45 * kDeg, 1e-5);
	EXPECT_NEAR(beamAngle(centred, 180), -45 * kDeg, 1e-5);
}

TEST(CarmenReader, PosesTimestampsAndValidity)
{
	const std::string text =
		"# comment\n\nPARAM robot_front_laser_max 8.0 h 0\n"
		"FLASER 5 1.0 0 8.0 9.5 2.5 1 2 0.5 3 4 0.25 10.5 host 10.75\n";
	const LogData d = parse(text);
	ASSERT_EQ(d.scans.size(), 1u);
	const ScanRecord& r = d.scans[0];
	EXPECT_DOUBLE_EQ(r.timestamp, 10.5);
	EXPECT_DOUBLE_EQ(r.logPose.x, 1);
	EXPECT_DOUBLE_EQ(r.logPose.phi, 0.5);
	EXPECT_DOUBLE_EQ(r.odometry.x, 3);
	EXPECT_DOUBLE_EQ(r.odometry.y, 4);
	EXPECT_DOUBLE_EQ(r.odometry.phi, 0.25);
	const bool expect[5] = {true, false, false, false, true};  // 0 and >= max are no return
	for (int i = 0; i < 5; i++) EXPECT_EQ(r.scan->getScanRangeValidity(i), expect[i]) << i;
}

TEST(CarmenReader, RobotLaserAndRawLaser)
{
	// ROBOTLASER1 type start fov res max acc mode n r.. m laser(3) robot(3) tv rv fs ss ta ts host lts
	const std::string robotLaser = "ROBOTLASER1 0 -1.5707963 3.1415926 0.0174533 30 0.01 0 181" +
								   std::string(181 * 4, ' ') +
								   " 0 "
								   "1.2 2 0 1 2 0 0 0 0 0 0 20.25 h 20.25\n";
	std::string rl = robotLaser;
	for (size_t i = 0, k = rl.find(" 181") + 4; i < 181; i++) rl.replace(k + 4 * i, 4, " 2.5");
	LogData d = parse(rl);
	ASSERT_EQ(d.scans.size(), 1u);
	EXPECT_NEAR(d.scans[0].scan->aperture, M_PI, 1e-5);
	EXPECT_FLOAT_EQ(d.scans[0].scan->maxRange, 30.f);
	EXPECT_NEAR(d.scans[0].scan->sensorPose.x(), 0.2, 1e-9);  // laser 0.2 m ahead of the robot
	EXPECT_DOUBLE_EQ(d.scans[0].odometry.x, 1);
	EXPECT_DOUBLE_EQ(d.scans[0].timestamp, 20.25);

	// RAWLASER1 has no pose: odometry comes from ODOM, interpolated at its time
	std::string raw =
		"ODOM 0 0 0 0 0 0 1.0 h 1.0\nODOM 2 0 1.0 0 0 0 3.0 h 3.0\n"
		"RAWLASER1 0 -1.5707963 3.1415926 0.0174533 30 0.01 0 3 1 2 3 0 2.0 h 2.0\n";
	d = parse(raw);
	ASSERT_EQ(d.scans.size(), 1u);
	ASSERT_TRUE(d.scans[0].hasOdometry);
	EXPECT_FALSE(d.scans[0].hasLogPose);
	EXPECT_NEAR(d.scans[0].odometry.x, 1.0, 1e-12);
	EXPECT_NEAR(d.scans[0].odometry.phi, 0.5, 1e-12);
}

TEST(CarmenReader, MalformedLinesNameFileAndLine)
{
	const std::string ok = flaser(5, 1.0);
	EXPECT_EQ(errorOf(ok + "FLASER 5 1 1 1 1 1 0 0 0 0 0 0\n"),
			  "mem.log:2: FLASER: 5 beams announced: expected 16 fields, found 13");
	// a beam count one too high or too low names the count, not a pose field read as a range
	EXPECT_EQ(errorOf("FLASER 6 1 1 1 1 1 -1.5 0 0 0 0 0 1 h 1\n"),
			  "mem.log:1: FLASER: 6 beams announced: expected 17 fields, found 16");
	EXPECT_EQ(errorOf("FLASER 4 1 1 1 1 1 -1.5 0 0 0 0 0 1 h 1\n"),
			  "mem.log:1: FLASER: 4 beams announced: expected 15 fields, found 16");
	EXPECT_EQ(errorOf("FLASER 5 1 nan 1 1 1 0 0 0 0 0 0 1 h 1\n"),
			  "mem.log:1: FLASER range 1 is 'nan' (not a finite number)");
	EXPECT_EQ(errorOf("\n\nFLASER 5 1 1 -2 1 1 0 0 0 0 0 0 1 h 1\n"), "mem.log:3: FLASER range 2 is -2 (negative)");
	EXPECT_EQ(errorOf("FLASER 3 1 inf 1 0 0 0 0 0 0 1 h 1\n"),
			  "mem.log:1: FLASER range 1 is 'inf' (not a finite number)");
	EXPECT_EQ(errorOf("FLASER x 1\n"), "mem.log:1: FLASER beam count is 'x' (not an integer)");
	EXPECT_EQ(errorOf("FLASER 400 1 2 3\n"), "mem.log:1: FLASER: 400 ranges announced, line has only 3 more fields");
	EXPECT_EQ(errorOf("ODOM 1 2 3\n"), "mem.log:1: ODOM: expected 10 fields, found 4");
	EXPECT_EQ(errorOf("ODOM 1 2 3 0 0 0 1e999 h 1\n"), "mem.log:1: ODOM timestamp is '1e999' (not a finite number)");
	EXPECT_EQ(errorOf("PARAM laser_front_laser_resolution fast h 0\n"),
			  "mem.log:1: PARAM laser_front_laser_resolution is 'fast' (not a finite number)");
	EXPECT_EQ(errorOf("PARAM robot_front_laser_max -3 h 0\n"),
			  "mem.log:1: PARAM robot_front_laser_max is -3 (must be > 0)");
	EXPECT_EQ(errorOf(ok + ok + "1.5 2.5 garbage\n"),
			  "mem.log:3: unrecognised line starting with '1.5' (not a CARMEN message)");
	EXPECT_EQ(errorOf("PARAM x\n"), "mem.log:1: PARAM: expected 'PARAM name value ...', found 2 fields");
	// unknown message types are not errors: they are counted
	const LogData d = parse("GPSNMEA 1 2 3\n" + ok);
	EXPECT_NE(d.summary.find("1 GPSNMEA ignored"), std::string::npos);
}

TEST(CarmenReader, GzipAndPlainGiveTheSameScansAndTruncationIsAnError)
{
	const std::vector<char> text = readFileBytes(kIntel);
	const std::string plain = tempPath("intel.log");
	writeFileAtomically(plain, [&](std::ostream& os) { os.write(text.data(), std::streamsize(text.size())); });
	const LogData a = readLog(kIntel), b = readLog(plain);
	ASSERT_EQ(a.scans.size(), b.scans.size());
	for (size_t i = 0; i < a.scans.size(); i += 97)
	{
		EXPECT_EQ(a.scans[i].timestamp, b.scans[i].timestamp);
		EXPECT_EQ(a.scans[i].scan->getScanRange(7), b.scans[i].scan->getScanRange(7));
	}
	// a gzip file cut short is reported, not silently read in part
	std::ifstream in(kIntel, std::ios::binary);
	std::vector<char> gz((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	const std::string cut = tempPath("cut.log.gz");
	writeFileAtomically(cut, [&](std::ostream& os) { os.write(gz.data(), std::streamsize(gz.size() / 2)); });
	try
	{
		readLog(cut);
		ADD_FAILURE() << "truncated gzip accepted";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()), cut + ": truncated or corrupt gzip data (CRC/length trailer mismatch)");
	}
	// a plain log cut inside a line: the last line has too few fields
	const std::string cutPlain = tempPath("cut.log");
	writeFileAtomically(cutPlain, [&](std::ostream& os) { os.write(text.data(), std::streamsize(text.size() / 3)); });
	EXPECT_THROW(readLog(cutPlain), std::runtime_error);
	EXPECT_THROW(readLog(tempPath("does-not-exist.log")), std::runtime_error);
	fs::remove(plain);
	fs::remove(cut);
	fs::remove(cutPlain);
}

namespace
{
std::string requireScansError(const LogData& d)
{
	try
	{
		requireScans(d);
	}
	catch (const std::runtime_error& e)
	{
		return e.what();
	}
	return "no error";
}
}  // namespace

TEST(CarmenReader, NoScansSaysWhatTheLogHolds)
{
	const LogData d = parse(
		"PARAM robot_front_laser_max 81 h 0\nODOM 0 0 0 0 0 0 1.0 h 1\nODOM 0.1 0 0 0 0 0 1.2 h 1\n"
		"GPSNMEA x 1 h 1\n");
	EXPECT_EQ(d.contents.odometryRecords, 2u);
	EXPECT_EQ(d.contents.paramLines, 1u);
	ASSERT_EQ(d.contents.ignored.size(), 1u);
	EXPECT_EQ(d.contents.ignored.at("GPSNMEA"), 1u);
	EXPECT_EQ(requireScansError(d), "mem.log: no laser scans (2 ODOM, 1 PARAM, 1 GPSNMEA ignored)");
	EXPECT_EQ(requireScansError(parse("")), "mem.log: no laser scans (0 ODOM, 0 PARAM)");
	// rear scans left out on request are what the file holds
	ReadOptions front;
	front.includeRearLaser = false;
	const std::string rear = "RLASER 3 1 1 1 0 0 0 0 0 0 1.5 h 1\n";
	const LogData r = parseCarmenLog(std::vector<char>(rear.begin(), rear.end()), "rear.log", front);
	EXPECT_EQ(requireScansError(r), "rear.log: no laser scans (0 ODOM, 0 PARAM, 1 RLASER ignored)");
	EXPECT_EQ(requireScansError(parse(rear)), "no error");
	// the summary says the same
	EXPECT_NE(d.summary.find("; 2 ODOM, 1 PARAM, 1 GPSNMEA ignored"), std::string::npos) << d.summary;
}

TEST(TrajectoryFile, RoundTripAndErrors)
{
	const std::string p = tempPath("traj.txt");
	Trajectory t = {{1.5, {1, 2, 0.5}}, {2.0, {-1, 0.25, -3.0}}};
	writeTrajectory(p, t);
	const Trajectory r = readTrajectory(p);
	ASSERT_EQ(r.size(), 2u);
	EXPECT_DOUBLE_EQ(r[1].first, 2.0);
	EXPECT_DOUBLE_EQ(r[1].second.y, 0.25);
	EXPECT_DOUBLE_EQ(r[1].second.phi, -3.0);
	writeFileAtomically(p, [](std::ostream& os) { os << "# t x y th\n1 2 3 4\n5 6 7\n"; });
	try
	{
		readTrajectory(p);
		ADD_FAILURE();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()), p + ":3: expected 't x y theta', found 3 fields");
	}
	EXPECT_THROW(writeTrajectory("/nonexistent-dir/x.txt", t), std::runtime_error);
	fs::remove(p);
}

TEST(TrajectoryFile, PosesAtScansByPositionOrByTime)
{
	// csail-corrected prints its timestamps with six digits: many scans share one time
	LogData log;
	for (double t : {100.0, 100.0, 100.0, 110.0})
	{
		ScanRecord r;
		r.timestamp = t;
		log.scans.push_back(r);
	}
	const Trajectory perScan = {{100, {0, 0, 0}}, {100, {1, 0, 0}}, {100, {2, 0, 0}}, {110, {3, 0, 0}}};
	auto p = posesAtScans(log, perScan, "est.txt");  // one pose per scan, in order: by position
	ASSERT_EQ(p.size(), 4u);
	for (size_t i = 0; i < 4; i++) EXPECT_DOUBLE_EQ(p[i]->x, double(i));
	// by time, the three poses at t = 100 could not be told apart: an error, not the first of them
	const Trajectory fewer = {{100, {0, 0, 0}}, {100, {1, 0, 0}}, {110, {3, 0, 0}}};
	try
	{
		posesAtScans(log, fewer, "est.txt");
		ADD_FAILURE() << "ambiguous match accepted";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(
			std::string(e.what()).rfind("est.txt: 2 different poses at t = 100.000000: scans cannot be matched", 0), 0u)
			<< e.what();
	}
	// unique times (here out of order, one repeated with the same pose): the nearest within maxDt
	const Trajectory byTime = {{110.02, {3, 0, 0}}, {100.01, {1, 0, 0}}, {100.01, {1, 0, 0}}};
	p = posesAtScans(log, byTime, "est.txt");
	EXPECT_DOUBLE_EQ(p[0]->x, 1);
	EXPECT_DOUBLE_EQ(p[3]->x, 3);
	p = posesAtScans(log, {{105, {5, 0, 0}}}, "est.txt");
	for (const auto& q : p) EXPECT_FALSE(q);  // nothing within 0.05 s
}

TEST(AtomicFile, NothingAppearsUntilCommit)
{
	const std::string p = tempPath("atomic.txt");
	fs::remove(p);
	{
		AtomicFile f(p);
		f.stream() << "hello";
		EXPECT_FALSE(fs::exists(p));
	}  // not committed: nothing written, temporary removed
	EXPECT_FALSE(fs::exists(p));
	for (const auto& e : fs::directory_iterator(fs::temp_directory_path()))
		EXPECT_EQ(e.path().filename().string().find(".gv_carmen_test_atomic.txt.tmp"), std::string::npos);
	writeFileAtomically(p, [](std::ostream& os) { os << "done"; });
	std::ifstream in(p);
	std::string s;
	in >> s;
	EXPECT_EQ(s, "done");
	try
	{
		AtomicFile bad("/proc/gv-no-such-dir/x.txt");
		ADD_FAILURE();
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()).rfind("/proc/gv-no-such-dir/x.txt: cannot write (", 0), 0u);
	}
	fs::remove(p);
}

TEST(NoReturnRange, SaturationBelowTheDeclaredMaximumIsNoReturn)
{
	// 81 m declared (as mkbench writes it), but the scanner reports "no return" as 50.00 m
	std::string text = "PARAM robot_front_laser_max 81 h 0\n";
	for (int t = 0; t < 200; ++t)
		text += "FLASER 3 1.5 " + std::string(t % 4 == 0 ? "50.00" : "20.25") + " 2.5 0 0 0 0 0 0 " +
				std::to_string(10 + t) + ".5 host 0\n";
	const std::string path = tempPath("saturation.log");
	writeFileAtomically(path, [&](std::ostream& os) { os << text; });
	const LogData d = readLog(path);
	ASSERT_EQ(d.scans.size(), 200u);
	EXPECT_FLOAT_EQ(d.scans[0].scan->maxRange, 50.f);
	EXPECT_DOUBLE_EQ(d.noReturnRange, 50.0);
	EXPECT_FALSE(d.scans[0].scan->getScanRangeValidity(1));  // 50 m: no return
	EXPECT_TRUE(d.scans[1].scan->getScanRangeValidity(1));  // 20.25 m: a hit
	ASSERT_EQ(d.warnings.size(), 1u);
	EXPECT_EQ(d.warnings[0],
			  "readings of 50.00 m and more (a spike at the top, in >= 1 % and >= 10 of the scans) are the "
			  "scanner's no-return value: max range 50.00 m instead of 81.00 m");
	// off: the declared maximum stands
	ReadOptions keep;
	keep.detectNoReturnRange = false;
	const LogData k = readLog(path, keep);
	EXPECT_FLOAT_EQ(k.scans[0].scan->maxRange, 81.f);
	EXPECT_TRUE(k.scans[0].scan->getScanRangeValidity(1));
	fs::remove(path);
}

TEST(NoReturnRange, RareLargestReadingIsAWall)
{
	// a wall's ranges spread as the robot moves (20.00-20.99 m), the farthest one seen once
	std::string text = "PARAM robot_front_laser_max 81 h 0\n";
	for (int t = 0; t < 200; ++t)
	{
		char wall[16];
		std::snprintf(wall, sizeof wall, "%.2f", 20.0 + 0.01 * (t % 100));
		text += "FLASER 3 1.5 " + std::string(t == 7 ? "50.00" : wall) + " 2.5 0 0 0 0 0 0 " +
				std::to_string(10 + t) + ".5 host 0\n";
	}
	const LogData d = parse(text);
	EXPECT_FALSE(saturationRange(d).has_value());  // 1 of 200 scans: below 1 %
	const std::string path = tempPath("rare.log");
	writeFileAtomically(path, [&](std::ostream& os) { os << text; });
	const LogData r = readLog(path);
	EXPECT_FLOAT_EQ(r.scans[7].scan->maxRange, 81.f);
	EXPECT_TRUE(r.scans[7].scan->getScanRangeValidity(1));
	EXPECT_TRUE(r.warnings.empty());
	fs::remove(path);
}

// A code that jitters (51.14-51.16 m, two stray readings above) and a second code (50.00 m) under real readings
// that thin out with range: both are no return, the real ones below stay hits.
TEST(NoReturnRange, JitteringCodesAtTheTopAreNoReturn)
{
	std::string text = "PARAM robot_front_laser_max 81 h 0\n";
	for (int t = 0; t < 400; ++t)
	{
		const char* code = t % 25 == 0 ? "50.00" : t % 3 == 0 ? "51.15" : t % 3 == 1 ? "51.14" : "51.16";
		char far[16];
		std::snprintf(far, sizeof far, "%.2f", 30.0 + 0.05 * (t % 360));  // 30-48 m, thinning above 40 m
		const char* stray = t == 5 ? "51.25" : t == 6 ? "51.20" : far;
		text += std::string("FLASER 4 1.5 ") + code + " " + (t % 2 ? far : stray) + " 2.5 0 0 0 0 0 0 " +
				std::to_string(10 + t) + ".5 host 0\n";
	}
	const LogData d = parse(text);
	ASSERT_TRUE(saturationRange(d).has_value());
	EXPECT_FLOAT_EQ(float(*saturationRange(d)), 50.0f);
	// and the real readings alone have none
	std::string real = "PARAM robot_front_laser_max 81 h 0\n";
	for (int t = 0; t < 400; ++t)
	{
		char far[16];
		std::snprintf(far, sizeof far, "%.2f", 30.0 + 0.05 * (t % 360));
		real += std::string("FLASER 3 1.5 ") + far + " 2.5 0 0 0 0 0 0 " + std::to_string(10 + t) + ".5 host 0\n";
	}
	EXPECT_FALSE(saturationRange(parse(real)).has_value());
}

TEST(NoReturnRange, TinyLogNeedsTenScansAtTheLargestReading)
{
	// 20 scans: one scan's 50.00 m is 5 % of them, yet a wall seen once (1 % alone took it as no return)
	auto text = [](int atTop) {
		std::string t = "PARAM robot_front_laser_max 81 h 0\n";
		for (int k = 0; k < 20; ++k)
		{
			char wall[16];  // a wall's ranges spread as the robot moves
			std::snprintf(wall, sizeof wall, "%.2f", 20.0 + 0.01 * k);
			t += "FLASER 3 1.5 " + std::string(k < atTop ? "50.00" : wall) + " 2.5 0 0 0 0 0 0 " +
				 std::to_string(10 + k) + ".5 host 0\n";
		}
		return t;
	};
	EXPECT_FALSE(saturationRange(parse(text(1))).has_value());
	EXPECT_FALSE(saturationRange(parse(text(9))).has_value());
	ASSERT_TRUE(saturationRange(parse(text(10))).has_value());
	EXPECT_DOUBLE_EQ(*saturationRange(parse(text(10))), 50.0);
	EXPECT_TRUE(saturationRange(parse(text(1)), 0.01, 1).has_value());  // the share alone
	// through readLog: the reading stays a hit, no warning
	const std::string path = tempPath("tiny.log");
	writeFileAtomically(path, [&](std::ostream& os) { os << text(1); });
	const LogData r = readLog(path);
	EXPECT_DOUBLE_EQ(r.noReturnRange, 0.0);
	EXPECT_FLOAT_EQ(r.scans[0].scan->maxRange, 81.f);
	EXPECT_TRUE(r.scans[0].scan->getScanRangeValidity(1));
	EXPECT_TRUE(r.warnings.empty());
	fs::remove(path);
}

TEST(CarmenReader, BinaryGarbageIsQuotedPrintablyInTheError)
{
	for (const std::string& text : {std::string("FLASER 3 1 \x1b[2J\x01\xff 3 0 0 0 0 0 0 1 h 1\n"),
									std::string("\x1b[2J") + std::string(500, 'A') + "\n"})
	{
		try
		{
			parse(text);
			ADD_FAILURE() << "accepted";
		}
		catch (const std::runtime_error& e)
		{
			const std::string msg = e.what();
			EXPECT_EQ(msg.rfind("mem.log:1: ", 0), 0u) << msg;
			for (char c : msg) EXPECT_TRUE(c >= 0x20 && c < 0x7f) << msg;
			EXPECT_NE(msg.find("\\x1b[2J"), std::string::npos) << msg;
			EXPECT_LT(msg.size(), 160u) << msg;
		}
	}
}

// issue 22: every number that sizes a geometry is bounded where it is read
TEST(CarmenReader, AbsurdParamsAndGeometryAreErrorsNamingTheLine)
{
	const std::string scan = flaser(180, 2.0);
	const auto starts = [](const std::string& err, const std::string& head) {
		return err.rfind(head, 0) == 0 ? ::testing::AssertionSuccess() : ::testing::AssertionFailure() << err;
	};
	EXPECT_TRUE(starts(errorOf("PARAM laser_front_laser_resolution 1e300\n" + scan),
					   "mem.log:1: PARAM laser_front_laser_resolution is 1e300 (at most 180 deg)"));
	EXPECT_TRUE(starts(errorOf("PARAM laser_front_laser_resolution 10\n" + scan),
					   "mem.log:2: FLASER: 180 beams at a resolution of 10 deg span more than 360 deg"));
	EXPECT_TRUE(
		starts(errorOf("PARAM laser_front_laser_fov 1e300\n" + scan), "mem.log:1: PARAM laser_front_laser_fov"));
	EXPECT_TRUE(starts(errorOf("PARAM robot_frontlaser_side_offset -1e308\n" + scan),
					   "mem.log:1: PARAM robot_frontlaser_side_offset is -1e308 (beyond +-10 m)"));
	EXPECT_TRUE(
		starts(errorOf("PARAM robot_frontlaser_offset 1e6\n" + scan), "mem.log:1: PARAM robot_frontlaser_offset"));
	EXPECT_TRUE(starts(errorOf("PARAM robot_front_laser_max 1e9\n" + scan),
					   "mem.log:1: PARAM robot_front_laser_max is 1e9 (at most 1000 m)"));
	EXPECT_TRUE(starts(errorOf(flaser(180, 2.0, "1e15 2 0.5 3 4 0.25 10.5 host 10.5")),
					   "mem.log:1: FLASER pose x is 1e15 (beyond +-1e+07 m)"));
	EXPECT_TRUE(starts(errorOf(flaser(180, 2.0, "0x1p3 2 0.5 3 4 0.25 10.5 host 10.5")),
					   "mem.log:1: FLASER pose x is '0x1p3' (not a finite number)"));
	EXPECT_TRUE(starts(errorOf("FLASER 100001 1\n"), "mem.log:1: FLASER beam count is 100001 (must be in 0..100000)"));
	// ROBOTLASER1: its own resolution, max range and laser pose
	const auto robotlaser = [](const std::string& res, const std::string& maxRange, const std::string& laserX) {
		std::string s = "ROBOTLASER1 0 -1.5708 3.14159 " + res + " " + maxRange + " 0.01 0 3 1 1 1 0 " + laserX +
						" 0 0 0 0 0 0 0 1 1 1 5.0 host 5.0\n";
		return s;
	};
	EXPECT_EQ(parse(robotlaser("0.0174533", "50", "0.1")).scans.size(), 1u);
	EXPECT_TRUE(
		starts(errorOf(robotlaser("1e300", "50", "0.1")), "mem.log:1: ROBOTLASER1: 3 beams at a resolution of"));
	EXPECT_TRUE(starts(errorOf(robotlaser("0", "50", "0.1")),
					   "mem.log:1: ROBOTLASER1: 3 beams at a resolution of 0 deg (must be > 0)"));
	EXPECT_TRUE(starts(errorOf(robotlaser("-0.01", "50", "0.1")), "mem.log:1: ROBOTLASER1: 3 beams"));
	EXPECT_TRUE(starts(errorOf(robotlaser("0.0174533", "1e300", "0.1")), "mem.log:1: ROBOTLASER1 max range is 1e300"));
	EXPECT_TRUE(starts(errorOf(robotlaser("0.0174533", "50", "1e6")),
					   "mem.log:1: ROBOTLASER1: the laser pose is 1e+06 m from the robot pose (at most 10 m)"));
}

TEST(CarmenReader, PipesAndFifosReadEveryByte)
{
	// a log longer than the 8 KiB a stream buffer takes: through a FIFO written by another thread
	std::string log = kMax;
	for (int i = 0; i < 40; i++) log += flaser(180, 2.0 + 0.01 * i);
	const fs::path fifo = fs::temp_directory_path() / "gv_carmen_fifo.log";
	fs::remove(fifo);
	ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
	std::thread writer([&] { std::ofstream(fifo) << log; });
	const LogData d = readCarmenLog(fifo.string());
	writer.join();
	EXPECT_EQ(d.scans.size(), 40u);
	// no writer at all: an error after the wait, not a hang in open()
	try
	{
		readCarmenLog(fifo.string());
		ADD_FAILURE() << "a FIFO without a writer was read";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()), fifo.string() + ": cannot read (a FIFO that no writer opened within 3 s)");
	}
	fs::remove(fifo);
}

TEST(CarmenReader, LineLongerThanTheLimitStopsTheRead)
{
	const fs::path p = fs::temp_directory_path() / "gv_carmen_longline.log";
	std::ofstream(p) << kMax << std::string(kMaxLineBytes + 10, '1') << "\n";
	try
	{
		readLog(p.string());
		ADD_FAILURE() << "a 4 MiB line was read";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_EQ(std::string(e.what()), p.string() + ":2: line longer than 4194304 bytes (the limit)");
	}
	fs::remove(p);
}
