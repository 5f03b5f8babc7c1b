// Walking people: circles that walk the walk graph between random goals, some
// pausing for long, some zig-zagging across the corridor in front of the robot,
// and stepping out of the robot's way.
#pragma once

#include "sim/Random.h"
#include "sim/WalkGraph.h"

#include <vector>

namespace gridvector::sim
{
struct Person
{
	enum class Kind
	{
		Walker,  //!< far goals, short pauses
		Pauser,  //!< near goals, long pauses (chatting, reading a notice)
		Crosser  //!< near goals: crosses back and forth in front of the robot
	};
	Kind kind = Kind::Walker;
	Vec2 pos;
	double radius = 0.25;
	double speed = 1.0;
	std::vector<size_t> path;  //!< walk-graph nodes still to visit
	double pauseLeft = 0;  //!< seconds
	double waited = 0;  //!< seconds blocked by the robot
};

class Crowd
{
   public:
	/** count people at random nodes at least 3 m from the robot's start; pauseS > 0: a pauser's
	 * pauses last pauseS..2 pauseS s (0: 4-15 s). */
	Crowd(const WalkGraph& graph, const std::vector<Segment>& walls, int count, const Vec2& robotStart, Random& rng,
		  double pauseS = 0);
	/** Advances everyone by dt seconds; robot is the robot's current position. */
	void step(double dt, const Vec2& robot);
	const std::vector<Person>& people() const { return people_; }

	static constexpr double kRobotRadius = 0.3;

   private:
	void newGoal(Person& p);
	void walk(Person& p, double dt, const Vec2& robot);
	bool freeOfWalls(const Vec2& c, double r) const;
	double pauserPause(double lo, double hi);

	const WalkGraph& graph_;
	const std::vector<Segment>& walls_;
	Random& rng_;
	double pauseS_;
	std::vector<Person> people_;
};

}  // namespace gridvector::sim
