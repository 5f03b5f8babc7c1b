// Sec. 5.4, Fig. 10: "if two corners share the same static vector, while their vertices are close
// to each other, and their dynamic vectors have the same length, the vertex can be regarded as the
// hinge of a door, and the dynamic vectors represent different open states of the door."
#pragma once

#include "doors/Door.h"

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <optional>
#include <vector>

namespace gridvector::doors
{
/** Corner of wall s and candidate d meeting at `vertex`, the leaf pointing to `tip`. */
Corner cornerAt(const std::vector<GridVector>& v, size_t s, size_t d, const mrpt::math::TPoint2D& vertex,
				const mrpt::math::TPoint2D& tip);

/** The paper's corner-and-hinge rule, nothing else: corners at the vectors' ends, corners
 * grouped by wall, vertex and leaf length, a group with two states or more is a hinge. */
class HingeRule
{
   public:
	explicit HingeRule(const DoorOptions& opts) : opts_(opts) {}

	/** A door candidate's length: min_door_length..max_door_length, within max_length_diff. */
	bool isCandidate(const GridVector& leaf) const;
	/** The nearest ends of wall s and candidate d, if within max_corner_gap: the vertex at d's end
	 * there, the tip at its other end. A corner when the two turn (turns). */
	std::optional<Corner> meetingEnds(const std::vector<GridVector>& v, size_t s, size_t d) const;
	/** "Each corner has a vertex and two vectors as the borders": the leaf turns from the wall's
	 * line by min_corner_angle_deg or more. */
	bool turns(const Corner& c, const GridVector& wall) const;
	/** Two corners share the static vector, their vertices are close, their leaves equally long. */
	bool sameDoor(const Corner& a, const Corner& b) const;
	/** The group's states: leaf directions at least min_state_diff_deg apart, in group order. */
	std::vector<double> distinctStates(const std::vector<Corner>& cs, const std::vector<size_t>& group) const;
	/** A hinge: two states or more, one of them dynamic (the door candidate). */
	bool isHinge(const std::vector<Corner>& cs, const std::vector<size_t>& group,
				 const std::vector<double>& angles) const;
	/** The door of a hinge's corners: the hinge at their vertices' mean, the leaf length their
	 * mean, the first corner's wall, every corner's leaf (angles not set). */
	Door hingeOf(const std::vector<Corner>& cs, const std::vector<size_t>& group) const;
	/** The door's mean leaf length lies in min_door_length..max_door_length. */
	bool hasDoorLength(const Door& d) const;

   private:
	DoorOptions opts_;
};

}  // namespace gridvector::doors
