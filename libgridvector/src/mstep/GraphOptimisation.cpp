#include "mstep/GraphOptimisation.h"

#include <algorithm>
#include <mrpt/math/TPose2D.h>

namespace gridvector
{
using Eigen::Matrix3d;

// The matcher's information is over z in the earlier scan's frame; Eq. 21's error has its
// translation in z's frame (PoseGraph::errorFrameInformation).
Matrix3d graphInformation(const Constraint& c, const MStepOptions& opts)
{
	return opts.informationInEdgeFrame ? PoseGraph::errorFrameInformation(c.information, c.z) : c.information;
}

bool farFromEstimate(const std::map<EdgeKey, Constraint>& edges, const Poses& poses,
					 const std::vector<EdgeKey>& keys, const GridVectorConfig& cfg)
{
	return std::any_of(keys.begin(), keys.end(), [&](const EdgeKey& k) {
		const auto it = edges.find(k);
		if (it == edges.end() || it->second.rejected) return false;
		const Constraint& c = it->second;
		const Eigen::Vector3d e = PoseGraph::error(poses[c.from], poses[c.to], c.z);
		return PoseGraph::farLoop(e.dot(graphInformation(c, cfg.mstep) * e), cfg.posegraph);
	});
}

// Eq. 20-22: the odometry edges (u^t) and the active registrations of static vectors, Eq. 22 minimised.
std::vector<EdgeKey> GraphOptimisation::optimise(Poses& poses, const Poses& odometry,
												 std::map<EdgeKey, Constraint>& edges, MStepReport& rep, bool count,
												 bool graduate)
{
	graph_.setNodes(poses);
	graph_.clearEdges();
	for (uint32_t i = 1; i < poses.size(); ++i)
	{
		PoseEdge e;
		e.from = i - 1;
		e.to = i;
		e.z = odometry[i] - odometry[i - 1];
		e.information = PoseGraph::odometryInformation(e.z, cfg_.posegraph);
		e.kind = EdgeKind::Odometry;
		graph_.addEdge(e);
	}
	std::vector<Constraint*> byEdge(graph_.edges().size(), nullptr);
	for (auto& [key, c] : edges)
	{
		// switchable behaviour: an edge rejected against an earlier estimate gets another
		// chance, unless it was rejected reconsider_limit times with these correspondences
		if (cfg_.mstep.reconsiderRejected) c.rejected = rejectionStands(key, c);
		if (c.rejected) continue;
		PoseEdge e;
		e.from = c.from;
		e.to = c.to;
		e.z = c.z;
		e.information = graphInformation(c, cfg_.mstep);
		e.dof = c.dof;
		e.kind = c.kind;
		graph_.addEdge(e);
		byEdge.push_back(&c);
	}
	rep.optimisation = graph_.optimize(graduate);
	std::vector<EdgeKey> rejected;
	for (size_t k = 0; k < byEdge.size(); ++k)
		if (byEdge[k] && !graph_.edges()[k].active)
		{
			byEdge[k]->rejected = true;
			rejected.push_back({byEdge[k]->from, byEdge[k]->to});
		}
	poses = graph_.nodes();
	if (count) countRejections(rejected, edges);
	return rejected;
}

void GraphOptimisation::countRejections(const std::vector<EdgeKey>& keys, const std::map<EdgeKey, Constraint>& edges)
{
	if (steps_ <= kReconsiderFreeSteps) return;
	for (const EdgeKey& k : keys) countRejection(k, edges.at(k));
}

// Eq. 24-25 for rejections: a pair rejected reconsider_limit times with the same
// correspondences stays out, also when re-registered with the same correspondences
// (else the edges flip in and out and EM never converges); other correspondences
// (a changed data association) start the count again. Rejections of the first
// kReconsiderFreeSteps M-steps (raw chain, first loop closures) do not count.
bool GraphOptimisation::rejectionStands(const EdgeKey& key, const Constraint& c) const
{
	if (cfg_.mstep.reconsiderLimit <= 0) return false;
	auto r = rejections_.find(key);
	return r != rejections_.end() && r->second.count >= cfg_.mstep.reconsiderLimit &&
		   r->second.correspondences == c.correspondences;
}

void GraphOptimisation::countRejection(const EdgeKey& key, const Constraint& c)
{
	Rejections& r = rejections_[key];
	if (r.correspondences != c.correspondences) r = {0, c.correspondences};
	++r.count;
}

}  // namespace gridvector
