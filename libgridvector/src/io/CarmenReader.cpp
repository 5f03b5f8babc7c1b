#include "io/CarmenParams.h"
#include "io/CarmenReader.h"
#include "io/Counted.h"
#include "io/FileBytes.h"
#include "io/InputLimits.h"
#include "io/OdometryTrack.h"
#include "io/Progress.h"
#include "io/TextParsing.h"

#include <mrpt/core/Clock.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/poses/CPose3D.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <string>

namespace gridvector::io
{
namespace
{
using Tokens = std::vector<std::string_view>;
using mrpt::math::TPose2D;

std::string str(std::string_view s) { return std::string(s); }

std::string fmt(const char* f, double v)
{
	char b[64];
	std::snprintf(b, sizeof b, f, v);
	return b;
}

/** What a scan message contributes before the max range is known. */
struct ScanMessage
{
	std::string type;
	std::vector<float> ranges;
	BeamLayout layout;
	mrpt::poses::CPose3D sensorPose;
	bool flipped = false;
	std::optional<double> maxRange;  //!< unset: inferred from the log's readings
};

class CarmenParser
{
   public:
	CarmenParser(std::string source, const ReadOptions& opt) : opt_(opt)
	{
		pos_.file = source;
		out_.source = std::move(source);
	}
	LogData parse(const std::vector<char>& text);

   private:
	void dispatch(const Tokens& t);
	void onParam(const Tokens& t);
	void onOdom(const Tokens& t);
	void onFlaser(const Tokens& t, bool rear);
	void onRobotLaser(const Tokens& t);
	void onRawLaser(const Tokens& t, int which);
	ScanMessage laserMessage(const Tokens& t, size_t timestampAfterTail, size_t& tail, double& ts);
	void onOther(const Tokens& t);

	double timestampAfter(const Tokens& t, size_t base, const std::string& what);
	void requireAperture(const BeamLayout& b, size_t n, const std::string& what);
	TPose2D poseAt(const Tokens& t, size_t i, const std::string& what);
	std::vector<float> ranges(const Tokens& t, size_t first, size_t n, const std::string& what);
	size_t count(const Tokens& t, size_t i, const std::string& what);
	void addScan(ScanMessage m, double t);
	void finish();
	std::string summary() const;

