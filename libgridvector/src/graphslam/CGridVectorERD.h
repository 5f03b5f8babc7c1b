// Sec. 4.2-4.3 as graphslam-engine edge registration: the online EM-SLAM's registration edges in the graph.
#pragma once

#include "graphslam/CGridVectorNRD.h"
#include "graphslam/DeciderOptions.h"

#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/graphslam/interfaces/CEdgeRegistrationDecider.h>

#include <map>

namespace gridvector::graphslam
{
/** Edge registration decider for CGraphSlamEngine<CNetworkOfPoses2DInf>, with CGridVectorNRD.
 *
 * The edges are those of the node decider's OnlineEmSlam: when a node (keyframe i) comes, its sequential
 * edges to the mstep.sequential_window nodes before it, its overlap edges to earlier passes through the
 * place (Sec. 4.3) and its loop edges (the loop search in the window of the odometry model), as each was
 * kept by the consistency check, with the registration's information (Sec. 4.2). After each optimisation
 * of the online EM-SLAM (Eq. 22), the graph's registration edges are made equal to its active ones: the
 * chi2-rejected edges leave the graph, reconsidered ones come back. So the engine's optimizer (CLevMarqGSO)
 * works on Eq. 22's graph. Edges between nodes more than LC_min_nodeid_diff apart count as loop closures.
 *
 * It needs the CGridVectorNRD of the same engine: linkDeciders() (gv-graphslam does it). Cost per node:
 * its new edges; per optimisation, one pass over the edges. */
class CGridVectorERD : public mrpt::graphslam::deciders::CEdgeRegistrationDecider<mrpt::graphs::CNetworkOfPoses2DInf>
{
   public:
	using graph_t = mrpt::graphs::CNetworkOfPoses2DInf;
	using parent_t = mrpt::graphslam::deciders::CEdgeRegistrationDecider<graph_t>;
	using TNodeID = mrpt::graphs::TNodeID;

	CGridVectorERD();

	/** Throws std::logic_error if no CGridVectorNRD was linked (linkDeciders). */
	bool updateState(mrpt::obs::CActionCollection::Ptr action, mrpt::obs::CSensoryFrame::Ptr observations,
					 mrpt::obs::CObservation::Ptr observation) override;
	void loadParams(const std::string& source_fname) override;
	void printParams() const override;
	void getDescriptiveReport(std::string* report_str) const override;
	/** Only "LC": the engine's edge counter knows no vector-matching type. */
	void getEdgesStats(std::map<std::string, int>* edge_types_to_num) const override;

	void loadOptions(const mrpt::config::CConfigFileBase& cfg, const std::string& sourceName);

	/** The node decider whose online EM-SLAM's edges go into the graph; it must outlive this. */
	void follow(const CGridVectorNRD& nrd) { nrd_ = &nrd; }
	/** The graph's registration edges made equal to the online EM-SLAM's active ones (after an optimisation,
	 * and at the end after CGridVectorNRD::finish). */
	void synchronise();

	struct Stats
	{
		size_t sequentialEdges = 0, overlapEdges = 0, loopEdges = 0;  //!< in the graph now, by kind
		size_t loopClosures = 0;  //!< ... spanning more than LC_min_nodeid_diff
		size_t inserted = 0, removed = 0;  //!< edges put into / taken out of the graph over the run
		size_t synchronisations = 0;
	};
	const Stats& stats() const { return stats_; }
	const EdgeDeciderOptions& options() const { return params_; }

   private:
	/** The node decider's OnlineEmSlam; throws if none is linked. */
	const online::OnlineEmSlam& online() const;
	struct Mirrored
	{
		graph_t::edges_map_t::iterator edge;  //!< in the graph's multimap (odometry edges share keys)
		EdgeKind kind;
	};
	/** `key`'s constraint into the graph, or its value updated if there. */
	void mirror(const EdgeKey& key, const Constraint& c);
	std::map<EdgeKey, Mirrored>::iterator unmirror(std::map<EdgeKey, Mirrored>::iterator it);
	/** Adds `sign` to the stats of an edge of that key and kind. */
	void count(const EdgeKey& key, EdgeKind kind, int sign);

	EdgeDeciderOptions params_;
	const CGridVectorNRD* nrd_ = nullptr;
	std::map<EdgeKey, Mirrored> mirrored_;  //!< the registration edges in the graph
	size_t knownNodes_ = 0, seenOptimisations_ = 0;
	Stats stats_;
};

}  // namespace gridvector::graphslam
