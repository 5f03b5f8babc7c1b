// Sec. 5.4, Fig. 10: a corner (a wall and a door candidate meeting at a vertex); the door is public
// (gridvector/Door.h).
#pragma once

#include <gridvector/Door.h>
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


}  // namespace gridvector
