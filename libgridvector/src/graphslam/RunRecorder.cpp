#include "graphslam/RunRecorder.h"

#include <mrpt/poses/CPose3D.h>
#include <mrpt/system/datetime.h>

namespace gridvector::graphslam
{
using mrpt::math::TPose2D;
using mrpt::poses::CPose2D;

void RunRecorder::record(const mrpt::obs::CActionCollection::Ptr& action,
						 const mrpt::obs::CSensoryFrame::Ptr& observations,
						 const mrpt::obs::CObservation::Ptr& observation, size_t nodeCount)
{
	odometry_.update(action, observations, observation);
	if (const auto scan = scanOf(observations, observation))
	{
		ScanEntry e;
		e.t = scan->timestamp == INVALID_TIMESTAMP ? 0.0 : mrpt::Clock::toDouble(scan->timestamp);
		e.scan = scan;
		e.odometry = odometry_.pose();
		e.anchor = anchor_;
		scans_.push_back(std::move(e));
	}
	if (scans_.empty()) return;
	for (size_t n = nodeScan_.size(); n < nodeCount; ++n)
	{
		const auto id = mrpt::graphs::TNodeID(n);
		nodeScan_[id] = n == 0 ? 0 : scans_.size() - 1;
		if (n == 0) continue;
		anchor_ = id;
		scans_.back().anchor = id;
	}
}

TPose2D RunRecorder::poseOf(const ScanEntry& s, const Nodes& nodes) const
{
	const auto it = nodes.find(s.anchor);
	const CPose2D base = it != nodes.end() ? CPose2D(it->second) : CPose2D();
	const auto ns = nodeScan_.find(s.anchor);
	const TPose2D& odoBase = scans_[ns != nodeScan_.end() ? ns->second : 0].odometry;
	return (base + (CPose2D(s.odometry) - CPose2D(odoBase))).asTPose();
}

io::Trajectory RunRecorder::nodeTrajectory(const Nodes& nodes) const
{
	io::Trajectory out;
	for (const auto& [id, pose] : nodes)
	{
		const auto it = nodeScan_.find(id);
		if (it != nodeScan_.end()) out.emplace_back(scans_[it->second].t, CPose2D(pose).asTPose());
	}
	return out;
}

io::Trajectory RunRecorder::scanTrajectory(const Nodes& nodes) const
{
	io::Trajectory out;
	out.reserve(scans_.size());
	for (const auto& s : scans_) out.emplace_back(s.t, poseOf(s, nodes));
	return out;
}

void RunRecorder::buildMap(const Nodes& nodes, mrpt::maps::CGridVectorMap& map) const
{
	for (const auto& s : scans_) map.insertObservation(*s.scan, mrpt::poses::CPose3D(CPose2D(poseOf(s, nodes))));
}

}  // namespace gridvector::graphslam
