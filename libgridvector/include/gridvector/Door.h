// Sec. 5.4, Fig. 10: a door, as DoorDetector finds it: a hinge and the leaf states seen.
#pragma once

#include <mrpt/math/TPoint2D.h>

#include <cstddef>
#include <vector>

namespace gridvector
{
/** A door: a hinge and the leaf states seen (Fig. 10). */
struct Door
{
	mrpt::math::TPoint2D hinge;
	double length = 0;  //!< mean leaf length [m]
	std::vector<double> angles;  //!< leaf directions of the states, ascending [rad]
	size_t wall = 0;  //!< index of the shared static vector
	/** The wall's ends as detected (EmSlam cuts a wall where a state runs along it afterwards, and
	 * Door::wall then indexes the first piece only). */
	mrpt::math::TPoint2D wallStart, wallEnd;
	std::vector<size_t> leaves;  //!< indices of the dynamic vectors
	/** The closed leaf lies inside the door's wall, merged across the doorway (ClosedInWall):
	 * direction closedAngle. Not a state seen (not in angles). */
	bool closedInWall = false;
	double closedAngle = 0;
};

}  // namespace gridvector
