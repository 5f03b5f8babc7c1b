// Sec. 5.4, Fig. 10: doors from corners of static and dynamic vectors.
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

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
	double leafAngle = 0;  //!< direction of the leaf from the vertex outwards [rad]
	double leafLength = 0;
};

/** A door: a hinge and the leaf states seen (Fig. 10). */
struct Door
{
	mrpt::math::TPoint2D hinge;
	double length = 0;  //!< mean leaf length [m]
	std::vector<double> angles;  //!< leaf directions of the states, ascending [rad]
	size_t wall = 0;  //!< index of the shared static vector
	std::vector<size_t> leaves;  //!< indices of the dynamic vectors
};

/** Two corners sharing the static vector, with close vertices and leaves of
 * equal length (and different directions) make a hinge; every corner agreeing
 * with it is one more state of that door. At least one state must be dynamic
 * (Sec. 5.4: the dynamic vector is the door candidate); a static leaf joining
 * it is a state Eq. 6 could not see change (an open leaf whose place was never
 * seen through after the door closed) and is a door state all the same.
 * A dynamic leaf may continue the wall's line: the closed state. */
class DoorDetector
{
   public:
	explicit DoorDetector(const DoorOptions& opts = {});

	std::vector<Corner> corners(const std::vector<GridVector>& vectors) const;
	std::vector<Door> detect(const std::vector<GridVector>& vectors) const;

   private:
	bool sameDoor(const Corner& a, const Corner& b) const;
	bool collinearBeyond(const GridVector& wall, const mrpt::math::TPoint2D& vertex,
						 const mrpt::math::TPoint2D& tip) const;
	DoorOptions opts_;
};

}  // namespace gridvector
