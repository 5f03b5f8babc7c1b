// Sec. 6's sequential mode as graphslam-engine node registration: the nodes are OnlineEmSlam's keyframes.
#pragma once

#include <gridvector/GridVectorConfig.h>
#include "extraction/VectorExtractor.h"
#include "graphslam/DeciderOptions.h"
#include "graphslam/OdometryTracker.h"
#include "online/OnlineEmSlam.h"

#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/graphslam/interfaces/CNodeRegistrationDecider.h>

#include <memory>
#include <optional>

namespace gridvector::graphslam
{
/** Node registration decider for CGraphSlamEngine<CNetworkOfPoses2DInf> (both rawlog formats), driven by
 * the online EM-SLAM (OnlineEmSlam, the same implementation as `gv-em-slam --online`).
 *
 * Every laser scan's grid vectors (Sec. 3.1) and its odometry go to OnlineEmSlam::addScan: the scan is
 * registered against the last keyframe, and each keyframe (mstep.keyframe_distance /
 * keyframe_rotation_deg, as the batch EM's) gets its sequential, overlap and loop edges and goes into the
 * classified map. A keyframe becomes a node, at the online estimate, with the odometry edge of Eq. 22 from
 * the previous node; the registration edges are CGridVectorERD's (linkDeciders). When a loop edge makes
 * Eq. 22 due, it runs here, in the engine's step, and every node moves to its result. MRPT 2.5's engine
 * re-derives every node's pose by Dijkstra from the root after a step that registered a node; the next
 * scan puts them back at the online estimate (and finish() at the end). The root is the first scan, at
 * the origin.
 *
 * Options: [NodeRegistrationDeciderParameters] class_verbosity, and the [gridvector_*] sections of
 * GridVectorConfig (doc/parameters.md). Cost per scan: one extraction and OnlineEmSlam::addScan (that of
 * the robot's surroundings); per loop closure, one optimisation of the whole graph. */
class CGridVectorNRD : public mrpt::graphslam::deciders::CNodeRegistrationDecider<mrpt::graphs::CNetworkOfPoses2DInf>
{
   public:
	using graph_t = mrpt::graphs::CNetworkOfPoses2DInf;
	using parent_t = mrpt::graphslam::deciders::CNodeRegistrationDecider<graph_t>;

	CGridVectorNRD();

	bool updateState(mrpt::obs::CActionCollection::Ptr action, mrpt::obs::CSensoryFrame::Ptr observations,
					 mrpt::obs::CObservation::Ptr observation) override;
	/** Reads the options; throws std::runtime_error("FILE: ...") on an unknown key in the decider's own
	 * sections or a value out of range. Starts a new OnlineEmSlam. */
	void loadParams(const std::string& source_fname) override;
	void printParams() const override;
	void getDescriptiveReport(std::string* report_str) const override;
	/** The online estimate of the last scan, in the graph's frame. */
	global_pose_t getCurrentRobotPosEstimation() const override;

	/** Loads the options from an already open config (loadParams' work). */
	void loadOptions(const mrpt::config::CConfigFileBase& cfg, const std::string& sourceName);

	/** End of the data: OnlineEmSlam::finish() (its closing edge search and Eq. 22) and every node at its
	 * result. The engine has no end-of-data call: the program driving it calls this (finishDeciders). */
	void finish();

	struct Stats
	{
		size_t scans = 0;  //!< laser scans processed
		size_t registered = 0;  //!< ... whose pose came from a registration (else from the odometry)
		size_t nodes = 0;  //!< nodes registered (the root included)
		size_t optimisations = 0;  //!< Eq. 22 runs applied to the nodes
	};
	const Stats& stats() const { return stats_; }
	const NodeDeciderOptions& options() const { return params_; }
	const GridVectorConfig& config() const { return cfg_; }
	/** The online EM-SLAM behind the nodes (keyframe k is node k). */
	const online::OnlineEmSlam& online() const { return *slam_; }
	/** What OnlineEmSlam::addScan did with the last scan (its keyframe's edges: CGridVectorERD's). */
	const online::OnlineStep& lastStep() const { return last_; }

   protected:
	/** Did the last scan become a keyframe (beyond the first)? */
	bool checkRegistrationCondition() override { return newKeyframe_; }

   private:
	bool processScan(const mrpt::obs::CObservation2DRangeScan& scan);
	/** Eq. 22 (take, run, apply) when a loop edge made it due. */
	bool optimiseIfDue();
	/** The newest keyframe as a node: the root first if there is none, the odometry edge from the previous. */
	void registerKeyframe();
	/** Nodes `from`.. at the online estimate. */
	void placeNodes(size_t from);

	NodeDeciderOptions params_;
	GridVectorConfig cfg_;
	VectorExtractor extractor_;
	std::unique_ptr<online::OnlineEmSlam> slam_;
	OdometryTracker odometry_;
	std::optional<mrpt::math::TPose2D> odometryOrigin_;  //!< odometry of the first scan: the graph's origin
	bool newKeyframe_ = false;
	online::OnlineStep last_;
	Stats stats_;
};

}  // namespace gridvector::graphslam
