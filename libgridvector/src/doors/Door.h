// Sec. 5.4, Fig. 10: a corner (a wall and a door candidate meeting at a vertex) and a door (a
// hinge and the leaf states seen).
#pragma once

#include <gridvector/GridVector.h>

#include <mrpt/math/TPoint2D.h>

#include <vector>

namespace gridvector
{
/** A corner: one static vector (the wall) and a door candidate (a dynamic
 * vector, or a static one of door length) with an end of each close together;
 * the vertex is the candidate's end there. */
struct Corner
{
	size_t wall = 0, leaf = 0;  //!< indices of the static vector and the candidate
	bool dynamicLeaf = true;  //!< the candidate is dynamic (Eq. 14)
	mrpt::math::TPoint2D vertex;
	mrpt::math::TPoint2D tip;  //!< the leaf's far end
	double leafAngle = 0;  //!< direction of the leaf from the vertex outwards [rad]
	double leafLength = 0;
	bool tee = false;  //!< the vertex lies on the wall's interior, not at an end (TeeCorners)
	bool alongWall = false;  //!< the leaf continues or lies along the wall's line (a closed state)
};

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
