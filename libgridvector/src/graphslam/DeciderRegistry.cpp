#include "graphslam/CGridVectorERD.h"
#include "graphslam/CGridVectorNRD.h"

#include <gridvector/graphslam/DeciderRegistry.h>

#include <mrpt/graphslam/GSO/CEmptyGSO.h>

#include <stdexcept>

namespace gridvector::graphslam
{
namespace
{
/** MRPT 2.5's CEmptyGSO leaves optimizeGraph() pure, which is why its registry creates a CLevMarqGSO
 * under that name; this is the empty optimizer the name promises. */
class EmptyGSO : public mrpt::graphslam::optimizers::CEmptyGSO<DeciderRegistry::graph_t>
{
   public:
	void optimizeGraph() override {}
};
}  // namespace

DeciderRegistry::DeciderRegistry()
{
	createDeciderOptimizerMappings();
	populateDeciderOptimizerProperties();
}

void DeciderRegistry::createDeciderOptimizerMappings()
{
	base_t::createDeciderOptimizerMappings();
	optimizers_map["CEmptyGSO"] = &createGraphSlamOptimizer<EmptyGSO>;  // MRPT 2.5's entry made a CLevMarqGSO
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
		"Online EM-SLAM (Wang, Xiong, Chu, Sec. 4 in sequential mode): every scan registered by grid-vector "
		"matching against the last keyframe; each keyframe a node with its odometry edge, the nodes moved to "
		"the pose graph's optimum after every loop closure. Use with CGridVectorERD");
	add("CGridVectorERD", "Edge",
		"The online EM-SLAM's registration edges (sequential, overlap with earlier passes, loop closures "
		"verified for consistency, chi2-rejected ones removed); needs CGridVectorNRD");
}

void linkDeciders(mrpt::graphslam::deciders::CNodeRegistrationDecider<DeciderRegistry::graph_t>& nrd,
				  mrpt::graphslam::deciders::CEdgeRegistrationDecider<DeciderRegistry::graph_t>& erd)
{
	auto* edges = dynamic_cast<CGridVectorERD*>(&erd);
	if (!edges) return;
	const auto* nodes = dynamic_cast<const CGridVectorNRD*>(&nrd);
	if (!nodes)
		throw std::invalid_argument(
			"CGridVectorERD needs the node decider CGridVectorNRD: its edges are that decider's online EM-SLAM's");
	edges->follow(*nodes);
}

bool finishDeciders(mrpt::graphslam::deciders::CNodeRegistrationDecider<DeciderRegistry::graph_t>& nrd,
					mrpt::graphslam::deciders::CEdgeRegistrationDecider<DeciderRegistry::graph_t>& erd)
{
	auto* nodes = dynamic_cast<CGridVectorNRD*>(&nrd);
	if (!nodes) return false;
	nodes->finish();
	if (auto* edges = dynamic_cast<CGridVectorERD*>(&erd)) edges->synchronise();
	return true;
}

}  // namespace gridvector::graphslam
