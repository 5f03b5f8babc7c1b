#include "io/ErrorText.h"
#include "io/FileBytes.h"
#include "io/InputLimits.h"
#include "io/OdometryTrack.h"
#include "io/RawlogPrecheck.h"
#include "io/Progress.h"
#include "io/RawlogReader.h"
#include "io/Counted.h"

#include <mrpt/io/CMemoryStream.h>
#include <mrpt/maps/registerAllClasses.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <map>
#include <stdexcept>

namespace gridvector::io
{
namespace
{
using namespace mrpt::obs;

class RawlogParser
{
   public:
	RawlogParser(std::string source, const ReadOptions& opt) : opt_(opt) { out_.source = std::move(source); }
	LogData parse(const std::vector<char>& bytes);

   private:
	void onObject(const mrpt::serialization::CSerializable::Ptr& obj);
	void onActions(const CActionCollection& acts);
	void onObservation(const CObservation::Ptr& obs, bool inFrame);
	void checkRanges(const CObservation2DRangeScan& s) const;
	void checkGeometry(const CObservation2DRangeScan& s) const;
	void checkPose(const mrpt::math::TPose2D& p, const char* what) const;
	void finish();
	[[noreturn]] void fail(const std::string& msg) const;

	ReadOptions opt_;
	LogData out_;
	size_t entry_ = 0;
	size_t noTimestamp_ = 0;
	OdometryTrack odomObs_;
	mrpt::poses::CPose2D cumulative_;
	bool hasMotion_ = false;
};

LogData RawlogParser::parse(const std::vector<char>& bytes)
{
	mrpt::io::CMemoryStream mem;
	mem.assignMemoryNotOwn(bytes.data(), bytes.size());
	auto arch = mrpt::serialization::archiveFrom(mem);
	Progress progress("reading " + out_.source, opt_.quiet);
	while (mem.getPosition() < bytes.size())
	{
		entry_++;
		mrpt::serialization::CSerializable::Ptr obj;
		const auto at = size_t(mem.getPosition());
		try
		{
			// MRPT's deserialisers trust the counts in the stream: check them in the bytes first
			precheckRawlogEntry(reinterpret_cast<const unsigned char*>(bytes.data()) + at, bytes.size() - at);
		}
		catch (const TruncatedEntry& e)
		{
			fail(e.what());
		}
		catch (const std::runtime_error& e)
		{
			fail(std::string("corrupt rawlog object (") + e.what() + ")");
		}
		try
		{
			arch >> obj;
		}
		catch (const mrpt::serialization::CExceptionEOF&)
		{
			fail("truncated or corrupt rawlog (this entry reads past the end of the file)");
		}
		catch (const std::exception& e)
		{
			if (mem.getPosition() >= bytes.size())
				fail("truncated or corrupt rawlog (this entry reads past the end of the file)");
			fail("corrupt rawlog object (" + gridvector::oneLineError(e) + ")");
		}
		onObject(obj);
		progress.update(double(mem.getPosition()) / double(bytes.size()), out_.scans.size());
	}
	progress.done();
	finish();
	return std::move(out_);
}

void RawlogParser::fail(const std::string& msg) const
{
	throw std::runtime_error(out_.source + ": entry " + std::to_string(entry_) + ": " + msg);
}

void RawlogParser::onObject(const mrpt::serialization::CSerializable::Ptr& obj)
{
	if (!obj) return void(out_.contents.ignored["null object"]++);
	if (auto acts = std::dynamic_pointer_cast<CActionCollection>(obj)) return onActions(*acts);
	if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(obj))
	{
		out_.contents.sensoryFrames++;
		for (const auto& o : *sf) onObservation(o, true);
		return;
	}
	if (auto o = std::dynamic_pointer_cast<CObservation>(obj)) return onObservation(o, false);
	out_.contents.ignored[obj->GetRuntimeClass()->className]++;
}

void RawlogParser::onActions(const CActionCollection& acts)
{
	out_.contents.actionSets++;
	const auto mov = acts.getActionByClass<CActionRobotMovement2D>();
	if (!mov) return;
	const bool odometry = mov->estimationMethod == CActionRobotMovement2D::emOdometry;
	if (!odometry && !mov->poseChange) fail("robot movement without a pose change (corrupt data?)");
	const mrpt::poses::CPose2D inc = odometry ? mov->rawOdometryIncrementReading : mov->poseChange->getMeanVal();
	checkPose(inc.asTPose(), "robot movement increment");
	cumulative_ = cumulative_ + inc;
	checkPose(cumulative_.asTPose(), "odometry (the sum of the robot movements)");
	hasMotion_ = true;
}

void RawlogParser::onObservation(const CObservation::Ptr& obs, bool inFrame)
{
	if (!inFrame) out_.contents.observations++;
	const double t = obs->timestamp == INVALID_TIMESTAMP ? 0.0 : mrpt::Clock::toDouble(obs->timestamp);
	if (auto odo = std::dynamic_pointer_cast<CObservationOdometry>(obs))
	{
		checkPose(odo->odometry.asTPose(), "odometry observation");
		return odomObs_.add(t, odo->odometry.asTPose());
	}
	auto scan = std::dynamic_pointer_cast<CObservation2DRangeScan>(obs);
	if (!scan) return void(out_.contents.ignored[obs->GetRuntimeClass()->className]++);
	if (!opt_.sensorLabel.empty() && scan->sensorLabel != opt_.sensorLabel)
		return void(out_.contents.ignored["scans of other sensors"]++);
	checkRanges(*scan);
	checkGeometry(*scan);
	if (obs->timestamp == INVALID_TIMESTAMP) noTimestamp_++;
	ScanRecord r;
	r.timestamp = t;
	r.scan = scan;
	r.odometry = cumulative_.asTPose();
	r.hasOdometry = hasMotion_;
	out_.scans.push_back(std::move(r));
}

/** Beams flagged valid must have a finite, non-negative range. */
void RawlogParser::checkRanges(const CObservation2DRangeScan& s) const
{
	if (s.getScanSize() == 0) fail("2D scan with 0 beams");  // as a CARMEN FLASER with none
	for (size_t i = 0; i < s.getScanSize(); i++)
	{
		const float r = s.getScanRange(i);
		if (s.getScanRangeValidity(i) && (!std::isfinite(r) || r < 0))
			fail("2D scan beam " + std::to_string(i) + " is valid with range " + std::to_string(r) +
				 " (corrupt data?)");
	}
	if (!std::isfinite(s.aperture) || s.aperture <= 0 || !std::isfinite(s.maxRange) || s.maxRange <= 0)
		fail("2D scan with aperture " + std::to_string(s.aperture) + " and max range " + std::to_string(s.maxRange) +
			 " (corrupt data?)");
}

/** The sensor pose, aperture and max range place every beam endpoint: bounded as the CARMEN reader's. */
void RawlogParser::checkGeometry(const CObservation2DRangeScan& s) const
{
	if (!(s.aperture <= kMaxApertureRad))
		fail("2D scan with an aperture of " + std::to_string(s.aperture) + " rad (at most 2 pi)");
	if (!(s.maxRange <= kMaxRangeLimit))
		fail("2D scan with a max range of " + std::to_string(s.maxRange) + " m (at most " +
			 std::to_string(int(kMaxRangeLimit)) + " m)");
	const auto& p = s.sensorPose;
	const double offset = std::sqrt(p.x() * p.x() + p.y() * p.y() + p.z() * p.z());
	if (!(offset <= kMaxSensorOffset) || !std::isfinite(p.yaw()) || !std::isfinite(p.pitch()) ||
		!std::isfinite(p.roll()))
		fail("2D scan with its sensor at (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) + ", " +
			 std::to_string(p.z()) + ") m, yaw " + std::to_string(p.yaw()) + " (at most " +
			 std::to_string(int(kMaxSensorOffset)) + " m from the robot)");
}

void RawlogParser::checkPose(const mrpt::math::TPose2D& p, const char* what) const
{
	if (std::abs(p.x) <= kMaxCoordinate && std::abs(p.y) <= kMaxCoordinate && std::abs(p.phi) <= kMaxAngle) return;
	fail(std::string(what) + " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.phi) +
		 ") is not finite or beyond +-" + std::to_string(int(kMaxCoordinate)) + " m");
}

void RawlogParser::finish()
{
	if (hasMotion_)  // scans before the first action: the robot has not moved yet
		for (auto& r : out_.scans) r.hasOdometry = true;
	if (!odomObs_.empty())
		for (auto& r : out_.scans)
		{
			r.odometry = *odomObs_.at(r.timestamp);
			r.hasOdometry = true;
		}
	size_t backwards = 0;  // as the CARMEN reader: scans are used in file order, said when time disagrees
	for (size_t i = 1; i < out_.scans.size(); i++) backwards += out_.scans[i].timestamp <= out_.scans[i - 1].timestamp;
	if (backwards > 0 && noTimestamp_ < out_.scans.size())
		out_.warnings.push_back(counted(backwards, "scan timestamp") + " " + agree(backwards, "does", "do") +
								" not increase (unsorted or repeated timestamps in the file)");
	if (noTimestamp_)
		out_.warnings.push_back(counted(noTimestamp_, "scan") + " " + agree(noTimestamp_, "has", "have") +
								" no timestamp (set to 0)");
	if (out_.scans.empty()) out_.warnings.push_back("no 2D laser scans in the file");
	out_.contents.format = LogContents::Format::Rawlog;
	out_.contents.odometryRecords = odomObs_.size();
	out_.contents.movementActions = hasMotion_;
	std::string s = out_.source + ": " + counted(out_.scans.size(), "scan") + "; " + describeContents(out_.contents);
	for (const auto& w : out_.warnings) s += "; warning: " + w;
	out_.summary = s;
}
}  // namespace

LogData parseRawlog(const std::vector<char>& bytes, const std::string& source, const ReadOptions& opt)
{
	mrpt::maps::registerAllClasses_mrpt_maps();  // observation classes that live in mrpt-maps
	RawlogParser p(source, opt);
	return p.parse(bytes);
}

LogData readRawlog(const std::string& path, const ReadOptions& opt)
{
	ReadLimits lim;
	lim.onHead = [path](std::string_view head) -> size_t {
		if (!head.empty() && head[0] == '\0')
			throw std::runtime_error(path + ": not an MRPT rawlog (it starts with a NUL byte)");
		return 0;
	};
	return parseRawlog(readFileBytes(path, nullptr, lim), path, opt);
}

}  // namespace gridvector::io
