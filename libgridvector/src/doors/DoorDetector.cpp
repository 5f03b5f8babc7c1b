#include "doors/DoorDetector.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <cmath>

namespace gridvector
{
using mrpt::math::TPoint2D;

namespace
{
double dist(const TPoint2D& a, const TPoint2D& b) { return std::hypot(a.x - b.x, a.y - b.y); }

/** The smallest arc holding all angles (ascending): counter-clockwise from `start`, `width` wide. */
std::pair<double, double> statesArc(const std::vector<double>& as)
{
	double gap = -1;
	size_t from = 0;
	for (size_t k = 0; k < as.size(); ++k)
	{
		const double g = k + 1 < as.size() ? as[k + 1] - as[k] : as[0] + 2 * M_PI - as[k];
		if (g > gap) gap = g, from = k;
	}
	return {as[(from + 1) % as.size()], 2 * M_PI - gap};
}

/** The closed leaf's direction: the wall's direction (either way) nearer `mid`, the middle of
 * the states' arc. */
double closedDirection(double mid, const GridVector& wall)
{
	double closed = wall.psi();
	if (std::abs(mrpt::math::wrapToPi(closed + M_PI - mid)) < std::abs(mrpt::math::wrapToPi(closed - mid))) closed += M_PI;
	return closed;
}
}  // namespace

DoorDetector::DoorDetector(const DoorOptions& opts) : opts_(opts) {}

// Fig. 10: a corner is built by a static vector (the wall) and a door candidate meeting at an end.
// The candidate is dynamic; a static one of door length counts too, as a state that Eq. 6 could
// not see change (an open leaf nobody looked through after it closed) — detect() only keeps doors
// with a dynamic state. A dynamic candidate may continue the wall's line (a closed leaf). Where the
// merged wall runs across the doorway (a door closed most of the time), the hinge lies inside the
// wall: a candidate's end on a long wall's interior makes a T corner.
std::vector<Corner> DoorDetector::corners(const std::vector<GridVector>& v) const
{
	std::vector<Corner> out;
	const double minLen = opts_.minDoorLength - opts_.maxLengthDiff;
	for (size_t d = 0; d < v.size(); ++d)
	{
		const double len = v[d].length();
		if (len < minLen || len > opts_.maxDoorLength + opts_.maxLengthDiff)
			continue;
		for (size_t s = 0; s < v.size(); ++s)
		{
			if (s == d || v[s].state != VectorState::Static) continue;
			if (endCorner(v, s, d, out)) continue;
			if (v[s].length() > opts_.maxDoorLength) teeCorners(v, s, d, out);
		}
	}
	return out;
}

namespace
{
/** Position of p along the wall from its centre, and its distance from the wall's line. */
std::pair<double, double> alongAndOff(const GridVector& wall, const TPoint2D& p)
{
	const TPoint2D d = wall.direction(), c = wall.centre();
	return {(p.x - c.x) * d.x + (p.y - c.y) * d.y, std::abs((p.x - c.x) * d.y - (p.y - c.y) * d.x)};
}

double bendDeg(double leafAngle, const GridVector& wall)
{
	const double turn = std::abs(mrpt::math::wrapToPi(leafAngle - wall.psi()));
	return std::min(turn, M_PI - turn) * 180 / M_PI;
}

/** Wall s and candidate d meeting at `vertex`, the leaf pointing to `tip`. */
Corner cornerAt(const std::vector<GridVector>& v, size_t s, size_t d, const TPoint2D& vertex, const TPoint2D& tip)
{
	Corner c;
	c.wall = s;
	c.leaf = d;
	c.dynamicLeaf = v[d].state == VectorState::Dynamic;
	c.vertex = vertex;
	c.leafAngle = std::atan2(tip.y - vertex.y, tip.x - vertex.x);
	c.leafLength = v[d].length();
	c.hingeFrom = c.hingeTo = vertex;
	c.tip = tip;
	return c;
}

/** The point of c's hinge interval nearest p. */
TPoint2D closestOn(const Corner& c, const TPoint2D& p)
{
	const double dx = c.hingeTo.x - c.hingeFrom.x, dy = c.hingeTo.y - c.hingeFrom.y, l2 = dx * dx + dy * dy;
	if (l2 <= 0) return c.hingeFrom;
	const double t = std::clamp(((p.x - c.hingeFrom.x) * dx + (p.y - c.hingeFrom.y) * dy) / l2, 0.0, 1.0);
	return TPoint2D(c.hingeFrom.x + t * dx, c.hingeFrom.y + t * dy);
}
}  // namespace

// Sec. 5.4, Fig. 10: an end of the candidate near an end of the wall. A closed leaf continuing the wall's line that
// overlaps the wall (merged closed states reach into it) starts at the wall's end: vertex and
// length are taken there.
bool DoorDetector::endCorner(const std::vector<GridVector>& v, size_t s, size_t d, std::vector<Corner>& out) const
{
	double best = opts_.maxCornerGap;
	int end = -1;
	for (int de = 0; de < 2; ++de)
		for (const TPoint2D& se : {v[s].start(), v[s].end()})
		{
			const double g = dist(de ? v[d].end() : v[d].start(), se);
			if (g <= best) best = g, end = de;
		}
	if (end < 0) return false;
	const TPoint2D tip = end ? v[d].start() : v[d].end();
	Corner c = cornerAt(v, s, d, end ? v[d].end() : v[d].start(), tip);
	if (bendDeg(c.leafAngle, v[s]) < opts_.minCornerAngleDeg)
	{
		if (!(c.dynamicLeaf && collinearBeyond(v[s], c.vertex, tip))) return false;
		c.alongWall = true;
		const double half = v[s].length() / 2;
		if (std::abs(alongAndOff(v[s], c.vertex).first) < half)  // the leaf overlaps the wall
		{
			if (opts_.closedLeafHiddenEnds) c.hingeFrom = c.vertex;  // the hinge lies from its end inside the wall
			c.vertex = c.hingeTo = alongAndOff(v[s], tip).first > 0 ? v[s].end() : v[s].start();  // to the wall's end
			if (!opts_.closedLeafHiddenEnds) c.hingeFrom = c.vertex;
			c.leafLength = dist(c.vertex, tip);
		}
		closedLeafEnds(v, s, c);
	}
	out.push_back(c);
	return true;
}

// Sec. 5.4, beyond the paper (the T corner).
// A hinge inside the wall: an end of the candidate on the wall's line, between its ends. The
// candidate leaves the wall (open state) or, dynamic, lies along it (closed state inside a wall
// merged across the doorway: each of its ends may be the hinge). A closed state along the wall
// that runs on past the wall's end overlaps the wall by more than the corner gap: the wall merged
// part way into the doorway, or the merged closed state reaching back into the wall (endCorner),
// or both; the hinge is its end inside the wall or the wall's end, and both are corners (the
// other states' corners decide which, sameDoor).
void DoorDetector::teeCorners(const std::vector<GridVector>& v, size_t s, size_t d, std::vector<Corner>& out) const
{
	const double half = v[s].length() / 2;
	for (int de = 0; de < 2; ++de)
	{
		const TPoint2D vertex = de ? v[d].end() : v[d].start(), tip = de ? v[d].start() : v[d].end();
		const auto [along, off] = alongAndOff(v[s], vertex);
		if (off > opts_.maxTeeOffset || std::abs(along) >= half) continue;
		Corner c = cornerAt(v, s, d, vertex, tip);
		c.tee = true;
		c.alongWall = bendDeg(c.leafAngle, v[s]) < opts_.minCornerAngleDeg;
		const auto [tipAlong, tipOff] = alongAndOff(v[s], tip);
		if (c.alongWall && !(c.dynamicLeaf && tipOff <= opts_.maxTeeOffset)) continue;
		const bool pastEnd = c.alongWall && std::abs(tipAlong) > half;
		if (!pastEnd || !opts_.closedLeafHiddenEnds)
		{
			if (c.alongWall) closedLeafEnds(v, s, c);
			out.push_back(c);
		}
		if (pastEnd)  // past the wall's end: it starts there (or, closed_leaf_hidden_ends, anywhere from its end inside the wall)
		{
			c.vertex = c.hingeTo = tipAlong > 0 ? v[s].end() : v[s].start();
			if (!opts_.closedLeafHiddenEnds) c.hingeFrom = c.vertex;
			c.leafLength = dist(c.vertex, tip);
			c.tee = false;
			closedLeafEnds(v, s, c);
			out.push_back(c);
		}
	}
}

// Sec. 5.4, beyond the paper (the closed leaf's tip): a closed leaf whose tip runs into the
// latch-side wall (a static vector on its line starting between its ends: both merged into the
// doorway) ends anywhere from that wall's start to its tip. With doors.closed_leaf_to_latch, a
// leaf ending short of such a wall ahead (no farther than a door's length from the vertex) was
// seen in part and may reach that wall.
void DoorDetector::closedLeafEnds(const std::vector<GridVector>& v, size_t s, Corner& c) const
{
	if (!opts_.closedLeafHiddenEnds && !opts_.closedLeafToLatch) return;  // the tip where it was seen
	// along the wall's line (a doorway in one wall), towards the tip, from the vertex
	double dx = v[s].direction().x, dy = v[s].direction().y;
	if ((c.tip.x - c.vertex.x) * dx + (c.tip.y - c.vertex.y) * dy < 0) dx = -dx, dy = -dy;
	const auto along = [&](const TPoint2D& p) { return (p.x - c.vertex.x) * dx + (p.y - c.vertex.y) * dy; };
	const double tipU = along(c.tip);
	double ahead = opts_.maxDoorLength - tipU;
	bool hidden = false;
	for (size_t w = 0; w < v.size(); ++w)
	{
		if (w == s || w == c.leaf || v[w].state != VectorState::Static || bendDeg(v[w].psi(), v[s]) >= opts_.minCornerAngleDeg)
			continue;
		const bool startNear = along(v[w].start()) <= along(v[w].end());
		const TPoint2D nearEnd = startNear ? v[w].start() : v[w].end();
		const double u0 = along(nearEnd), u1 = along(startNear ? v[w].end() : v[w].start());
		// its near end on the wall's line, ahead of the hinge (not the wall, nor one merged across the doorway)
		if (alongAndOff(v[s], nearEnd).second > opts_.maxTeeOffset || u0 <= 0) continue;
		if (u0 < tipU && tipU <= u1) c.tipBack = opts_.closedLeafHiddenEnds ? std::max(c.tipBack, tipU - u0) : 0.0, hidden = true;
		else if (u0 >= tipU) ahead = std::min(ahead, u0 - tipU);
	}
	if (opts_.closedLeafToLatch && !hidden && ahead < opts_.maxDoorLength - tipU) c.tipAhead = std::max(0.0, ahead);
}

// Sec. 5.4, beyond the paper: a closed leaf: on the wall's line, pointing away from the wall (not lying along it).
bool DoorDetector::collinearBeyond(const GridVector& wall, const TPoint2D& vertex, const TPoint2D& tip) const
{
	const auto [tipAlong, off] = alongAndOff(wall, tip);
	return off <= opts_.maxCornerGap && std::abs(tipAlong) > std::abs(alongAndOff(wall, vertex).first);
}

// Sec. 5.4: a door's states are dynamic, also where a static wall runs along one of them (and
// its closed leaf inside a wall merged across the doorway, closedInWall).
std::vector<std::pair<double, double>> DoorDetector::stateSpans(const std::vector<Door>& doors,
																const GridVector& v) const
{
	std::vector<std::pair<double, double>> out;
	const double half = v.length() / 2;
	for (const Door& d : doors)
	{
		std::vector<double> states = d.angles;
		if (d.closedInWall) states.push_back(d.closedAngle);
		for (double a : states)
		{
			if (bendDeg(a, v) >= opts_.minCornerAngleDeg) continue;
			const TPoint2D tip(d.hinge.x + d.length * std::cos(a), d.hinge.y + d.length * std::sin(a));
			const auto [h, hOff] = alongAndOff(v, d.hinge);
			const auto [t, tOff] = alongAndOff(v, tip);
			if (hOff > opts_.maxTeeOffset || tOff > opts_.maxTeeOffset) continue;
			const double u0 = std::clamp(std::min(h, t) + half, 0.0, v.length());
			const double u1 = std::clamp(std::max(h, t) + half, 0.0, v.length());
			if (u1 > u0) out.emplace_back(u0, u1);
		}
	}
	return out;
}

// Sec. 5.4, Fig. 10: two corners share the static vector, their vertices are close, their leaves equally long.
// A closed leaf overlapping the wall or the latch-side wall is compared over where its hinge and
// tip may lie (Corner::hingeFrom/hingeTo, tipBack/tipAhead); other corners at their vertex.
bool DoorDetector::sameDoor(const Corner& a, const Corner& b) const
{
	if (a.wall != b.wall) return false;
	const TPoint2D pb = closestOn(b, closestOn(a, b.vertex)), pa = closestOn(a, pb);
	if (dist(pa, pb) > opts_.maxVertexDistance) return false;
	const auto [a0, a1] = lengthRange(a, pb, opts_.maxVertexDistance);
	const auto [b0, b1] = lengthRange(b, pa, opts_.maxVertexDistance);
	return std::max(a0 - b1, b0 - a1) <= opts_.maxLengthDiff;
}

// The leaf's length [shortest, longest] from a hinge on its interval within `radius` of `near`,
// its tip anywhere it may lie.
std::pair<double, double> DoorDetector::lengthRange(const Corner& c, const TPoint2D& near, double radius) const
{
	if (!c.spansHinge()) return {c.leafLength, c.leafLength};
	const double dx = c.hingeTo.x - c.hingeFrom.x, dy = c.hingeTo.y - c.hingeFrom.y, l = std::hypot(dx, dy);
	double t0 = 0, t1 = l;  // the part of the interval within radius of near, from hingeFrom [m]
	if (l > 0)
	{
		const double t = ((near.x - c.hingeFrom.x) * dx + (near.y - c.hingeFrom.y) * dy) / l;
		const double off = ((near.x - c.hingeFrom.x) * dy - (near.y - c.hingeFrom.y) * dx) / l;
		const double w = std::sqrt(std::max(0.0, radius * radius - off * off));
		t0 = std::clamp(t - w, 0.0, l), t1 = std::clamp(t + w, 0.0, l);
	}
	const auto at = [&](double t) {
		return l > 0 ? TPoint2D(c.hingeFrom.x + t / l * dx, c.hingeFrom.y + t / l * dy) : c.hingeFrom;
	};
	const double la = dist(at(t0), c.tip), lb = dist(at(t1), c.tip);
	return {std::min(la, lb) - c.tipBack, std::max(la, lb) + c.tipAhead};
}

// Sec. 5.4, beyond the paper (the leaf chain).
// A leaf cut by Fig. 4's split into a short dynamic piece and a collinear static piece (the
// part of an open leaf that was never seen through after the door closed stays static): the
// two pieces, end to end, are one door candidate (two dynamic pieces are not: people's tracks). Returns the pieces of each chain (index n + k of
// the candidates appended to `v`).
std::vector<std::pair<size_t, size_t>> DoorDetector::leafChains(std::vector<GridVector>& v) const
{
	const size_t n = v.size();
	const double maxTurn = opts_.leafChainMaxTurnDeg * M_PI / 180, gap = opts_.leafChainGap;
	std::vector<std::pair<size_t, size_t>> parts;
	for (size_t a = 0; a < n; ++a)
	{
		if (v[a].state != VectorState::Dynamic || v[a].length() >= opts_.minDoorLength) continue;
		for (size_t b = 0; b < n; ++b)
		{
			if (b == a || v[b].state != VectorState::Static || v[b].length() > opts_.maxDoorLength) continue;
			for (int ea = 0; ea < 2; ++ea)
				for (int eb = 0; eb < 2; ++eb)
				{
					// a's end ea meets b's end eb; the chain runs from a's other end to b's other end
					const TPoint2D from = ea ? v[a].start() : v[a].end(), joint = ea ? v[a].end() : v[a].start();
					const TPoint2D meet = eb ? v[b].end() : v[b].start(), to = eb ? v[b].start() : v[b].end();
					if (dist(joint, meet) > gap) continue;
					const double ta = std::atan2(joint.y - from.y, joint.x - from.x);
					const double tb = std::atan2(to.y - meet.y, to.x - meet.x);
					if (std::abs(mrpt::math::wrapToPi(ta - tb)) > maxTurn) continue;
					const double len = dist(from, to);
					if (len < opts_.minDoorLength || len > opts_.maxDoorLength) continue;
					GridVector chain(from, to, GridOptions{});
					chain.state = VectorState::Dynamic;  // its dynamic piece is the door candidate
					v.push_back(std::move(chain));
					parts.emplace_back(a, b);
				}
		}
	}
	return parts;
}

// Sec. 5.4: corners sharing the wall, close vertices, equal leaf lengths -> hinge + states.
std::vector<Door> DoorDetector::detect(const std::vector<GridVector>& input) const
{
	std::vector<GridVector> v = input;
	const size_t n = input.size();
	const auto chainParts = leafChains(v);
	std::vector<Door> doors = detectIn(v);
	for (Door& d : doors)  // a chain's leaves are its pieces
	{
		std::vector<size_t> leaves;
		for (size_t leaf : d.leaves)
		{
			if (leaf < n) leaves.push_back(leaf);
			else leaves.push_back(chainParts[leaf - n].first), leaves.push_back(chainParts[leaf - n].second);
		}
		std::sort(leaves.begin(), leaves.end());
		leaves.erase(std::unique(leaves.begin(), leaves.end()), leaves.end());
		d.leaves = std::move(leaves);
	}
	return doors;
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
			if (!used[j] && !taken[cs[j].leaf] && sameDoor(cs[i], cs[j])) group.push_back(j);
		std::vector<double> angles = distinctStates(cs, group);
		if (!isHinge(cs, group, angles)) continue;
		for (size_t k : group) used[k] = true;
		Door d = hingeOf(cs, group);
		if (d.length < opts_.minDoorLength || d.length > opts_.maxDoorLength) continue;
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
		const double reach = std::max(door.length, longest) + opts_.maxLengthDiff;
		wallAsState(v, door, reach, taken);
		joinStates(v, door, reach, taken);
		closedInWall(v, door);
		// no door (below): with closed_leaf_hidden_ends it claims no leaf another hinge may have
		if (opts_.closedLeafHiddenEnds && isNew && !turnsFromWall(v, door))
		{
			for (size_t leaf : door.leaves) taken[leaf] = false;
			doors.pop_back();
		}
	}
	doors.erase(std::remove_if(doors.begin(), doors.end(), [&](const Door& d) { return !turnsFromWall(v, d); }),
				doors.end());
	for (Door& d : doors) d.wallStart = v[d.wall].start(), d.wallEnd = v[d.wall].end();
	return doors;
}

