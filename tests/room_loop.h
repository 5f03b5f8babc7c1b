// A room with clutter and a drive of two laps round a loop in it, with biased odometry: the world of the
// online EM-SLAM's API test and the graphslam deciders' test.
#pragma once

#include "test_scans.h"

#include <mrpt/math/TPose2D.h>
#include <mrpt/poses/CPose2D.h>

#include <cmath>
#include <vector>

namespace gvtest
{
/** A 12 m by 8 m room with four pieces of clutter: enough wall directions for vector matching. */
inline std::vector<Seg> clutteredRoom()
{
	auto w = room(-6, -4, 6, 4);
	w.push_back({-2, -4, -2, -1.5});
	w.push_back({2, 4, 2, 1.0});
	w.push_back({3.5, -2, 5, -2});
	w.push_back({-5, 2, -3.5, 2});
	return w;
}

/** Two laps of a 3 m by 2 m loop clear of the clutter, 0.2 m steps and 11.25 deg turns; odometry with
 * 2 % scale, 3 % turn and 0.002 rad per step of heading bias. */
struct RoomLoop
{
	std::vector<mrpt::math::TPose2D> truth, odometry;
	RoomLoop()
	{
		using mrpt::math::TPose2D;
		using mrpt::poses::CPose2D;
		TPose2D t(-1.5, -1, 0), o = t;
		for (int lap = 0; lap < 2; ++lap)
			for (int side = 0; side < 4; ++side)
			{
				const int steps = side % 2 == 0 ? 15 : 10;
				for (int i = 0; i < steps + 8; ++i)
				{
					const TPose2D step = i < steps ? TPose2D(0.2, 0, 0) : TPose2D(0, 0, M_PI / 16);
					t = (CPose2D(t) + CPose2D(step)).asTPose();
					o = (CPose2D(o) + CPose2D(step.x * 1.02, 0, step.phi * 1.03 + 0.002)).asTPose();
					truth.push_back(t);
					odometry.push_back(o);
				}
			}
	}
};
}  // namespace gvtest
