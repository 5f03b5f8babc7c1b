// Sec. 4.2: node registration for MRPT's graphslam-engine by vector matching.
#pragma once

#include <gridvector/GridVectorConfig.h>
#include "extraction/VectorExtractor.h"
#include "mstep/VectorMatcher.h"
#include "graphslam/DeciderOptions.h"
#include "graphslam/OdometryTracker.h"
#include "graphslam/PoseFusion.h"

#include <mrpt/graphs/CNetworkOfPoses.h>
#include <mrpt/graphslam/interfaces/CNodeRegistrationDecider.h>

namespace gridvector::graphslam
{
/** Node registration decider for CGraphSlamEngine<CNetworkOfPoses2DInf>
 * (both rawlog formats).
 *
 * Each laser scan's grid vectors (Sec. 3.1) are registered by vector
 * matching against the scan of the last node (a keyframe), starting from the
 * previous estimate moved by the odometry increment. An accepted match is
 * fused with the odometry increment in information form; a failed or
 * implausible match (further than max_correction_* from the prediction) falls
 * back to odometry. A node is registered, with that estimate and information
 * as its edge from the previous node, once the robot has moved
 * registration_max_distance or turned registration_max_angle since the last
 * node. The root node sits at the origin with the first scan.
 *
 * Options: see NodeDeciderOptions, plus the [gridvector_extraction],
 * [gridvector_grid], [gridvector_matcher] and [gridvector_posegraph]
 * (odometry model) sections of GridVectorConfig. Cost per scan: one
 * extraction and one registration. */
class CGridVectorNRD : public mrpt::graphslam::deciders::CNodeRegistrationDecider<mrpt::graphs::CNetworkOfPoses2DInf>
{
   public:
	using graph_t = mrpt::graphs::CNetworkOfPoses2DInf;
	using parent_t = mrpt::graphslam::deciders::CNodeRegistrationDecider<graph_t>;

	CGridVectorNRD();

	bool updateState(mrpt::obs::CActionCollection::Ptr action, mrpt::obs::CSensoryFrame::Ptr observations,
					 mrpt::obs::CObservation::Ptr observation) override;
	/** Reads the options; throws std::runtime_error("FILE: ...") on an unknown
	 * key in the decider's own sections or a value out of range. */
	void loadParams(const std::string& source_fname) override;
	void printParams() const override;
	void getDescriptiveReport(std::string* report_str) const override;

	/** Loads the options from an already open config (loadParams' work). */
	void loadOptions(const mrpt::config::CConfigFileBase& cfg, const std::string& sourceName);

	struct Stats
	{
		size_t scans = 0;  //!< laser scans processed
		size_t matched = 0;  //!< ... registered by vector matching
		size_t failed = 0;  //!< ... whose match the matcher rejected
		size_t implausible = 0;  //!< ... whose match was too far from the odometry prediction
		size_t nodes = 0;  //!< nodes registered (the root included)
	};
	const Stats& stats() const { return stats_; }
	const NodeDeciderOptions& options() const { return params_; }
	const GridVectorConfig& config() const { return cfg_; }
	/** Current estimate of the motion since the last node. */
	const PoseEstimate& sinceLastNode() const { return since_; }

   protected:
	bool checkRegistrationCondition() override;

   private:
	bool processScan(const mrpt::obs::CObservation2DRangeScan& scan);
	PoseEstimate odometryPrior(const mrpt::math::TPose2D& prediction) const;
	void registerNode(std::vector<MatchSegment>&& keyframe);

	NodeDeciderOptions params_;
	GridVectorConfig cfg_;
	VectorExtractor extractor_;
	VectorMatcher matcher_;
	OdometryTracker odometry_;
	std::vector<MatchSegment> keyframe_;  //!< the last node's vectors
	bool haveKeyframe_ = false;
	mrpt::math::TPose2D odomAtNode_, odomAtScan_;  //!< odometry at the last node / scan
	PoseEstimate since_;  //!< motion since the last node
	Stats stats_;
};

}  // namespace gridvector::graphslam