	ReadOptions opt_;
	TextPos pos_;
	CarmenParams params_;
	LogData out_;
	std::vector<ScanMessage> pending_;  //!< parallel to out_.scans
	std::vector<size_t> needOdometry_;  //!< RAWLASER scans: odometry from ODOM lines
	OdometryTrack odom_;
	std::map<std::string, size_t> scans_;
	double maxReading_ = 0;
	double inferredMax_ = 0;
	std::set<std::string> layouts_;
};

LogData CarmenParser::parse(const std::vector<char>& text)
{
	Progress progress("reading " + pos_.file, opt_.quiet);
	LineCursor cur(text);
	std::string_view line;
	while (cur.next(line))
	{
		pos_.line = cur.lineNumber();
		const Tokens t = splitTokens(line);
		if (t.empty() || t[0][0] == '#') continue;
		dispatch(t);
		if ((pos_.line & 4095) == 0) progress.update(cur.fractionDone(), out_.scans.size());
	}
	progress.done();
	finish();
	return std::move(out_);
}

void CarmenParser::dispatch(const Tokens& t)
{
	const std::string_view k = t[0];
	if (k == "PARAM")
		onParam(t);
	else if (k == "ODOM")
		onOdom(t);
	else if (k == "FLASER")
		onFlaser(t, false);
	else if (k == "RLASER")
		onFlaser(t, true);
	else if (k == "ROBOTLASER1" || k == "ROBOTLASER2")
		onRobotLaser(t);
	else if (k.size() == 9 && k.substr(0, 8) == "RAWLASER" && k[8] >= '1' && k[8] <= '4')
		onRawLaser(t, k[8] - '0');
	else
		onOther(t);
}

void CarmenParser::onOther(const Tokens& t)
{
	const std::string_view k = t[0];
	const bool identifier =
		std::isupper(static_cast<unsigned char>(k[0])) && std::all_of(k.begin(), k.end(), [](char c) {
			return std::isupper(static_cast<unsigned char>(c)) || std::isdigit(static_cast<unsigned char>(c)) ||
				   c == '_';
		});
	if (!identifier)
		parseError(pos_, "unrecognised line starting with '" + printableToken(k) + "' (not a CARMEN message)");
	out_.contents.ignored[str(k)]++;
}

void CarmenParser::onParam(const Tokens& t)
{
	if (t.size() < 3)
		parseError(pos_, "PARAM: expected 'PARAM name value ...', found " + io::counted(t.size(), "field"));
	params_.apply(t[1], t[2], pos_);
	out_.contents.paramLines++;
}

/** The message's trailer is "timestamp host logger_timestamp" (or just "timestamp"). */
double CarmenParser::timestampAfter(const Tokens& t, size_t base, const std::string& what)
{
	if (t.size() != base + 3 && t.size() != base + 1)
		parseError(pos_, what + ": expected " + io::counted(base + 3, "field") + ", found " + std::to_string(t.size()));
	return parseDouble(t[base], pos_, what + " timestamp");
}

TPose2D CarmenParser::poseAt(const Tokens& t, size_t i, const std::string& what)
{
	return TPose2D(parseBounded(t[i], pos_, what + " x", kMaxCoordinate, "m"),
				   parseBounded(t[i + 1], pos_, what + " y", kMaxCoordinate, "m"),
				   parseBounded(t[i + 2], pos_, what + " theta", kMaxAngle, "rad"));
}

size_t CarmenParser::count(const Tokens& t, size_t i, const std::string& what)
{
	if (i >= t.size()) parseError(pos_, what + ": line ends early (" + counted(t.size(), "field") + ")");
	return size_t(parseInt(t[i], pos_, what, 0, long(kMaxBeams)));
}

/** n beams at the layout's resolution must fit in one turn (else MRPT's beam angles overflow). */
void CarmenParser::requireAperture(const BeamLayout& b, size_t n, const std::string& what)
{
	if (b.resolution > 0 && b.aperture <= kMaxApertureRad) return;
	parseError(pos_, what + ": " + counted(n, "beam") + " at a resolution of " +
						 fmt("%g deg", b.resolution * 180 / M_PI) +
						 (b.resolution > 0 ? " span more than 360 deg" : " (must be > 0)"));
}

std::vector<float> CarmenParser::ranges(const Tokens& t, size_t first, size_t n, const std::string& what)
{
	if (first + n > t.size())
		parseError(pos_, what + ": " + counted(n, "range") + " announced, line has only " +
							 counted(t.size() - std::min(first, t.size()), "more field"));
	std::vector<float> r(n);
	for (size_t i = 0; i < n; i++)
	{
		const double v = parseDouble(t[first + i], pos_, what + " range " + std::to_string(i));
		if (v < 0) parseError(pos_, what + " range " + std::to_string(i) + " is " + str(t[first + i]) + " (negative)");
		r[i] = float(v);
	}
	return r;
}

void CarmenParser::onOdom(const Tokens& t)
{
	const double ts = timestampAfter(t, 7, "ODOM");
	odom_.add(ts, poseAt(t, 1, "ODOM"));
	out_.contents.odometryRecords++;
}

void CarmenParser::onFlaser(const Tokens& t, bool rear)
{
	if (rear && !opt_.includeRearLaser) return void(out_.contents.ignored[str(t[0])]++);
	const std::string what = str(t[0]);
	const size_t n = count(t, 1, what + " beam count");
	if (n == 0) parseError(pos_, what + ": zero beams");
	const CarmenLaserParams& lp = rear ? params_.rear() : params_.front();
	// a wrong beam count shifts every field: say so, not "range 181 is -1.6" (the pose's x read as a range)
	const size_t trailer = 2 + n + 6;
	if (t.size() >= 2 + n && !flaserFieldCountMatches(n, t.size()))
		parseError(pos_, what + ": " + counted(n, "beam") + " announced: expected " + counted(trailer + 3, "field") +
							 ", found " + std::to_string(t.size()));
	ScanMessage m;
	m.type = what;
	m.ranges = ranges(t, 2, n, what);
	const double ts = timestampAfter(t, trailer, what);
	m.layout = carmenBeamLayout(n, lp);
	requireAperture(m.layout, n, what);
	m.flipped = lp.flipped;
	m.maxRange = lp.maxRange;
	const double yaw = lp.offsetYaw + (rear ? M_PI : 0.0) + (lp.flipped ? -m.layout.yawOffset : m.layout.yawOffset);
	m.sensorPose = mrpt::poses::CPose3D(lp.offsetX, lp.offsetY, 0, yaw, 0, 0);
	addScan(std::move(m), ts);
	ScanRecord& r = out_.scans.back();
	r.logPose = poseAt(t, 2 + n, what + " pose");
	r.odometry = poseAt(t, 2 + n + 3, what + " odometry");
	r.hasLogPose = r.hasOdometry = true;
}

/** The head ROBOTLASERx and RAWLASERx share: type start fov res max accuracy remission_mode n
 * [ranges] m [remissions]. `tail`: the index of the first token after it; `ts`: the timestamp
 * after the `timestampAfterTail` tokens that follow (parsed before the ranges, as errors are
 * reported in token order of the checks). The message has no sensor pose yet. */
ScanMessage CarmenParser::laserMessage(const Tokens& t, size_t timestampAfterTail, size_t& tail, double& ts)
{
	const std::string what = str(t[0]);
	const size_t n = count(t, 8, what + " beam count");
	const size_t m = count(t, 9 + n, what + " remission count");
	tail = 10 + n + m;
	ts = timestampAfter(t, tail + timestampAfterTail, what);
	ScanMessage s;
	s.type = what;
	s.ranges = ranges(t, 9, n, what);
	s.layout = explicitBeamLayout(n, parseBounded(t[2], pos_, what + " start angle", kMaxAngle, "rad"),
								  parseDouble(t[4], pos_, what + " resolution"));
	requireAperture(s.layout, n, what);
	const double maxR = parseBounded(t[5], pos_, what + " max range", kMaxRangeLimit, "m");
	if (maxR > 0) s.maxRange = maxR;
	return s;
}

/** ROBOTLASERx head (laserMessage), then
 *  laser_x laser_y laser_theta robot_x robot_y robot_theta tv rv fwd_safety side_safety turn_axis ts host lts */
void CarmenParser::onRobotLaser(const Tokens& t)
{
	size_t posesAt = 0;
	double ts = 0;
	ScanMessage s = laserMessage(t, 11, posesAt, ts);
	const TPose2D laser = poseAt(t, posesAt, s.type + " laser pose");
	const TPose2D robot = poseAt(t, posesAt + 3, s.type + " robot pose");
	const mrpt::poses::CPose2D rel = mrpt::poses::CPose2D(laser) - mrpt::poses::CPose2D(robot);
	if (!(rel.norm() <= kMaxSensorOffset))
		parseError(pos_, s.type + ": the laser pose is " + fmt("%g m", rel.norm()) + " from the robot pose (at most " +
							 fmt("%g m", kMaxSensorOffset) + ")");
	s.sensorPose = mrpt::poses::CPose3D(rel.x(), rel.y(), 0, rel.phi() + s.layout.yawOffset, 0, 0);
	addScan(std::move(s), ts);
	ScanRecord& r = out_.scans.back();
	r.logPose = r.odometry = robot;
	r.hasLogPose = r.hasOdometry = true;
}

/** RAWLASERx head (laserMessage), then ts host lts */
void CarmenParser::onRawLaser(const Tokens& t, int which)
{
	if (which == 2 && !opt_.includeRearLaser) return void(out_.contents.ignored[str(t[0])]++);
	size_t tail = 0;
	double ts = 0;
	ScanMessage s = laserMessage(t, 0, tail, ts);
	const CarmenLaserParams* lp = which == 1 ? &params_.front() : which == 2 ? &params_.rear() : nullptr;
	const double yaw = (which == 2 ? M_PI : 0.0) + (lp ? lp->offsetYaw : 0.0) + s.layout.yawOffset;
	s.sensorPose = mrpt::poses::CPose3D(lp ? lp->offsetX : 0, lp ? lp->offsetY : 0, 0, yaw, 0, 0);
	addScan(std::move(s), ts);
	needOdometry_.push_back(out_.scans.size() - 1);
}

void CarmenParser::addScan(ScanMessage m, double t)
{
	if (!m.maxRange)
		for (float r : m.ranges) maxReading_ = std::max(maxReading_, double(r));
	ScanRecord rec;
	rec.timestamp = t;
	scans_[m.type]++;
	out_.scans.push_back(std::move(rec));
	pending_.push_back(std::move(m));
}

void CarmenParser::finish()
{
	inferredMax_ = std::min(maxReading_, kSickErrorCodeRange);
	for (size_t i = 0; i < out_.scans.size(); i++)
	{
		ScanMessage& m = pending_[i];
		ScanRecord& r = out_.scans[i];
		const double maxRange = m.maxRange.value_or(inferredMax_);
		auto s = mrpt::obs::CObservation2DRangeScan::Create();
		s->sensorLabel = m.type;
		s->timestamp = mrpt::Clock::fromDouble(r.timestamp);
		s->aperture = float(m.layout.aperture);
		s->rightToLeft = !m.flipped;
		s->maxRange = float(maxRange);
		s->sensorPose = m.sensorPose;
		s->resizeScan(m.ranges.size());
		for (size_t k = 0; k < m.ranges.size(); k++)
		{
			s->setScanRange(k, m.ranges[k]);
			s->setScanRangeValidity(k, m.ranges[k] > 0 && m.ranges[k] < maxRange);
		}
		r.scan = s;
		layouts_.insert(std::to_string(m.ranges.size()) + " beams" +
						fmt(" over %.2f deg", m.layout.aperture * 180 / M_PI) +
						(m.layout.resolutionInferred ? " (resolution inferred)" : "") +
						fmt(", max range %.2f m", maxRange) + (m.maxRange ? "" : " (inferred from the readings)"));
	}
	for (size_t i : needOdometry_)
		if (auto p = odom_.at(out_.scans[i].timestamp))
		{
			out_.scans[i].odometry = *p;
			out_.scans[i].hasOdometry = true;
		}
	size_t backwards = 0;
	for (size_t i = 1; i < out_.scans.size(); i++)
		if (out_.scans[i].timestamp <= out_.scans[i - 1].timestamp) backwards++;
	if (backwards)
		out_.warnings.push_back(counted(backwards, "scan timestamp") + " " + agree(backwards, "does", "do") +
								" not increase (low-precision or unsorted timestamps in the file)");
	if (out_.scans.empty()) out_.warnings.push_back("no laser scans in the file");
	pending_.clear();
	out_.summary = summary();
}

std::string CarmenParser::summary() const
{
	std::string s = out_.source + ": " + counted(out_.scans.size(), "scan") + " (";
	bool first = true;
	for (const auto& [k, n] : scans_) s += (first ? "" : ", ") + std::to_string(n) + " " + k, first = false;
	s += ")";
	for (const auto& l : layouts_) s += "; " + l;
	s += "; " + describeContents(out_.contents);
	for (const auto& w : out_.warnings) s += "; warning: " + w;
	return s;
}
}  // namespace

bool flaserFieldCountMatches(size_t beams, size_t fields)
{
	const size_t trailer = 2 + beams + 6;  // name, count, ranges, laser pose, odometry pose
	return fields == trailer + 3 || fields == trailer + 1;
}

LogData parseCarmenLog(const std::vector<char>& text, const std::string& source, const ReadOptions& opt)
{
	CarmenParser p(source, opt);
	return p.parse(text);
}

LogData readCarmenLog(const std::string& path, const ReadOptions& opt)
{
	ReadLimits lim;
	lim.onHead = [](std::string_view) { return kMaxLineBytes; };
	return parseCarmenLog(readFileBytes(path, nullptr, lim), path, opt);
}

}  // namespace gridvector::io
