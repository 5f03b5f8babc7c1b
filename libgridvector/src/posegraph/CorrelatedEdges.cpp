#include "posegraph/CorrelatedEdges.h"

#include <algorithm>
#include <map>
#include <utility>

namespace gridvector
{
namespace
{
bool grouped(const PoseEdge& e)
{
	return e.active && e.from != e.to && (e.kind == EdgeKind::Overlap || e.kind == EdgeKind::Loop);
}

// Runs of other ends at most `gap` apart among (other end, edge index) sorted by other end.
void weighRuns(std::vector<std::pair<uint32_t, size_t>>& ends, int gap, double rho, std::vector<double>& w)
{
	std::sort(ends.begin(), ends.end());
	for (size_t a = 0; a < ends.size();)
	{
		size_t b = a + 1;
		while (b < ends.size() && ends[b].first - ends[b - 1].first <= uint32_t(gap)) ++b;
		const double share = 1.0 / (1.0 + double(b - a - 1) * rho);
		for (size_t k = a; k < b; ++k) w[ends[k].second] = std::min(w[ends[k].second], share);
		a = b;
	}
}
}  // namespace

// Each group of n correlated registrations: n / (1 + (n - 1) rho) edges' worth (rho = 1: covariance intersection).
std::vector<double> correlatedEdgeWeights(const std::vector<PoseEdge>& edges, int gap, double rho)
{
	std::vector<double> w(edges.size(), 1.0);
	if (gap <= 0) return w;
	std::map<uint32_t, std::vector<std::pair<uint32_t, size_t>>> byScan;  // shared scan -> (other end, edge)
	for (size_t k = 0; k < edges.size(); ++k)
	{
		const PoseEdge& e = edges[k];
		if (!grouped(e)) continue;
		byScan[e.from].emplace_back(e.to, k);
		byScan[e.to].emplace_back(e.from, k);
	}
	for (auto& [scan, ends] : byScan)
		if (ends.size() > 1) weighRuns(ends, gap, rho, w);
	return w;
}

}  // namespace gridvector
