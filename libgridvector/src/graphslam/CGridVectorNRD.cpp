#include "graphslam/CGridVectorNRD.h"
#include "graphslam/EngineEdge.h"
#include "graphslam/RegistrationConfig.h"
#include "posegraph/PoseGraph.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/core/format.h>
#include <mrpt/poses/CPose2D.h>

#include <sstream>

namespace gridvector::graphslam
{
using mrpt::math::TPose2D;
using mrpt::poses::CPose2D;

CGridVectorNRD::CGridVectorNRD() : extractor_(cfg_.extraction, cfg_.grid), slam_(std::make_unique<online::OnlineEmSlam>(cfg_))
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
	slam_ = std::make_unique<online::OnlineEmSlam>(cfg_);
	odometryOrigin_.reset();
	last_ = {};
	stats_ = {};
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

// Sec. 6: the scan into the online EM-SLAM; a new keyframe becomes a node.
bool CGridVectorNRD::processScan(const mrpt::obs::CObservation2DRangeScan& scan)
{
	LocalScan s = extractor_.extract(scan);
	s.scanIndex = int64_t(stats_.scans++);
	s.timestamp = scan.timestamp == INVALID_TIMESTAMP ? 0.0 : mrpt::Clock::toDouble(scan.timestamp);
	if (!odometryOrigin_) odometryOrigin_ = odometry_.pose();
	last_ = slam_->addScan(s, (CPose2D(odometry_.pose()) - CPose2D(*odometryOrigin_)).asTPose());
	const online::OnlineStep& st = last_;
	stats_.registered += st.registered;
	// the engine re-derives every node by Dijkstra after a step that registered one: back to the estimate
	const bool optimised = optimiseIfDue();
	const bool moved = optimised || newKeyframe_;
	newKeyframe_ = st.keyframe && slam_->keyframes().size() > 1;
	MRPT_LOG_DEBUG_FMT("scan %zu: %s%s%s, pose %s", stats_.scans, st.registered ? "registered" : "odometry",
					   st.keyframe ? ", keyframe" : "", optimised ? ", optimised" : "", st.pose.asString().c_str());
	if (!checkRegistrationCondition())
	{
		if (moved) placeNodes(0);
		return false;
	}
	registerKeyframe();
	placeNodes(moved ? 0 : this->m_graph->nodeCount() - 1);
	return true;
}

bool CGridVectorNRD::optimiseIfDue()
{
	if (!slam_->optimisationDue()) return false;
	slam_->optimise();
	++stats_.optimisations;
	return true;
}

// Eq. 20's odometry edge u between the previous keyframe and this one, in the error's frame as PoseGraph has it.
void CGridVectorNRD::registerKeyframe()
{
	if (this->m_prev_registered_nodeID == mrpt::graphs::INVALID_NODEID)
	{  // the root: the first scan, at the origin
		this->m_graph->nodes[this->m_graph->root] = graph_t::global_pose_t();
		this->m_prev_registered_nodeID = this->m_graph->root;
		++stats_.nodes;
	}
	const Poses& odo = slam_->keyframeOdometry();
	const size_t i = odo.size() - 1;
	const TPose2D z = (CPose2D(odo[i]) - CPose2D(odo[i - 1])).asTPose();
	this->registerNewNodeAtEnd(engineEdge(z, PoseGraph::odometryInformation(z, cfg_.posegraph)));
	++stats_.nodes;
}

void CGridVectorNRD::placeNodes(size_t from)
{
	const Poses& poses = slam_->keyframePoses();
	for (size_t k = from; k < poses.size() && k < this->m_graph->nodeCount(); ++k)
		this->m_graph->nodes[mrpt::graphs::TNodeID(k)] = CPose2D(poses[k]);
}

void CGridVectorNRD::finish()
{
	slam_->finish();
	++stats_.optimisations;
	placeNodes(0);
}

CGridVectorNRD::global_pose_t CGridVectorNRD::getCurrentRobotPosEstimation() const
{
	return slam_->scans() ? CPose2D(slam_->currentPose()) : global_pose_t();
}

void CGridVectorNRD::getDescriptiveReport(std::string* report_str) const
{
	std::ostringstream ss;
	ss << "Grid-vector node registration (online EM-SLAM) summary:\n" << std::string(80, '#') << "\n";
	params_.dumpToTextStream(ss);
	ss << mrpt::format("scans %zu: registered %zu, from odometry %zu; nodes %zu; optimisations %zu\n\n",
					   stats_.scans, stats_.registered, stats_.scans - stats_.registered, stats_.nodes,
					   stats_.optimisations);
	report_str->clear();
	parent_t::getDescriptiveReport(report_str);
	*report_str += ss.str();
	*report_str += this->m_time_logger.getStatsAsText() + "\n\n";
	*report_str += this->getLogAsString() + "\n";
}

}  // namespace gridvector::graphslam
