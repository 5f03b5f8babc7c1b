#include "sim/WalkGraph.h"

#include <algorithm>
#include <cmath>
#include <queue>

namespace gridvector::sim
{
namespace
{
constexpr double kEdgeMargin = 0.5, kLaneSpacing = 1.0, kStep = 1.5, kMaxEdge = 2.0;

/** Evenly spaced positions in [lo + margin, hi - margin], about `spacing` apart. */
std::vector<double> spread(double lo, double hi, double spacing)
{
	const double a = lo + kEdgeMargin, b = hi - kEdgeMargin;
	if (b <= a) return {0.5 * (lo + hi)};
	const int n = int(std::floor((b - a) / spacing)) + 1;
	std::vector<double> v;
	for (int i = 0; i < n; i++) v.push_back(n == 1 ? 0.5 * (a + b) : a + (b - a) * i / (n - 1));
	return v;
}
}  // namespace

WalkGraph::WalkGraph(const World& world, double clearance) : obstacles_(world.walls), clearance_(clearance)
{
	for (const auto& o : world.objects)
		for (const auto* poly : {&o.first, &o.second})
			for (size_t i = 0; i < poly->size(); i++)
				obstacles_.emplace_back((*poly)[i], (*poly)[(i + 1) % poly->size()]);
	for (const auto& d : world.doors)  // the area a door leaf sweeps
		for (int k = 0; k <= 6; k++)
			obstacles_.push_back(d.leaf(d.closedAngle + (d.openAngle - d.closedAngle) * k / 6.0));
	for (const auto& z : world.walkZones)
	{
		const bool alongX = z.x1 - z.x0 >= z.y1 - z.y0;
		const auto lanes = alongX ? spread(z.y0, z.y1, kLaneSpacing) : spread(z.x0, z.x1, kLaneSpacing);
		const auto steps = alongX ? spread(z.x0, z.x1, kStep) : spread(z.y0, z.y1, kStep);
		for (double l : lanes)
			for (double s : steps)
			{
				const Vec2 p = alongX ? Vec2(s, l) : Vec2(l, s);
				const bool duplicate =
					std::any_of(nodes_.begin(), nodes_.end(), [&](const Vec2& q) { return (q - p).norm() < 0.4; });
				if (!duplicate && clear({p, p})) nodes_.push_back(p);
			}
	}
	adj_.resize(nodes_.size());
	for (size_t i = 0; i < nodes_.size(); i++)
		for (size_t j = i + 1; j < nodes_.size(); j++)
			if ((nodes_[i] - nodes_[j]).norm() < kMaxEdge && clear({nodes_[i], nodes_[j]}))
			{
				adj_[i].push_back(j);
				adj_[j].push_back(i);
			}
}

bool WalkGraph::clear(const Segment& s) const
{
	return std::all_of(obstacles_.begin(), obstacles_.end(),
					   [&](const Segment& o) { return segmentDistance(s, o) >= clearance_; });
}

std::vector<size_t> WalkGraph::shortestPath(size_t a, size_t b) const
{
	std::vector<double> dist(nodes_.size(), kNoHit);
	std::vector<size_t> prev(nodes_.size(), size_t(-1));
	using Item = std::pair<double, size_t>;
	std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
	dist[a] = 0;
	q.push({0, a});
	while (!q.empty())
	{
		const auto [d, u] = q.top();
		q.pop();
		if (d > dist[u]) continue;
		if (u == b) break;
		for (size_t v : adj_[u])
		{
			const double nd = d + (nodes_[u] - nodes_[v]).norm();
			if (nd < dist[v]) dist[v] = nd, prev[v] = u, q.push({nd, v});
		}
	}
	if (dist[b] == kNoHit) return {};
	std::vector<size_t> path;
	for (size_t v = b; v != size_t(-1); v = prev[v]) path.push_back(v);
	std::reverse(path.begin(), path.end());
	return path;
}

}  // namespace gridvector::sim