// Fig. 10, beyond the paper's words: the leaf turns from the wall about the hinge, so one state at
// least is seen open, doors.min_open_deg or more from the wall's line (either way). States all
// near that line are the wall's continuation seen dynamic in kinked pieces (real logs).
bool DoorDetector::turnsFromWall(const std::vector<GridVector>& v, const Door& d) const
{
	return std::any_of(d.angles.begin(), d.angles.end(),
					   [&](double a) { return bendDeg(a, v[d.wall]) >= opts_.minOpenDeg; });
}

// Fig. 10: the different open states of one door.
// The distinct states of a group of corners: leaf directions at least min_state_diff apart.
std::vector<double> DoorDetector::distinctStates(const std::vector<Corner>& cs, const std::vector<size_t>& group) const
{
	const double minDiff = opts_.minStateDiffDeg * M_PI / 180;
	std::vector<double> angles;
	for (size_t k : group)
	{
		const bool distinct = std::all_of(angles.begin(), angles.end(), [&](double a) {
			return std::abs(mrpt::math::wrapToPi(a - cs[k].leafAngle)) >= minDiff;
		});
		if (distinct) angles.push_back(cs[k].leafAngle);
	}
	return angles;
}

// Sec. 5.4, Fig. 10: corners sharing a wall make a hinge when they show two states or more, one
// of them dynamic, not all on one straight line; corners inside a wall only with a closed state.
bool DoorDetector::isHinge(const std::vector<Corner>& cs, const std::vector<size_t>& group,
						   const std::vector<double>& angles) const
{
	// Sec. 5.4: the door candidate is a dynamic vector; static states only join one
	const bool anyDynamic = std::any_of(group.begin(), group.end(), [&](size_t k) { return cs[k].dynamicLeaf; });
	if (angles.size() < 2 || !anyDynamic) return false;
	// Fig. 10: the leaf turns about the hinge; states on one straight line through the vertex
	// (either way, none between) are a line seen dynamic cut at a crossing vector, no door
	const double minDiff = opts_.minStateDiffDeg * M_PI / 180;
	const bool straight = std::all_of(angles.begin(), angles.end(), [&](double a) {
		const double turn = std::abs(mrpt::math::wrapToPi(a - angles[0]));
		return std::min(turn, M_PI - turn) < minDiff;
	});
	if (straight) return false;
	// a hinge inside a wall: the wall was merged across the doorway, so the door was seen closed
	const bool allTee = std::all_of(group.begin(), group.end(), [&](size_t k) { return cs[k].tee; });
	return !allTee || std::any_of(group.begin(), group.end(), [&](size_t k) { return cs[k].alongWall; });
}

