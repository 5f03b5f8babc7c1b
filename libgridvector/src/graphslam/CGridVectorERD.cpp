#include "graphslam/CGridVectorERD.h"
#include "graphslam/RegistrationConfig.h"
#include "graphslam/OdometryTracker.h"

#include <mrpt/config/CConfigFile.h>
#include <mrpt/core/format.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/system/filesystem.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace gridvector::graphslam
{
using mrpt::math::TPose2D;
using mrpt::poses::CPose2D;

CGridVectorERD::CGridVectorERD() : extractor_(cfg_.extraction, cfg_.grid), matcher_(cfg_.matcher)
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
	cfg_ = loadRegistrationConfig(cfg, sourceName);
	extractor_ = VectorExtractor(cfg_.extraction, cfg_.grid);
	matcher_ = VectorMatcher(cfg_.matcher);
	this->setMinLoggingLevel(mrpt::system::VerbosityLevel(params_.classVerbosity));
}

void CGridVectorERD::printParams() const
{
	parent_t::printParams();
	params_.dumpToConsole();
}

bool CGridVectorERD::updateState(mrpt::obs::CActionCollection::Ptr, mrpt::obs::CSensoryFrame::Ptr observations,
								 mrpt::obs::CObservation::Ptr observation)
{
	mrpt::system::CTimeLoggerEntry timer(this->m_time_logger, "updateState");
	const auto scan = scanOf(observations, observation);
	if (scan)
	{
		lastScan_ = scan;
		if (!firstScan_) firstScan_ = scan;
	}
	const size_t count = this->m_graph->nodeCount();
	if (count <= knownNodes_) return true;
	this->m_just_inserted_lc = false;
	const size_t first = std::max<size_t>(knownNodes_, 1);
	attachScans();
	for (size_t n = first; n < count; ++n) registerEdges(TNodeID(n));
	return true;
}

// The engine's convention: the root keeps the first scan, a new node the latest one.
void CGridVectorERD::attachScans()
{
	const size_t count = this->m_graph->nodeCount();
	for (size_t n = knownNodes_; n < count; ++n)
	{
		const auto& scan = n == 0 ? firstScan_ : lastScan_;
		nodeVectors_[TNodeID(n)] =
			scan ? MatchSegment::fromVectors(extractor_.extract(*scan).vectors) : std::vector<MatchSegment>{};
	}
	knownNodes_ = count;
}

std::vector<mrpt::graphs::TNodeID> CGridVectorERD::candidates(TNodeID n, size_t* sequentialCount) const
{
	const auto& nodes = this->m_graph->nodes;
	const CPose2D& pn = nodes.at(n);
	std::vector<TNodeID> out;
	const size_t window = size_t(params_.sequentialWindow);
	for (size_t k = params_.matchPreviousNode ? 1 : 2; k <= window + 1 && k <= n; ++k)
	{
		const TNodeID m = n - k;
		if (nodes.count(m) && nodes.at(m).distanceTo(pn) <= params_.maxDistance) out.push_back(m);
	}
	if (sequentialCount) *sequentialCount = out.size();
	const TNodeID below = n > window + 1 ? TNodeID(n - window - 1) : 0;
	const auto passes = passCandidates(n, below);
	out.insert(out.end(), passes.begin(), passes.end());
	return out;
}

// Older nodes near n, one (the nearest) per pass through the place.
std::vector<mrpt::graphs::TNodeID> CGridVectorERD::passCandidates(TNodeID n, TNodeID below) const
{
	const auto& nodes = this->m_graph->nodes;
	const CPose2D& pn = nodes.at(n);
	std::vector<std::pair<double, TNodeID>> best;  // per pass: (distance, node)
	TNodeID last = 0;
	for (auto it = nodes.begin(); it != nodes.end() && it->first < below; ++it)
	{
		const double d = it->second.distanceTo(pn);
		if (d > params_.maxDistance) continue;
		if (best.empty() || it->first - last > TNodeID(params_.passGap))
			best.emplace_back(d, it->first);
		else if (d < best.back().first)
			best.back() = {d, it->first};
		last = it->first;
	}
	std::sort(best.begin(), best.end());
	if (best.size() > size_t(params_.maxLoopCandidates)) best.resize(size_t(params_.maxLoopCandidates));
	std::vector<TNodeID> out;
	for (const auto& b : best) out.push_back(b.second);
	return out;
}

