// Sec. 4.2: edge registration for MRPT's graphslam-engine by vector matching.
#pragma once

#include <gridvector/GridVectorConfig.h>
#include "extraction/VectorExtractor.h"
#include "mstep/VectorMatcher.h"
#include "graphslam/DeciderOptions.h"
#include "graphslam/PoseFusion.h"

#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/graphslam/interfaces/CEdgeRegistrationDecider.h>

#include <map>
#include <optional>
#include <vector>

namespace gridvector::graphslam
{
/** Edge registration decider for CGraphSlamEngine<CNetworkOfPoses2DInf>.
 *
 * Keeps the grid vectors (Sec. 3.1) of every node's scan. When a node n is
 * registered, its vectors are matched against (a) its predecessors
 * n-2 .. n-1-sequential_window (and n-1 with match_previous_node) and (b)
 * earlier passes through the place: older nodes within max_distance of n's
 * current estimate, grouped into passes by pass_gap, the nearest node of each
 * of the max_loop_candidates nearest passes. A registration becomes an edge
 * (relative pose + the matcher's information matrix) when the matcher accepts
 * it, it lies within max_correction_* of the graph's current relative estimate
 * and, for (b), it matches min_matched_share of the shorter scan. Edges between
 * nodes more than LC_min_nodeid_diff apart are loop closures.
 *
 * Cost per new node: at most sequential_window + max_loop_candidates
 * registrations, plus a linear scan of the node estimates (as MRPT's ICP
 * deciders do). */
class CGridVectorERD : public mrpt::graphslam::deciders::CEdgeRegistrationDecider<mrpt::graphs::CNetworkOfPoses2DInf>
{
   public:
	using graph_t = mrpt::graphs::CNetworkOfPoses2DInf;
	using parent_t = mrpt::graphslam::deciders::CEdgeRegistrationDecider<graph_t>;
	using TNodeID = mrpt::graphs::TNodeID;

	CGridVectorERD();

	bool updateState(mrpt::obs::CActionCollection::Ptr action, mrpt::obs::CSensoryFrame::Ptr observations,
					 mrpt::obs::CObservation::Ptr observation) override;
	void loadParams(const std::string& source_fname) override;
	void printParams() const override;
	void getDescriptiveReport(std::string* report_str) const override;
	/** Only "LC": the engine's edge counter knows no vector-matching type. */
	void getEdgesStats(std::map<std::string, int>* edge_types_to_num) const override;

	void loadOptions(const mrpt::config::CConfigFileBase& cfg, const std::string& sourceName);

	struct Stats
	{
		size_t registrations = 0;  //!< matcher runs
		size_t sequentialEdges = 0, passEdges = 0;  //!< edges added, by candidate kind
		size_t loopClosures = 0;  //!< edges spanning more than LC_min_nodeid_diff
		size_t rejected = 0;  //!< registrations not turned into edges
	};
	const Stats& stats() const { return stats_; }
	const EdgeDeciderOptions& options() const { return params_; }

	/** Candidate nodes for new node n under the current estimates: first the
	 * sequential ones (newest first), then one per older pass (nearest pass
	 * first). `sequentialCount` receives how many of the first are sequential. */
	std::vector<TNodeID> candidates(TNodeID n, size_t* sequentialCount = nullptr) const;

   private:
	void attachScans();
	void registerEdges(TNodeID n);
	bool tryEdge(TNodeID from, TNodeID to, bool sequential);
	/** Registration of `to`'s vectors against `from`'s: from the guess, then
	 * (earlier passes, search_* > 0) from shifted guesses, best matched length. */
	std::optional<MatchResult> registerPair(TNodeID from, TNodeID to, const mrpt::math::TPose2D& guess,
											bool sequential);
	bool acceptable(const MatchResult& r, const mrpt::math::TPose2D& guess, bool sequential, double widenDistance,
					double widenAngle) const;
	std::vector<TNodeID> passCandidates(TNodeID n, TNodeID below) const;

	EdgeDeciderOptions params_;
	GridVectorConfig cfg_;
	VectorExtractor extractor_;
	VectorMatcher matcher_;
	std::map<TNodeID, std::vector<MatchSegment>> nodeVectors_;
	mrpt::obs::CObservation2DRangeScan::Ptr firstScan_, lastScan_;
	size_t knownNodes_ = 0;
	Stats stats_;
};

}  // namespace gridvector::graphslam
