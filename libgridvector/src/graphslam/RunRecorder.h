// Follows a graphslam-engine run: scans, odometry and the scan of each node.
#pragma once

#include "graphslam/OdometryTracker.h"
#include <gridvector/io/LogReader.h>

#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/maps/CGridVectorMap.h>

#include <map>
#include <vector>

namespace gridvector::graphslam
{
/** Records what CGraphSlamEngine was fed, step by step, with the engine's
 * own node-to-scan convention (the root keeps the first scan, a new node the
 * latest scan), so that after the run the final graph gives a pose to every
 * scan and a CGridVectorMap can be built from it. Works with any decider. */
class RunRecorder
{
   public:
	using graph_t = mrpt::graphs::CNetworkOfPoses2DInf;
	using Nodes = graph_t::global_poses_t;

	/** Call after each engine step with the step's inputs and the graph's node count then. */
	void record(const mrpt::obs::CActionCollection::Ptr& action, const mrpt::obs::CSensoryFrame::Ptr& observations,
				const mrpt::obs::CObservation::Ptr& observation, size_t nodeCount);

	size_t scanCount() const { return scans_.size(); }
	size_t nodeCount() const { return nodeScan_.size(); }

	/** "t x y theta" of every node, by ID; t = its scan's timestamp. */
	io::Trajectory nodeTrajectory(const Nodes& nodes) const;
	/** "t x y theta" of every scan: the pose of the last node registered at or
	 * before it (the root before the first node) compounded with the odometry
	 * from that node's scan to this one. With no node at all, the odometry
	 * relative to the first scan. */
	io::Trajectory scanTrajectory(const Nodes& nodes) const;
	/** Inserts every scan, in order, at its scanTrajectory() pose (sequential mode). */
	void buildMap(const Nodes& nodes, mrpt::maps::CGridVectorMap& map) const;

   private:
	struct ScanEntry
	{
		double t = 0;
		mrpt::obs::CObservation2DRangeScan::Ptr scan;
		mrpt::math::TPose2D odometry;
		mrpt::graphs::TNodeID anchor = 0;  //!< node whose pose this scan is relative to
	};
	mrpt::math::TPose2D poseOf(const ScanEntry& s, const Nodes& nodes) const;

	OdometryTracker odometry_;
	std::vector<ScanEntry> scans_;
	std::map<mrpt::graphs::TNodeID, size_t> nodeScan_;  //!< node -> index into scans_
	mrpt::graphs::TNodeID anchor_ = 0;
};

}  // namespace gridvector::graphslam
