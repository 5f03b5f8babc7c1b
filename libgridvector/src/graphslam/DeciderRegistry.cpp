#include "graphslam/CGridVectorERD.h"
#include "graphslam/CGridVectorNRD.h"

#include <gridvector/graphslam/DeciderRegistry.h>

namespace gridvector::graphslam
{
DeciderRegistry::DeciderRegistry()
{
	createDeciderOptimizerMappings();
	populateDeciderOptimizerProperties();
}

void DeciderRegistry::createDeciderOptimizerMappings()
{
	base_t::createDeciderOptimizerMappings();
	node_regs_map["CGridVectorNRD"] = &createNodeRegistrationDecider<CGridVectorNRD>;
	edge_regs_map["CGridVectorERD"] = &createEdgeRegistrationDecider<CGridVectorERD>;
}

void DeciderRegistry::populateDeciderOptimizerProperties()
{
	using Props = mrpt::graphslam::apps::TRegistrationDeciderProps;
	base_t::populateDeciderOptimizerProperties();
	auto add = [&](const char* name, const char* type, const char* description) {
		auto* p = new Props;  // owned and deleted by TUserOptionsChecker
		p->name = name;
		p->type = type;
		p->description = description;
		p->rawlog_format = "Both";
		p->observations_used = {"CObservation2DRangeScan - Format #1, #2",
								"CActionRobotMovement2D - Format #1 (odometry, optional)",
								"CObservationOdometry - Format #2 (odometry, optional)"};
		p->is_slam_2d = true;
		p->is_slam_3d = false;
		regs_descriptions.push_back(p);
	};
	add("CGridVectorNRD", "Node",
		"Register a new node when the robot has moved/turned enough since the last node; the "
		"motion is estimated by matching the grid vectors of each scan against the last node's "
		"(Wang, Xiong, Chu, Sec. 4.2), fused with odometry");
	add("CGridVectorERD", "Edge",
		"Register edges between the new node and its predecessors and earlier passes through "
		"the place by grid-vector matching; information matrix from the matcher");
}

}  // namespace gridvector::graphslam
