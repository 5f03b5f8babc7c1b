#include "posegraph/PoseGraph.h"
#include "graphslam/CGridVectorNRD.h"
#include "graphslam/RegistrationConfig.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/core/format.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/system/filesystem.h>

#include <cmath>
#include <sstream>

namespace gridvector::graphslam
{
using mrpt::math::TPose2D;
using mrpt::poses::CPose2D;

namespace
{
TPose2D relative(const TPose2D& from, const TPose2D& to) { return (CPose2D(to) - CPose2D(from)).asTPose(); }
TPose2D compose(const TPose2D& a, const TPose2D& b) { return (CPose2D(a) + CPose2D(b)).asTPose(); }
constexpr double kWeak = 1e-6;  // information scale of a prior that must not bias the match
}  // namespace

CGridVectorNRD::CGridVectorNRD() : extractor_(cfg_.extraction, cfg_.grid), matcher_(cfg_.matcher)
{
	this->initializeLoggers("CGridVectorNRD");
	this->setMinLoggingLevel(mrpt::system::VerbosityLevel(params_.classVerbosity));
}

void CGridVectorNRD::loadParams(const std::string& source_fname)
{
	parent_t::loadParams(source_fname);
	requireConfigFile(source_fname);
	mrpt::config::CConfigFile cfg(source_fname);
	loadOptions(cfg, source_fname);
}

void CGridVectorNRD::loadOptions(const mrpt::config::CConfigFileBase& cfg, const std::string& sourceName)
{
	params_.load(cfg, sourceName);
	cfg_ = loadRegistrationConfig(cfg, sourceName);
	extractor_ = VectorExtractor(cfg_.extraction, cfg_.grid);
	matcher_ = VectorMatcher(cfg_.matcher);
	this->setMinLoggingLevel(mrpt::system::VerbosityLevel(params_.classVerbosity));
}

void CGridVectorNRD::printParams() const
{
	parent_t::printParams();
	params_.dumpToConsole();
}

bool CGridVectorNRD::updateState(mrpt::obs::CActionCollection::Ptr action, mrpt::obs::CSensoryFrame::Ptr observations,
								 mrpt::obs::CObservation::Ptr observation)
{
	mrpt::system::CTimeLoggerEntry timer(this->m_time_logger, "updateState");
	odometry_.update(action, observations, observation);
	const auto scan = scanOf(observations, observation);
	return scan && processScan(*scan);
}

PoseEstimate CGridVectorNRD::odometryPrior(const TPose2D& prediction) const
{
	Eigen::Matrix3d info = PoseGraph::odometryInformation(relative(odomAtNode_, odometry_.pose()), cfg_.posegraph);
	if (!odometry_.seen() || !params_.useOdometry) info *= kWeak;
	return {prediction, info};
}

// Sec. 4.2: register the scan's vectors against the last node's, fuse with odometry.
bool CGridVectorNRD::processScan(const mrpt::obs::CObservation2DRangeScan& scan)
{
	++stats_.scans;
	std::vector<MatchSegment> segs = MatchSegment::fromVectors(extractor_.extract(scan).vectors);
	const TPose2D odom = odometry_.pose();
	if (!haveKeyframe_)
	{
		keyframe_ = std::move(segs);
		haveKeyframe_ = true;
		odomAtNode_ = odomAtScan_ = odom;
		since_ = {};
		return false;
	}
	const TPose2D prediction = compose(since_.mean, relative(odomAtScan_, odom));
	odomAtScan_ = odom;
	const PoseEstimate prior = odometryPrior(prediction);
	since_ = prior;
	const MatchResult r = matcher_.match(keyframe_, segs, prediction);
	if (!r.ok())
		++stats_.failed;
	else if (!closeTo(prediction, r.pose, params_.maxCorrectionDistance, params_.maxCorrectionAngleDeg * M_PI / 180) ||
			 !validInformation(r.information))
		++stats_.implausible;
	else
	{
		++stats_.matched;
		since_ = fuse(prior, PoseEstimate{r.pose, r.information});
	}
	MRPT_LOG_DEBUG_FMT("scan %zu: %s, since node %s", stats_.scans, toString(r.status), since_.mean.asString().c_str());
	// fused over the relative pose's parameters, both terms; the edge in the error's frame
	this->m_since_prev_node_PDF = toConstraint(since_, cfg_.mstep.informationInEdgeFrame);
	if (!checkRegistrationCondition()) return false;
	registerNode(std::move(segs));
	odomAtNode_ = odom;
	return true;
}

bool CGridVectorNRD::checkRegistrationCondition()
{
	const TPose2D& d = since_.mean;
	return std::hypot(d.x, d.y) > params_.registrationMaxDistance ||
		   std::abs(d.phi) > params_.registrationMaxAngleDeg * M_PI / 180;
}

void CGridVectorNRD::registerNode(std::vector<MatchSegment>&& keyframe)
{
	if (this->m_prev_registered_nodeID == mrpt::graphs::INVALID_NODEID)
	{  // the root: origin of the map, with the first scan
		this->m_graph->nodes[this->m_graph->root] = graph_t::global_pose_t();
		this->m_prev_registered_nodeID = this->m_graph->root;
		++stats_.nodes;
	}
	this->registerNewNodeAtEnd();  // edge = m_since_prev_node_PDF, then reset
	++stats_.nodes;
	keyframe_ = std::move(keyframe);
	since_ = {};
}

void CGridVectorNRD::getDescriptiveReport(std::string* report_str) const
{
	std::ostringstream ss;
	ss << "Grid-vector node registration (vector matching + odometry) summary:\n" << std::string(80, '#') << "\n";
	params_.dumpToTextStream(ss);
	ss << mrpt::format("scans %zu: matched %zu, match rejected %zu, implausible %zu; nodes %zu\n\n", stats_.scans,
					   stats_.matched, stats_.failed, stats_.implausible, stats_.nodes);
	report_str->clear();
	parent_t::getDescriptiveReport(report_str);
	*report_str += ss.str();
	*report_str += this->m_time_logger.getStatsAsText() + "\n\n";
	*report_str += this->getLogAsString() + "\n";
}

}  // namespace gridvector::graphslam
