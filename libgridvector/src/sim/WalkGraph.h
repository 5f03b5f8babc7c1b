// Where simulated people can walk: a graph of free-space points in the world's
// walk zones, with edges that keep clear of walls and furniture.
#pragma once

#include "sim/World.h"

#include <vector>

namespace gridvector::sim
{
class WalkGraph
{
   public:
	/** Nodes on lanes along each walk zone (lane spacing ~1 m, 0.5 m from its edges,
	 * every ~1.5 m along it), kept if at least `clearance` from every wall and from
	 * both footprints of every movable object and from
	 * the area each door leaf sweeps; edges join nodes closer than 2 m
	 * whose connecting segment keeps the same clearance. */
	WalkGraph(const World& world, double clearance);

	size_t size() const { return nodes_.size(); }
	const Vec2& node(size_t i) const { return nodes_[i]; }
	const std::vector<size_t>& neighbours(size_t i) const { return adj_[i]; }
	/** Node sequence from a to b (both included); empty if unreachable. */
	std::vector<size_t> shortestPath(size_t a, size_t b) const;

   private:
	bool clear(const Segment& s) const;
	std::vector<Segment> obstacles_;
	double clearance_;
	std::vector<Vec2> nodes_;
	std::vector<std::vector<size_t>> adj_;
};

}  // namespace gridvector::sim
