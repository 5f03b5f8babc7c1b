#include "sim/World.h"

namespace gridvector::sim
{
void World::addWallWithGaps(Vec2 a, Vec2 b, const std::vector<std::pair<double, double>>& gaps)
{
	const Segment s(a, b);
	const double len = s.length();
	double from = 0;
	for (const auto& [g0, g1] : gaps)
	{
		if (g0 > from) walls.emplace_back(s.at(from / len), s.at(g0 / len));
		from = g1;
	}
	if (from < len) walls.emplace_back(s.at(from / len), b);
}

void World::addBox(double x0, double y0, double x1, double y1)
{
	const auto p = box(x0, y0, x1, y1);
	for (size_t i = 0; i < p.size(); i++) walls.emplace_back(p[i], p[(i + 1) % p.size()]);
}

void World::addDoor(Vec2 a, Vec2 b, double s, double w, int roomSide, std::vector<std::pair<double, double>>& gaps)
{
	const Segment wall(a, b);
	const double len = wall.length();
	const double dir = std::atan2(b.y - a.y, b.x - a.x);
	DoorSpec d;
	d.hinge = wall.at(s / len);
	d.length = w;
	d.closedAngle = dir;
	d.openAngle = dir + roomSide * M_PI / 2;
	doors.push_back(d);
	gaps.emplace_back(s, s + w);
}

std::vector<Vec2> World::box(double x0, double y0, double x1, double y1)
{
	return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

}  // namespace gridvector::sim