// Fig. 10: the door of a hinge's corners: the hinge at their vertices' mean, the leaf length
// their mean, the first corner's wall, every corner's leaf (no states yet). A closed leaf whose
// hinge or tip a wall hides takes its hinge nearest the other corners' vertices and its length
// (where its tip may lie) nearest their longest leaf; the door's hinge then lies on its line.
Door DoorDetector::hingeOf(const std::vector<Corner>& cs, const std::vector<size_t>& group) const
{
	Door d;
	d.wall = cs[group[0]].wall;
	TPoint2D seen(0, 0);
	double seenLen = 0, n = 0;  // the longest of them: leaves seen in part are short
	for (size_t k : group)
		if (!cs[k].spansHinge())
			seen.x += cs[k].vertex.x, seen.y += cs[k].vertex.y, seenLen = std::max(seenLen, cs[k].leafLength), ++n;
	if (n > 0) seen.x /= n, seen.y /= n;
	double len = 0;
	for (size_t k : group)
	{
		TPoint2D h = cs[k].vertex;
		double l = cs[k].leafLength;
		if (n > 0 && cs[k].spansHinge())  // its length from there nearest theirs, its tip where it may lie
		{
			h = closestOn(cs[k], seen);
			const auto [l0, l1] = lengthRange(cs[k], h, 0.0);
			l = std::clamp(seenLen, l0, l1);
		}
		d.hinge.x += h.x / group.size();
		d.hinge.y += h.y / group.size();
		len += l;
		d.leaves.push_back(cs[k].leaf);
	}
	d.length = len / group.size();
	for (size_t k : group)  // a closed leaf along the wall: the hinge lies on its line
		if (cs[k].alongWall && cs[k].spansHinge())
		{
			const double ux = std::cos(cs[k].leafAngle), uy = std::sin(cs[k].leafAngle);
			const double t = (d.hinge.x - cs[k].vertex.x) * ux + (d.hinge.y - cs[k].vertex.y) * uy;
			d.hinge = TPoint2D(cs[k].vertex.x + t * ux, cs[k].vertex.y + t * uy);
			break;
		}
	return d;
}

