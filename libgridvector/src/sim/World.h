// A simulated indoor world: static walls and furniture, doors, an object that is
// moved during the run, areas where people walk, and the robot's route.
#pragma once

#include "sim/Geometry.h"

#include <mrpt/math/TPose2D.h>

#include <string>
#include <vector>

namespace gridvector::sim
{
/** A door leaf turning about its hinge; angles are world directions of the leaf. */
struct DoorSpec
{
	Vec2 hinge;
	double length = 0.9;
	double closedAngle = 0;  //!< leaf lies in the wall's gap
	double openAngle = 0;  //!< fully open (swung into the room)
	Segment leaf(double angle) const { return {hinge, hinge + Vec2::polar(length, angle)}; }
};

/** An object (box, cabinet, trolley) standing at `first`, later at `second`. */
struct MovableSpec
{
	std::string name;
	std::vector<Vec2> first, second;  //!< closed polygons (footprints)
};

struct Rect
{
	double x0, y0, x1, y1;
	bool contains(const Vec2& p) const { return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1; }
};

struct World
{
	std::string name, description;
	std::vector<Segment> walls;  //!< static walls and static furniture outlines
	std::vector<DoorSpec> doors;
	std::vector<MovableSpec> objects;
	std::vector<Rect> walkZones;  //!< where people walk (corridors, aisles)
	std::vector<Vec2> route;  //!< robot waypoints; closed (last = first) so laps can repeat
	mrpt::math::TPose2D start;  //!< the robot's true start pose
	int defaultLaps = 2;
	int defaultPeople = 4;
	double width = 0, height = 0;  //!< bounding box size [m]

	void addWall(Vec2 a, Vec2 b) { walls.emplace_back(a, b); }
	/** A wall from a to b with openings [from, to] (distances from a, ascending). */
	void addWallWithGaps(Vec2 a, Vec2 b, const std::vector<std::pair<double, double>>& gaps);
	/** Axis-aligned box outline (furniture). */
	void addBox(double x0, double y0, double x1, double y1);
	/** A door of width w at distance s along the wall a->b: the wall gets a gap and a
	 * leaf hinged at the gap's start that swings towards `roomSide` (+1: left of a->b). */
	void addDoor(Vec2 a, Vec2 b, double s, double w, int roomSide, std::vector<std::pair<double, double>>& gaps);
	/** Polygon outline of an axis-aligned box. */
	static std::vector<Vec2> box(double x0, double y0, double x1, double y1);
};

}  // namespace gridvector::sim
