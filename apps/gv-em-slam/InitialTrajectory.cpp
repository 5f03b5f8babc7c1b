#include "InitialTrajectory.h"

#include <gridvector/SE2.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridvector::app
{
std::vector<mrpt::math::TPose2D> initialTrajectory(const io::LogData& log,
												   const std::vector<mrpt::math::TPose2D>& odometry,
												   const std::string& path, double maxDt)
{
	io::Trajectory traj = io::readTrajectory(path);
	std::sort(traj.begin(), traj.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
	std::vector<mrpt::math::TPose2D> out(odometry.size());
	size_t matched = 0;
	for (size_t t = 0; t < out.size(); ++t)
	{
		const double ts = log.scans[t].timestamp;
		auto it = std::lower_bound(traj.begin(), traj.end(), ts, [](const auto& p, double v) { return p.first < v; });
		const io::Trajectory::value_type* best = nullptr;
		if (it != traj.end() && std::abs(it->first - ts) <= maxDt) best = &*it;
		if (it != traj.begin() && std::abs(std::prev(it)->first - ts) <= maxDt &&
			(!best || std::abs(std::prev(it)->first - ts) < std::abs(best->first - ts)))
			best = &*std::prev(it);
		if (best) out[t] = best->second, ++matched;
		else if (t == 0) out[t] = odometry[0];
		else out[t] = se2::compose(out[t - 1], se2::relative(odometry[t - 1], odometry[t]));
	}
	if (matched == 0)
		throw std::runtime_error(path + ": no pose within " + std::to_string(maxDt) + " s of any scan of " + log.source);
	return out;
}
}  // namespace gridvector::app
