#include "graphslam/CGridVectorERD.h"
#include "graphslam/EngineEdge.h"
#include "graphslam/RegistrationConfig.h"
#include "mstep/GraphOptimisation.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/core/format.h>

#include <sstream>
#include <stdexcept>

namespace gridvector::graphslam
{
CGridVectorERD::CGridVectorERD()
{
	this->initializeLoggers("CGridVectorERD");
	this->setMinLoggingLevel(mrpt::system::VerbosityLevel(params_.classVerbosity));
}

void CGridVectorERD::loadParams(const std::string& source_fname)
{
	parent_t::loadParams(source_fname);
	requireConfigFile(source_fname);
	mrpt::config::CConfigFile cfg(source_fname);
	loadOptions(cfg, source_fname);
}

void CGridVectorERD::loadOptions(const mrpt::config::CConfigFileBase& cfg, const std::string& sourceName)
{
	params_.load(cfg, sourceName);
	if (!params_.ignoredKeyNote.empty()) MRPT_LOG_WARN(params_.ignoredKeyNote);
	this->setMinLoggingLevel(mrpt::system::VerbosityLevel(params_.classVerbosity));
}

void CGridVectorERD::printParams() const
{
	parent_t::printParams();
	params_.dumpToConsole();
}

const online::OnlineEmSlam& CGridVectorERD::online() const
{
	if (!nrd_)
		throw std::logic_error(
			"CGridVectorERD needs the node decider CGridVectorNRD (its edges are that decider's online EM-SLAM's); "
			"link them with gridvector::graphslam::linkDeciders");
	return nrd_->online();
}

bool CGridVectorERD::updateState(mrpt::obs::CActionCollection::Ptr, mrpt::obs::CSensoryFrame::Ptr,
								 mrpt::obs::CObservation::Ptr)
{
	mrpt::system::CTimeLoggerEntry timer(this->m_time_logger, "updateState");
	const online::OnlineEmSlam& slam = online();
	const size_t count = this->m_graph->nodeCount();
	this->m_just_inserted_lc = false;
	if (nrd_->stats().optimisations != seenOptimisations_)
		synchronise();  // the new node's edges included
	else if (count > knownNodes_)
		for (const EdgeKey& key : nrd_->lastStep().edges)
			if (const auto c = slam.constraints().find(key); c != slam.constraints().end() && !c->second.rejected)
				mirror(key, c->second);
	knownNodes_ = count;
	return true;
}

// Eq. 22's registration edges: the graph gets the active ones, loses the rejected and the dropped ones.
void CGridVectorERD::synchronise()
{
	const online::OnlineEmSlam& slam = online();
	const auto& cs = slam.constraints();
	const size_t nodes = this->m_graph->nodeCount();
	auto wanted = [&](const EdgeKey& key, const Constraint& c) { return !c.rejected && key.second < nodes; };
	for (auto it = mirrored_.begin(); it != mirrored_.end();)
	{
		const auto c = cs.find(it->first);
		if (c == cs.end() || !wanted(c->first, c->second))
			it = unmirror(it);
		else
			mirror((it++)->first, c->second);
	}
	for (const auto& [key, c] : cs)
		if (wanted(key, c) && !mirrored_.count(key)) mirror(key, c);
	seenOptimisations_ = nrd_->stats().optimisations;
	++stats_.synchronisations;
}

// Sec. 4.2: the registration's relative pose with its information in the error's frame, as Eq. 22 uses it.
void CGridVectorERD::mirror(const EdgeKey& key, const Constraint& c)
{
	const auto edge = engineEdge(c.z, graphInformation(c, nrd_->config().mstep));
	if (const auto it = mirrored_.find(key); it != mirrored_.end())
	{
		it->second.edge->second = edge;
		return;
	}
	const auto from = TNodeID(key.first), to = TNodeID(key.second);
	const auto in = this->m_graph->edges.insert({{from, to}, edge});
	this->registerNewEdge(from, to, edge);
	mirrored_[key] = {in, c.kind};
	count(key, c.kind, +1);
	++stats_.inserted;
	if (key.second - key.first > uint32_t(params_.lcMinNodeIdDiff)) this->m_just_inserted_lc = true;
}

std::map<EdgeKey, CGridVectorERD::Mirrored>::iterator CGridVectorERD::unmirror(
	std::map<EdgeKey, Mirrored>::iterator it)
{
	this->m_graph->edges.erase(it->second.edge);
	count(it->first, it->second.kind, -1);
	++stats_.removed;
	return mirrored_.erase(it);
}

void CGridVectorERD::count(const EdgeKey& key, EdgeKind kind, int sign)
{
	size_t& byKind =
		kind == EdgeKind::Loop ? stats_.loopEdges : kind == EdgeKind::Overlap ? stats_.overlapEdges : stats_.sequentialEdges;
	byKind = size_t(long(byKind) + sign);
	if (key.second - key.first > uint32_t(params_.lcMinNodeIdDiff))
		stats_.loopClosures = size_t(long(stats_.loopClosures) + sign);
}

void CGridVectorERD::getEdgesStats(std::map<std::string, int>* edge_types_to_num) const
{
	edge_types_to_num->clear();
	(*edge_types_to_num)["LC"] = int(stats_.loopClosures);
}

void CGridVectorERD::getDescriptiveReport(std::string* report_str) const
{
	std::ostringstream ss;
	ss << "Grid-vector edge registration (online EM-SLAM edges) summary:\n" << std::string(80, '#') << "\n";
	params_.dumpToTextStream(ss);
	ss << mrpt::format(
		"edges in the graph: sequential %zu, overlap %zu, loop %zu (loop closures %zu); inserted %zu, removed %zu "
		"over %zu synchronisations\n\n",
		stats_.sequentialEdges, stats_.overlapEdges, stats_.loopEdges, stats_.loopClosures, stats_.inserted,
		stats_.removed, stats_.synchronisations);
	report_str->clear();
	parent_t::getDescriptiveReport(report_str);
	*report_str += ss.str();
	*report_str += this->m_time_logger.getStatsAsText() + "\n\n";
	*report_str += this->getLogAsString() + "\n";
}

}  // namespace gridvector::graphslam
