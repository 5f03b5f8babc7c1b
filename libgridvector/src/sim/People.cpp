#include "sim/People.h"

#include <algorithm>

namespace gridvector::sim
{
namespace
{
size_t nearestNode(const WalkGraph& g, const Vec2& p)
{
	size_t best = 0;
	for (size_t i = 1; i < g.size(); i++)
		if ((g.node(i) - p).norm() < (g.node(best) - p).norm()) best = i;
	return best;
}
}  // namespace

Crowd::Crowd(const WalkGraph& graph, const std::vector<Segment>& walls, int count, const Vec2& robotStart, Random& rng,
			 double pauseS)
	: graph_(graph), walls_(walls), rng_(rng), pauseS_(pauseS)
{
	std::vector<size_t> starts;
	for (size_t i = 0; i < graph.size(); i++)
		if ((graph.node(i) - robotStart).norm() >= 3.0 && !graph.neighbours(i).empty()) starts.push_back(i);
	if (starts.empty()) return;
	for (int k = 0; k < count; k++)
	{
		Person p;
		p.kind = static_cast<Person::Kind>(k % 3);
		p.pos = graph.node(starts[size_t(rng_.uniformInt(0, int(starts.size()) - 1))]);
		p.radius = rng_.uniform(0.2, 0.28);
		p.speed = rng_.uniform(0.6, 1.3);
		if (p.kind == Person::Kind::Pauser) p.pauseLeft = pauserPause(0, 10);
		people_.push_back(p);
		newGoal(people_.back());
	}
}

// A pauser's pause: lo..hi s, or pauseS..2 pauseS s when set (one draw either way).
double Crowd::pauserPause(double lo, double hi)
{
	return pauseS_ > 0 ? rng_.uniform(pauseS_, 2 * pauseS_) : rng_.uniform(lo, hi);
}

void Crowd::newGoal(Person& p)
{
	const size_t from = nearestNode(graph_, p.pos);
	const double maxDist = p.kind == Person::Kind::Walker ? 1e9 : p.kind == Person::Kind::Pauser ? 6.0 : 4.0;
	std::vector<size_t> goals;
	for (size_t i = 0; i < graph_.size(); i++)
	{
		const double d = (graph_.node(i) - graph_.node(from)).norm();
		if (i != from && d <= maxDist && d >= 1.0) goals.push_back(i);
	}
	if (goals.empty()) return void(p.path.clear());
	p.path = graph_.shortestPath(from, goals[size_t(rng_.uniformInt(0, int(goals.size()) - 1))]);
	if (!p.path.empty() && (graph_.node(p.path.front()) - p.pos).norm() < 1e-9) p.path.erase(p.path.begin());
}

bool Crowd::freeOfWalls(const Vec2& c, double r) const
{
	return std::all_of(walls_.begin(), walls_.end(),
					   [&](const Segment& w) { return distanceToSegment(c, w) > r + 0.02; });
}

void Crowd::walk(Person& p, double dt, const Vec2& robot)
{
	double budget = p.speed * dt;
	Vec2 pos = p.pos;
	size_t reached = 0;
	while (budget > 1e-9 && reached < p.path.size())
	{
		const Vec2 d = graph_.node(p.path[reached]) - pos;
		const double len = d.norm();
		if (len <= budget)
			pos = graph_.node(p.path[reached++]), budget -= len;
		else
			pos = pos + d * (budget / len), budget = 0;
	}
	const double keep = p.radius + kRobotRadius + 0.05;
	const double now = (p.pos - robot).norm(), next = (pos - robot).norm();
	if (next < keep && next < now)
	{
		// the robot is in the way: step aside if it is too close, else wait
		const Vec2 away = now > 1e-6 ? (p.pos - robot) * (p.speed * dt / now) : Vec2(0, 0);
		if (now < keep && freeOfWalls(p.pos + away, p.radius)) p.pos = p.pos + away;
		p.waited += dt;
		if (p.waited > 4.0) p.waited = 0, newGoal(p);  // give up, go elsewhere
		return;
	}
	p.waited = 0;
	p.pos = pos;
	p.path.erase(p.path.begin(), p.path.begin() + long(reached));
}

void Crowd::step(double dt, const Vec2& robot)
{
	for (Person& p : people_)
	{
		if (p.pauseLeft > 0)
		{
			p.pauseLeft -= dt;
			continue;
		}
		if (p.path.empty())
		{
			const bool pause = rng_.chance(p.kind == Person::Kind::Pauser ? 0.7 : 0.2);
			if (pause) p.pauseLeft = p.kind == Person::Kind::Pauser ? pauserPause(4, 15) : rng_.uniform(1, 4);
			newGoal(p);
			continue;
		}
		walk(p, dt, robot);
	}
}

}  // namespace gridvector::sim