void CGridVectorERD::registerEdges(TNodeID n)
{
	size_t sequential = 0;
	const auto cands = candidates(n, &sequential);
	for (size_t i = 0; i < cands.size(); ++i) tryEdge(cands[i], n, i < sequential);
}

bool CGridVectorERD::acceptable(const MatchResult& r, const TPose2D& guess, bool sequential, double widenDistance,
								double widenAngle) const
{
	return r.ok() &&
		   closeTo(guess, r.pose, params_.maxCorrectionDistance + widenDistance,
				   (params_.maxCorrectionAngleDeg * M_PI / 180) + widenAngle) &&
		   validInformation(r.information) && (sequential || r.matchedShare >= params_.minMatchedShare);
}

std::optional<MatchResult> CGridVectorERD::registerPair(TNodeID from, TNodeID to, const TPose2D& guess, bool sequential)
{
	const auto& a = nodeVectors_.at(from);
	const auto& b = nodeVectors_.at(to);
	if (a.empty() || b.empty()) return std::nullopt;
	++stats_.registrations;
	MatchResult r = matcher_.match(a, b, guess);
	if (acceptable(r, guess, sequential, 0, 0)) return r;
	const double d = params_.searchOffset, t = params_.searchAngleDeg * M_PI / 180;
	if (sequential || (d <= 0 && t <= 0)) return std::nullopt;
	std::optional<MatchResult> best;
	for (double dx : {-d, 0.0, d})
		for (double dy : {-d, 0.0, d})
			for (double dt : {-t, 0.0, t})
			{
				if ((dx == 0 && dy == 0 && dt == 0) || (d <= 0 && (dx != 0 || dy != 0)) || (t <= 0 && dt != 0))
					continue;
				++stats_.registrations;
				r = matcher_.match(a, b, TPose2D(guess.x + dx, guess.y + dy, guess.phi + dt));
				if (acceptable(r, guess, false, std::sqrt(2.0) * d, t) &&
					(!best || r.matchedLength > best->matchedLength))
					best = r;
			}
	return best;
}

// Sec. 4.2: one registration between two nodes' vectors, kept if plausible.
bool CGridVectorERD::tryEdge(TNodeID from, TNodeID to, bool sequential)
{
	const auto& nodes = this->m_graph->nodes;
	const TPose2D guess = (nodes.at(to) - nodes.at(from)).asTPose();
	const auto r = registerPair(from, to, guess, sequential);
	MRPT_LOG_DEBUG_FMT("register %u -> %u (%s): %s", unsigned(from), unsigned(to), sequential ? "sequential" : "pass",
					   r ? "edge" : "rejected");
	if (!r)
	{
		++stats_.rejected;
		return false;
	}
	const auto c = toConstraint({r->pose, r->information}, cfg_.mstep.informationInEdgeFrame);
	this->registerNewEdge(from, to, c);
	this->m_graph->insertEdge(from, to, c);
	++(sequential ? stats_.sequentialEdges : stats_.passEdges);
	if (to - from > TNodeID(params_.lcMinNodeIdDiff))
	{
		++stats_.loopClosures;
		this->m_just_inserted_lc = true;
	}
	return true;
}

void CGridVectorERD::getEdgesStats(std::map<std::string, int>* edge_types_to_num) const
{
	edge_types_to_num->clear();
	(*edge_types_to_num)["LC"] = int(stats_.loopClosures);
}

void CGridVectorERD::getDescriptiveReport(std::string* report_str) const
{
	std::ostringstream ss;
	ss << "Grid-vector edge registration (vector matching) summary:\n" << std::string(80, '#') << "\n";
	params_.dumpToTextStream(ss);
	ss << mrpt::format("matcher runs %zu: sequential edges %zu, pass edges %zu (loop closures %zu), rejected %zu\n\n",
					   stats_.registrations, stats_.sequentialEdges, stats_.passEdges, stats_.loopClosures,
					   stats_.rejected);
	report_str->clear();
	parent_t::getDescriptiveReport(report_str);
	*report_str += ss.str();
	*report_str += this->m_time_logger.getStatsAsText() + "\n\n";
	*report_str += this->getLogAsString() + "\n";
}

}  // namespace gridvector::graphslam
