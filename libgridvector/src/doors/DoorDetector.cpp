// Sec. 5.4: the paper's corner-and-hinge rule, then the rules beyond it, in a visible order.
#include "doors/DoorDetector.h"

#include "doors/ClosedInWall.h"
#include "doors/ClosedState.h"
#include "doors/DoorGeometry.h"
#include "doors/JoinStates.h"
#include "doors/LeafChains.h"
#include "doors/LeafTurns.h"
#include "doors/StateSpans.h"
#include "doors/TeeCorners.h"
#include "doors/WallAsState.h"

#include <algorithm>

namespace gridvector
{
using namespace doors;

DoorDetector::DoorDetector(const DoorOptions& opts) : opts_(opts), hinge_(opts_) {}

// Sec. 5.4: a corner per wall and candidate: at their ends (the paper), else as a closed state
// along the wall's line or, on a wall longer than a door, as T corners (beyond the paper).
std::vector<Corner> DoorDetector::corners(const std::vector<GridVector>& v) const
{
	std::vector<Corner> out;
	// an end of d within max_corner_gap of an end of s (meetingEnds), or within kMaxWallOffset of its line
	// inside its extent (teeCorners): in the box of s grown by the larger of the two
	std::vector<Box2D> reach;
	reach.reserve(v.size());
	for (const GridVector& w : v) reach.push_back(endBox(w, std::max(opts_.maxCornerGap, kMaxWallOffset)));
	for (size_t d = 0; d < v.size(); ++d)
	{
		if (!hinge_.isCandidate(v[d])) continue;  // dynamic, or static of door length (beyond the paper)
		for (size_t s = 0; s < v.size(); ++s)
		{
			if (s == d || v[s].state != VectorState::Static || !holdsAnEndOf(reach[s], v[d])) continue;
			if (auto c = hinge_.meetingEnds(v, s, d))
				if (hinge_.turns(*c, v[s]) || closedStateCorner(v[s], *c, opts_))
				{
					out.push_back(*c);
					continue;
				}
			if (v[s].length() > opts_.maxDoorLength) teeCorners(v, s, d, opts_, out);
		}
	}
	return out;
}

std::vector<Door> DoorDetector::detect(const std::vector<GridVector>& input) const
{
	const LeafChains chains(input, opts_);
	std::vector<Door> doors = detectIn(chains.vectors());
	for (Door& d : doors) d.leaves = chains.pieces(d.leaves);  // a chain's leaves are its pieces
	return doors;
}

// The paper's hinge (HingeRule::isHinge), and beyond it: not all states on one line, a group of
// T corners only with a closed state along the wall.
bool DoorDetector::isDoorHinge(const std::vector<Corner>& cs, const std::vector<size_t>& group,
							   const std::vector<double>& angles) const
{
	return hinge_.isHinge(cs, group, angles) && !statesOnOneLine(angles, opts_.minStateDiffDeg) &&
		   teeHingeSeenClosed(cs, group);
}

// Beyond the paper: a found door's states that made no corner of its group. `reach`: the longest
// leaf the door's states may have.
void DoorDetector::completeStates(const std::vector<GridVector>& v, Door& door, double reach,
								  std::vector<bool>& taken) const
{
	wallAsState(v, door, reach, taken, opts_);
	joinStates(v, door, reach, taken, opts_);
	closedInWall(v, door, opts_);
}

// Sec. 5.4 on the vectors (leaf chains included): corners grouped into hinges, each door's states completed.
std::vector<Door> DoorDetector::detectIn(const std::vector<GridVector>& v) const
{
	auto cs = corners(v);
	// the longest wall first: a static open leaf can also act as a "wall" of the closed state
	std::stable_sort(cs.begin(), cs.end(),
					 [&](const Corner& a, const Corner& b) { return v[a.wall].length() > v[b.wall].length(); });
	std::vector<Door> doors;
	std::vector<bool> used(cs.size(), false);
	std::vector<bool> taken(v.size(), false);  // a leaf is a state of one door only
	for (size_t i = 0; i < cs.size(); ++i)
	{
		if (used[i] || taken[cs[i].leaf]) continue;
		std::vector<size_t> group{i};
		for (size_t j = i + 1; j < cs.size(); ++j)
			if (!used[j] && !taken[cs[j].leaf] && hinge_.sameDoor(cs[i], cs[j])) group.push_back(j);
		std::vector<double> angles = hinge_.distinctStates(cs, group);
		if (!isDoorHinge(cs, group, angles)) continue;
		for (size_t k : group) used[k] = true;
		Door d = hinge_.hingeOf(cs, group);
		if (!hinge_.hasDoorLength(d)) continue;
		std::sort(angles.begin(), angles.end());
		d.angles = angles;
		// leaves seen in part make the mean short: a whole leaf of the group is a state, so reach it
		double longest = 0;
		for (size_t k : group) longest = std::max(longest, cs[k].leafLength);
		// one hinge is one door, even if several walls/leaf copies meet there
		const auto same = std::find_if(doors.begin(), doors.end(), [&](const Door& o) {
			return dist(o.hinge, d.hinge) <= opts_.maxVertexDistance;
		});
		const bool isNew = same == doors.end();
		if (!isNew) same->leaves.insert(same->leaves.end(), d.leaves.begin(), d.leaves.end());
		Door& door = isNew ? doors.emplace_back(d) : *same;
		std::sort(door.leaves.begin(), door.leaves.end());
		door.leaves.erase(std::unique(door.leaves.begin(), door.leaves.end()), door.leaves.end());
		for (size_t leaf : door.leaves) taken[leaf] = true;
		completeStates(v, door, std::max(door.length, longest) + opts_.maxLengthDiff, taken);
	}
	doors.erase(std::remove_if(doors.begin(), doors.end(), [&](const Door& d) { return !turnsFromWall(v[d.wall], d); }),
				doors.end());
	for (Door& d : doors) d.wallStart = v[d.wall].start(), d.wallEnd = v[d.wall].end();
	return doors;
}

std::vector<std::pair<double, double>> DoorDetector::stateSpans(const std::vector<Door>& doors,
																const GridVector& v) const
{
	return gridvector::doors::stateSpans(doors, v, opts_);
}

}  // namespace gridvector
