// graphslam-engine's decider/optimizer registry, with the grid-vector deciders added.
#pragma once

#include <mrpt/config/CConfigFile.h>  // MRPT 2.5's decider headers use it without including it
#include <mrpt/graphs/CNetworkOfPoses.h>
// before TUserOptionsChecker.h: MRPT 2.5's loop-closer header needs what these bring in
#include <mrpt/graphslam/interfaces/CEdgeRegistrationDecider.h>
#include <mrpt/graphslam/interfaces/CNodeRegistrationDecider.h>
#include <mrpt/graphslam/apps_related/TUserOptionsChecker.h>

namespace gridvector::graphslam
{
/** MRPT's TUserOptionsChecker for 2D graphs (CFixedIntervalsNRD,
 * CICPCriteriaNRD, CEmptyNRD, CICPCriteriaERD, CLoopCloserERD, CEmptyERD,
 * CLevMarqGSO, CEmptyGSO) plus CGridVectorNRD and CGridVectorERD, listed by
 * dumpRegistrarsToConsole() and created by name like MRPT's own.
 * The constructor fills both tables. */
struct DeciderRegistry : public mrpt::graphslam::apps::TUserOptionsChecker<mrpt::graphs::CNetworkOfPoses2DInf>
{
	using graph_t = mrpt::graphs::CNetworkOfPoses2DInf;
	using base_t = mrpt::graphslam::apps::TUserOptionsChecker<graph_t>;

	DeciderRegistry();
	void createDeciderOptimizerMappings() override;
	void populateDeciderOptimizerProperties() override;
};

/** Before the engine runs: gives a CGridVectorERD the CGridVectorNRD whose online EM-SLAM's edges it puts
 * into the graph. Throws std::invalid_argument if `erd` is a CGridVectorERD and `nrd` is not a
 * CGridVectorNRD; any other pair needs nothing. */
void linkDeciders(mrpt::graphslam::deciders::CNodeRegistrationDecider<DeciderRegistry::graph_t>& nrd,
				  mrpt::graphslam::deciders::CEdgeRegistrationDecider<DeciderRegistry::graph_t>& erd);

/** After the last rawlog entry (the engine has no end-of-data call): a CGridVectorNRD finishes its online
 * EM-SLAM (the closing edge search and Eq. 22) and moves the nodes to the result, a CGridVectorERD puts the
 * final edges into the graph. Any other decider: nothing. Returns true if the graph changed. */
bool finishDeciders(mrpt::graphslam::deciders::CNodeRegistrationDecider<DeciderRegistry::graph_t>& nrd,
					mrpt::graphslam::deciders::CEdgeRegistrationDecider<DeciderRegistry::graph_t>& erd);

}  // namespace gridvector::graphslam
