// Nearest points on the static stretches of the map's vectors (Eq. 14, Fig. 4 profile).
#include "mrpt/StaticFootPoints.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace gridvector
{
using mrpt::math::TPoint2D;

StaticFootPoints::StaticFootPoints(const GlobalMap& map, const GridVectorConfig& cfg, const StaticStretchTable* table)
	: map_(map), table_(table), estep_(cfg.estep, cfg.grid), threshold_(cfg.matching.staticThreshold)
{
	if (table_ && (table_->revision() != map.revision() || table_->size() != map.size()))
		throw std::invalid_argument("StaticFootPoints: the stretch table is not of the map's current state");
}

// Fig. 4: runs of columns whose profile is at or above the threshold, as [u0, u1] along the vector.
std::vector<std::pair<double, double>> StaticFootPoints::computeStretches(const GridVector& v) const
{
	std::vector<std::pair<double, double>> out;
	if (v.state == VectorState::Dynamic || v.cols() == 0) return out;  // Eq. 14: c_i = 0
	const std::vector<double> prof = estep_.profile(v);
	const double res = v.resolution(), len = v.length();
	int first = -1;
	for (int c = 0; c <= v.cols(); ++c)
	{
		const bool isStatic = c < v.cols() && prof[size_t(c)] >= threshold_;
		if (isStatic && first < 0) first = c;
		if (!isStatic && first >= 0)
		{
			out.emplace_back(std::min(first * res, len), std::min(c * res, len));
			first = -1;
		}
	}
	return out;
}

const std::vector<std::pair<double, double>>& StaticFootPoints::stretches(uint32_t slot) const
{
	if (table_) return table_->get(slot, [&] { return computeStretches(map_.vectors()[slot]); });
	auto it = stretches_.find(slot);
	if (it == stretches_.end()) it = stretches_.emplace(slot, computeStretches(map_.vectors()[slot])).first;
	return it->second;
}

namespace
{
/** The map's places on a vector's line are this many cells apart (0.025, 0.075, ... m from its
 * start at 10 cm cells): a place, not the continuous foot, so that ICP's pairs stop moving once
 * it has converged (with continuous feet every CICP step slid them a little, the step never fell
 * below CICP's 1e-6 and it ran into its iteration cap). Half a cell: MRPT's ICP test in 43
 * iterations, 4 mm off (a place per cell: 30, but 1.3 cm off on the corridor test). */
constexpr double kPlaceStep = 0.5;

int columnAt(const GridVector& v, double u) { return std::clamp(int(u / v.resolution()), 0, v.cols() - 1); }
}  // namespace

bool StaticFootPoints::footOn(uint32_t slot, const TPoint2D& p, double radius, FootPoint& out) const
{
	const GridVector& v = map_.vectors()[slot];
	const TPoint2D g = v.toGridFrame(p);  // (u along, w to the left)
	double best = radius * radius, bestU = 0;
	bool found = false;
	int bestCol = 0;
	for (const auto& [u0, u1] : stretches(slot))
	{
		const double q = v.resolution() * kPlaceStep;
		const double u = std::clamp((std::floor(std::clamp(g.x, u0, u1) / q) + 0.5) * q, u0, u1);
		const double d2 = (g.x - u) * (g.x - u) + g.y * g.y;
		if (d2 < best) best = d2, bestU = u, bestCol = columnAt(v, u), found = true;
	}
	if (!found) return false;
	const TPoint2D dir = v.direction();
	out.slot = slot;
	out.column = bestCol;
	out.at = TPoint2D(v.start().x + dir.x * bestU, v.start().y + dir.y * bestU);
	out.sqrDist = best;
	return true;
}

void StaticFootPoints::within(const TPoint2D& p, double radius, std::vector<FootPoint>& out) const
{
	slots_.clear();
	map_.index().query(Box2D{p.x, p.y, p.x, p.y}.expanded(radius), slots_);
	FootPoint f;
	for (uint32_t s : slots_)
		if (footOn(s, p, radius, f)) out.push_back(f);
}

bool StaticFootPoints::nearest(const TPoint2D& p, double radius, FootPoint& out) const
{
	slots_.clear();
	map_.index().query(Box2D{p.x, p.y, p.x, p.y}.expanded(radius), slots_);
	return nearestAmongSlots(p, radius, out);
}

bool StaticFootPoints::nearestAmongSlots(const TPoint2D& p, double radius, FootPoint& out) const
{
	bool found = false;
	FootPoint f;
	for (uint32_t s : slots_)
		if (footOn(s, p, radius, f)) out = f, radius = std::sqrt(f.sqrDist), found = true;
	return found;
}

bool StaticFootPoints::nearestAnywhere(const TPoint2D& p, FootPoint& out) const
{
	if (map_.empty()) return false;
	for (double r = map_.index().cellSize();; r *= 2)
	{
		if (nearest(p, r, out)) return true;
		// the box held every vector, none within r: the nearest of them, wherever it is
		if (slots_.size() >= map_.index().size())
			return nearestAmongSlots(p, std::numeric_limits<double>::infinity(), out);
	}
}

}  // namespace gridvector