// Sec. 5.4, beyond the paper (wallAsState).
// A door whose corners shared a static vector of leaf length from the hinge (an open state Eq. 6
// kept static, acting as the other states' "wall"): the door's wall is the longest static vector
// through the hinge (end or interior), and the short one, if it lies in the arc the door sweeps
// from that wall, is a state too. Without a longer wall nothing changes.
void DoorDetector::wallAsState(const std::vector<GridVector>& v, Door& d, double reach, std::vector<bool>& taken) const
{
	const size_t shortWall = d.wall;
	const GridVector& w = v[shortWall];
	if (w.length() > reach || taken[shortWall]) return;
	double best = opts_.maxDoorLength;
	for (size_t s = 0; s < v.size(); ++s)
	{
		if (v[s].state != VectorState::Static || taken[s] || v[s].length() <= best) continue;
		const auto [along, off] = alongAndOff(v[s], d.hinge);
		if (off <= opts_.maxTeeOffset && std::abs(along) <= v[s].length() / 2 + opts_.maxCornerGap)
			best = v[s].length(), d.wall = s;
	}
	if (d.wall == shortWall) return;
	const bool startAtHinge = dist(w.start(), d.hinge) <= dist(w.end(), d.hinge);
	const TPoint2D vertex = startAtHinge ? w.start() : w.end(), tip = startAtHinge ? w.end() : w.start();
	const double a = std::atan2(tip.y - d.hinge.y, tip.x - d.hinge.x);
	if (dist(vertex, d.hinge) > opts_.maxVertexDistance || !inSweep(d, v[d.wall], a)) return;
	addLeaf(d, shortWall, a, dist(tip, d.hinge), taken);
}

