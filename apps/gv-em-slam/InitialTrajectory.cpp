#include "InitialTrajectory.h"

#include <mrpt/math/TPose2D.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridvector::app
{
std::vector<mrpt::math::TPose2D> initialTrajectory(const io::LogData& log,
												   const std::vector<mrpt::math::TPose2D>& odometry,
												   const std::string& path, double maxDt)
{
	const auto poses = io::posesAtScans(log, io::readTrajectory(path), path, maxDt);
	std::vector<mrpt::math::TPose2D> out(odometry.size());
	size_t matched = 0;
	for (size_t t = 0; t < out.size(); ++t)
	{
		if (poses[t])
			out[t] = *poses[t], ++matched;
		else if (t == 0)
			out[t] = odometry[0];
		else
			out[t] = out[t - 1] + (odometry[t] - odometry[t - 1]);
	}
	if (matched == 0)
		throw std::runtime_error(path + ": no pose within " + std::to_string(maxDt) + " s of any scan of " +
								 log.source);
	return out;
}
}  // namespace gridvector::app
