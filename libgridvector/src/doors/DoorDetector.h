// Sec. 5.4, Fig. 10: doors from corners of static and dynamic vectors; the paper's rule
// (HingeRule) and then the rules beyond it, in the order detect() applies them.
#pragma once

#include "doors/Door.h"
#include "doors/HingeRule.h"

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <utility>
#include <vector>

namespace gridvector
{
/** Doors on a map's vectors. The paper's rule (doors::HingeRule): corners of a static vector
 * (the wall) and a dynamic door candidate meeting at their ends; corners sharing the wall with
 * close vertices and leaves of equal length make a hinge, their leaves the door's states.
 * Beyond the paper, each in its own unit, in this order:
 * - LeafChains: a leaf cut by Fig. 4's split into a dynamic and a static piece is one candidate;
 * - candidates: a static vector of door length is one too (a state Eq. 6 could not see change;
 *   a hinge still needs a dynamic state);
 * - closedStateCorner: a dynamic candidate continuing the wall's line is the closed state;
 * - teeCorners: a candidate's end on a long wall's interior (the wall merged across the doorway);
 * - the longest wall first, a leaf is a state of one door only, one hinge is one door;
 * - statesOnOneLine, teeHingeSeenClosed: hinges that are no door;
 * - wallAsState, joinStates (in the swept arc), closedInWall: a found door's other states;
 * - turnsFromWall: a door has a state seen open. */
class DoorDetector
{
   public:
	explicit DoorDetector(const DoorOptions& opts = {});

	std::vector<Corner> corners(const std::vector<GridVector>& vectors) const;
	std::vector<Door> detect(const std::vector<GridVector>& vectors) const;
	/** doors::stateSpans: where the doors' states lie on v [m from v's start]. */
	std::vector<std::pair<double, double>> stateSpans(const std::vector<Door>& doors, const GridVector& v) const;

   private:
	std::vector<Door> detectIn(const std::vector<GridVector>& v) const;
	bool isDoorHinge(const std::vector<Corner>& cs, const std::vector<size_t>& group,
					 const std::vector<double>& angles) const;
	void completeStates(const std::vector<GridVector>& v, Door& door, double reach, std::vector<bool>& taken) const;

	DoorOptions opts_;
	doors::HingeRule hinge_;
};

}  // namespace gridvector