// Sec. 5.4, beyond the paper (a leaf joining a door).
// Vector k from the hinge, its tip at angle a and distance r, is a leaf of door d; a whole leaf
// at an angle min_state_diff_deg from every state is a state too.
void DoorDetector::addLeaf(Door& d, size_t k, double a, double r, std::vector<bool>& taken) const
{
	d.leaves.push_back(k);
	taken[k] = true;
	const double minDiff = opts_.minStateDiffDeg * M_PI / 180;
	if (r >= d.length - opts_.maxLengthDiff &&
		std::all_of(d.angles.begin(), d.angles.end(), [&](double b) { return std::abs(mrpt::math::wrapToPi(a - b)) >= minDiff; }))
	{
		d.angles.push_back(a);
		std::sort(d.angles.begin(), d.angles.end());
	}
}

// Sec. 5.4, beyond the paper (closedInWall).
// A door whose wall runs through the hinge and on past it, on the states' side, for a leaf's
// length (merged across the doorway: the door was closed in most observations, so Eq. 6 kept
// its closed leaf static with the wall), and with no state along it: the closed leaf lies
// there, inside the wall. It is no state seen (not in angles); stateSpans makes it dynamic.
void DoorDetector::closedInWall(const std::vector<GridVector>& v, Door& d) const
{
	const GridVector& w = v[d.wall];
	if (w.length() <= opts_.maxDoorLength) return;
	const auto [start, width] = statesArc(d.angles);
	const double closed = closedDirection(start + width / 2, w), minDiff = opts_.minStateDiffDeg * M_PI / 180;
	if (std::any_of(d.angles.begin(), d.angles.end(), [&](double a) { return std::abs(mrpt::math::wrapToPi(a - closed)) < minDiff; }))
		return;  // the closed state is a state: stateSpans has it
	const auto [along, off] = alongAndOff(w, d.hinge);
	const double ahead = std::cos(closed - w.psi()) > 0 ? along : -along;  // the hinge's place in the closed direction
	if (off > opts_.maxTeeOffset || std::abs(along) >= w.length() / 2 ||
		w.length() / 2 - ahead < d.length - opts_.maxLengthDiff)
		return;
	d.closedInWall = true;
	d.closedAngle = closed;
}

