#include "sim/BuiltinWorlds.h"

#include <stdexcept>

namespace gridvector::sim
{
namespace
{
using Gaps = std::vector<std::pair<double, double>>;

/** A row of rooms behind a corridor wall at y = wallY, back wall at y = backY,
 * partitions every roomW from x0; doorRooms get a door 1.0 m into the room. */
void addRoomRow(World& w, double x0, double x1, double wallY, double backY, double roomW,
				const std::vector<int>& doorRooms, bool desks)
{
	const Vec2 a(x0, wallY), b(x1, wallY);
	const int side = backY > wallY ? +1 : -1;  // rooms left (+1) or right (-1) of a->b
	Gaps gaps;
	for (int r : doorRooms) w.addDoor(a, b, r * roomW + 1.0, 0.9, side, gaps);
	w.addWallWithGaps(a, b, gaps);
	const int rooms = int((x1 - x0) / roomW + 0.5);
	for (int r = 1; r < rooms; r++) w.addWall({x0 + r * roomW, wallY}, {x0 + r * roomW, backY});
	if (!desks) return;
	const double y0 = backY - side * 0.5, y1 = backY - side * 1.3;  // desk against the back wall
	for (int r = 0; r < rooms; r++)
		w.addBox(x0 + r * roomW + 0.6, std::min(y0, y1), x0 + r * roomW + 2.6, std::max(y0, y1));
}

/** Sec. 5.1: a cyclic floor with offices; the robot drives the corridor ring twice. */
World corridorLoop()
{
	World w;
	w.name = "corridor-loop";
	w.description = "38 x 20 m floor: a 2.4 m corridor ring around a central block, offices with doors";
	w.width = 38, w.height = 20;
	w.addBox(0, 0, 38, 20);  // building outline
	addRoomRow(w, 0, 38, 5, 0, 4.75, {1, 4, 6}, true);  // south offices
	addRoomRow(w, 0, 38, 15, 20, 4.75, {0, 3, 5}, true);  // north offices
	// central block: two meeting rooms, one door each
	Gaps south, north;
	w.addDoor({2.4, 7.4}, {35.6, 7.4}, 8.0, 0.9, +1, south);
	w.addDoor({2.4, 12.6}, {35.6, 12.6}, 24.0, 0.9, -1, north);
	w.addWallWithGaps({2.4, 7.4}, {35.6, 7.4}, south);
	w.addWallWithGaps({2.4, 12.6}, {35.6, 12.6}, north);
	w.addWall({2.4, 7.4}, {2.4, 12.6});
	w.addWall({35.6, 7.4}, {35.6, 12.6});
	w.addWall({19.0, 7.4}, {19.0, 12.6});
	w.addBox(7.0, 9.2, 12.0, 10.8);  // meeting tables
	w.addBox(25.0, 9.2, 30.0, 10.8);
	w.objects.push_back({"cabinet", World::box(14.0, 6.95, 14.9, 7.4), World::box(24.0, 12.6, 24.9, 13.05)});
	w.walkZones = {{0, 5, 38, 7.4}, {0, 12.6, 38, 15}, {0, 5, 2.4, 15}, {35.6, 5, 38, 15}};
	w.start = {1.2, 6.2, 0};
	w.route = {{36.8, 6.2}, {36.8, 13.8}, {1.2, 13.8}, {1.2, 6.2}};
	w.defaultLaps = 2;
	w.defaultPeople = 4;
	return w;
}

/** Sec. 5.2: a cluttered office (desks, chairs, cabinets) with a hallway and a store room. */
World office()
{
	World w;
	w.name = "office";
	w.description = "20 x 8 m cluttered office: desks, chairs, cabinets; doors to a hallway and a store room";
	w.width = 23, w.height = 10;
	Gaps northGaps, eastGaps;
	w.addDoor({0, 8}, {20, 8}, 10.5, 0.9, +1, northGaps);
	w.addDoor({0, 8}, {20, 8}, 16.0, 0.9, +1, northGaps);
	w.addDoor({20, 0}, {20, 8}, 5.5, 0.9, -1, eastGaps);
	w.addWall({0, 0}, {20, 0});
	w.addWall({0, 0}, {0, 10});
	w.addWallWithGaps({0, 8}, {20, 8}, northGaps);
	w.addWallWithGaps({20, 0}, {20, 8}, eastGaps);
	w.addWall({0, 10}, {20, 10});  // hallway behind the north wall
	w.addWall({20, 8}, {20, 10});
	w.addWall({20, 4}, {23, 4});  // store room behind the east wall
	w.addWall({23, 4}, {23, 8});
	w.addWall({20, 8}, {23, 8});
	for (double x : {1.0, 7.0, 13.0}) w.addBox(x, 0, x + 4.0, 0.8);  // desks along the south wall
	w.addBox(1.0, 7.2, 5.0, 8.0);  // desks along the north wall, doorways left free
	w.addBox(6.0, 7.2, 9.8, 8.0);
	w.addBox(12.0, 7.2, 15.5, 8.0);
	for (double x : {2.5, 8.5, 14.5}) w.addBox(x, 0.9, x + 0.45, 1.3);  // chairs
	for (double x : {3.0, 8.0, 13.5}) w.addBox(x, 6.7, x + 0.45, 7.1);
	w.addBox(4.0, 3.4, 9.5, 4.6);  // central desk island
	w.addBox(10.5, 3.4, 16.0, 4.6);
	for (double x : {5.0, 7.5}) w.addBox(x, 2.9, x + 0.45, 3.35);
	for (double x : {12.0, 14.5}) w.addBox(x, 4.65, x + 0.45, 5.1);
	w.addBox(0, 3.0, 0.5, 5.0);  // cabinets
	w.addBox(19.5, 2.6, 20.0, 3.6);
	w.objects.push_back({"box", World::box(18.9, 1.4, 19.5, 2.0), World::box(0.5, 5.6, 1.1, 6.2)});
	w.walkZones = {
		{0.5, 1.3, 19.5, 2.9}, {0.5, 5.1, 19.5, 6.7}, {0.5, 1.3, 4.0, 6.7}, {16.0, 1.3, 19.5, 6.7}, {0, 8, 20, 10}};
	w.start = {2.2, 2.1, 0};
	w.route = {{17.8, 2.1}, {17.8, 5.9}, {2.2, 5.9}, {2.2, 2.1}};
	w.defaultLaps = 3;
	w.defaultPeople = 3;
	return w;
}

/** Sec. 5.3: a 20 x 6 m corridor with rooms and doors on both sides, driven up and down. */
World longCorridor()
{
	World w;
	w.name = "long-corridor";
	w.description = "20 x 6 m: a 2.6 m corridor with seven doors to shallow rooms on both sides";
	w.width = 20, w.height = 6;
	w.addBox(0, 0, 20, 6);
	addRoomRow(w, 0, 20, 1.7, 0, 5.0, {0, 1, 2, 3}, false);
	addRoomRow(w, 0, 20, 4.3, 6, 5.0, {0, 1, 2}, false);
	w.addBox(6.0, 3.9, 7.5, 4.3);  // bench against the north wall
	w.addBox(18.3, 1.7, 19.0, 1.95);  // fire extinguisher cabinet
	w.objects.push_back({"trolley", World::box(13.5, 1.7, 14.3, 2.2), World::box(2.5, 3.8, 3.3, 4.3)});
	w.walkZones = {{0, 1.7, 20, 4.3}};
	w.start = {1.0, 3.0, 0};
	w.route = {{19.0, 3.0}, {1.0, 3.0}};
	w.defaultLaps = 3;
	w.defaultPeople = 5;
	return w;
}
}  // namespace

std::vector<std::string> builtinWorldNames() { return {"corridor-loop", "office", "long-corridor"}; }

World makeWorld(const std::string& name)
{
	if (name == "corridor-loop") return corridorLoop();
	if (name == "office") return office();
	if (name == "long-corridor") return longCorridor();
	std::string known;
	for (const auto& n : builtinWorldNames()) known += (known.empty() ? "" : ", ") + n;
	throw std::invalid_argument("unknown world '" + name + "' (known: " + known + ")");
}

}  // namespace gridvector::sim
