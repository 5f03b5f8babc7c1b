// Sec. 5.4, Fig. 10: doors from corners of static and dynamic vectors.
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <mrpt/math/TPoint2D.h>

#include <utility>
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
	bool tee = false;  //!< the vertex lies on the wall's interior, not at an end
	bool alongWall = false;  //!< the leaf continues or lies along the wall's line (a closed state)
	/** Where the hinge may lie: [hingeFrom, hingeTo] on the wall's line. A point (both = vertex)
	 * but for a closed leaf overlapping the wall's end, whose hinge the wall hides: anywhere from
	 * the leaf's end inside the wall to the wall's end (vertex). */
	mrpt::math::TPoint2D hingeFrom, hingeTo;
	mrpt::math::TPoint2D tip;  //!< the leaf's far end
	/** A closed leaf's tip hidden by the latch-side wall (the leaf runs into a collinear static
	 * vector): the tip may lie this much nearer the hinge [m]. */
	double tipBack = 0;
	/** A closed leaf seen in part, ending short of the latch-side wall ahead on its line
	 * (doors.closed_leaf_to_latch): the tip may lie this much farther [m]. */
	double tipAhead = 0;
	bool spansHinge() const { return tipBack > 0 || tipAhead > 0 || hingeFrom.x != hingeTo.x || hingeFrom.y != hingeTo.y; }
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
	/** The closed leaf lies inside the door's wall, merged across the doorway (the wall runs
	 * through the hinge and on past it, on the states' side, for a leaf's length, and no state
	 * lies along it): direction closedAngle. Not a state seen (not in angles). */
	bool closedInWall = false;
	double closedAngle = 0;
};

/** Two corners sharing the static vector, with close vertices and leaves of
 * equal length (and different directions) make a hinge; every corner agreeing
 * with it is one more state of that door. At least one state must be dynamic
 * (Sec. 5.4: the dynamic vector is the door candidate); a static leaf joining
 * it is a state Eq. 6 could not see change (an open leaf whose place was never
 * seen through after the door closed) and is a door state all the same.
 * A dynamic leaf may continue the wall's line: the closed state (if it
 * reaches into the wall, it starts at the wall's end; reaching in by more than
 * doors.max_corner_gap, it starts there or at its end inside the wall: a corner at each;
 * with doors.closed_leaf_hidden_ends its hinge lies anywhere from its end inside the wall
 * to the wall's end and, where it runs into the latch-side wall, its tip anywhere from that
 * wall's start to its end: corners are compared, and its hinge placed, where the other
 * corners' vertices and lengths fit best). Where the static wall
 * was merged across the doorway, the hinge lies on the wall's interior: a
 * candidate's end within doors.max_tee_offset of a wall longer than a door
 * makes a T corner (open states leave the wall, a dynamic closed state lies
 * along it); a door of T corners only needs that closed state (people by a
 * wall make T corners too, none along it). Once a door is found, every other vector from its hinge into
 * the arc its states sweep (at least a right angle from the closed state)
 * and reaching no farther than the longest leaf of its corners (+ doors.max_length_diff;
 * the mean leaf length is short when leaves seen in part joined the corners) is one more state (a
 * door opened to different angles) or part of one (a leaf seen in part). A vector is a state of one door only: the corners a
 * door's leaves make elsewhere (e.g. their tips at the latch-side frame) make
 * no second door. A leaf that Fig. 4's split cut into a short dynamic piece and
 * a collinear static piece (the part never seen through again) is one
 * candidate made of both. Where a static vector of leaf length from the hinge
 * served as the corners' wall, the door's wall is the long static vector
 * through the hinge and the short one, in the swept arc, is a state. The arc
 * runs from the wall's line (the closed leaf, whether seen as a state or not)
 * through the states. States on one straight line through the vertex (either
 * way, none between) are no door: no leaf turned about a hinge there (a line
 * seen dynamic, cut where a static vector ends on it). A door none of whose states lies
 * doors.min_open_deg or more from its wall's line is no door either: the wall's own continuation
 * seen dynamic in kinked pieces (its vectors make no other door). */
class DoorDetector
{
   public:
	explicit DoorDetector(const DoorOptions& opts = {});

	std::vector<Corner> corners(const std::vector<GridVector>& vectors) const;
	std::vector<Door> detect(const std::vector<GridVector>& vectors) const;
	/** Where the doors' states (and a closed leaf inside the wall, Door::closedInWall) lie on
	 * v: [from, to] in metres from v's start, for every state parallel to v (within min_corner_angle_deg) whose hinge
	 * and tip are within max_tee_offset of v's line (a closed leaf inside a
	 * wall merged across the doorway: part of the door, so dynamic). */
	std::vector<std::pair<double, double>> stateSpans(const std::vector<Door>& doors, const GridVector& v) const;

   private:
	std::vector<std::pair<size_t, size_t>> leafChains(std::vector<GridVector>& v) const;
	std::vector<Door> detectIn(const std::vector<GridVector>& v) const;
	std::vector<double> distinctStates(const std::vector<Corner>& cs, const std::vector<size_t>& group) const;
	bool turnsFromWall(const std::vector<GridVector>& v, const Door& d) const;
	bool isHinge(const std::vector<Corner>& cs, const std::vector<size_t>& group, const std::vector<double>& angles) const;
	Door hingeOf(const std::vector<Corner>& cs, const std::vector<size_t>& group) const;
	bool endCorner(const std::vector<GridVector>& v, size_t wall, size_t leaf, std::vector<Corner>& out) const;
	void teeCorners(const std::vector<GridVector>& v, size_t wall, size_t leaf, std::vector<Corner>& out) const;
	bool sameDoor(const Corner& a, const Corner& b) const;
	std::pair<double, double> lengthRange(const Corner& c, const mrpt::math::TPoint2D& near, double radius) const;
	void closedLeafEnds(const std::vector<GridVector>& v, size_t s, Corner& c) const;
	void closedInWall(const std::vector<GridVector>& v, Door& d) const;
	void wallAsState(const std::vector<GridVector>& v, Door& d, double reach, std::vector<bool>& taken) const;
	bool inSweep(const Door& d, const GridVector& wall, double angle) const;
	void joinStates(const std::vector<GridVector>& v, Door& d, double reach, std::vector<bool>& taken) const;
	void addLeaf(Door& d, size_t k, double a, double r, std::vector<bool>& taken) const;
	bool collinearBeyond(const GridVector& wall, const mrpt::math::TPoint2D& vertex,
						 const mrpt::math::TPoint2D& tip) const;
	DoorOptions opts_;
};

}  // namespace gridvector