// Sec. 5.4, beyond the paper (the swept arc).
// The arc a door's leaf sweeps: the smallest arc holding all states (the complement of the
// largest gap between them); when the states seen span less than doors.min_sweep_deg (a right
// angle), the arc from the wall's line (the closed leaf) through the states, at least that wide.
bool DoorDetector::inSweep(const Door& d, const GridVector& wall, double angle) const
{
	auto [start, width] = statesArc(d.angles);  // counter-clockwise from start
	const double minSweep = M_PI * (opts_.minSweepDeg / 180);  // exactly M_PI / 2 for 90 deg
	if (width < minSweep)
	{
		// the closed leaf lies along the wall, in the wall's direction nearer the states (a state
		// or not: a closed leaf inside a wall merged across the doorway is none); the arc runs
		// from there through the states, at least minSweep wide
		const double mid = start + width / 2, closed = closedDirection(mid, wall);
		if (mrpt::math::wrapToPi(mid - closed) >= 0)  // states counter-clockwise from the closed leaf
			width = std::max(minSweep, mrpt::math::wrapTo2Pi(start + width - closed)), start = closed;
		else
			width = std::max(minSweep, mrpt::math::wrapTo2Pi(closed - start)), start = closed - width;
	}
	const double rel = mrpt::math::wrapTo2Pi(angle - start), tol = opts_.minStateDiffDeg * M_PI / 180;
	return rel <= width + tol || rel >= 2 * M_PI - tol;
}

// Sec. 5.4, beyond the paper (joinStates).
// Every other vector from the hinge into the swept arc, reaching no farther than the longest leaf
// of the door's corners (plus doors.max_length_diff), is one more
// state (a door opened to different angles; a state whose corner went to another wall piece)
// or a part of one (a leaf seen in part: occluded, or cut by the split of Fig. 4).
void DoorDetector::joinStates(const std::vector<GridVector>& v, Door& d, double reach, std::vector<bool>& taken) const
{
	for (size_t k = 0; k < v.size(); ++k)
	{
		if (taken[k] || v[k].length() > reach) continue;
		for (int e = 0; e < 2; ++e)
		{
			const TPoint2D vertex = e ? v[k].end() : v[k].start(), tip = e ? v[k].start() : v[k].end();
			const double r = dist(tip, d.hinge);
			if (dist(vertex, d.hinge) > opts_.maxVertexDistance || r > reach || r <= opts_.maxVertexDistance) continue;
			const double a = std::atan2(tip.y - d.hinge.y, tip.x - d.hinge.x);
			if (!inSweep(d, v[d.wall], a)) continue;
			addLeaf(d, k, a, r, taken);
			break;
		}
	}
}

}  // namespace gridvector
