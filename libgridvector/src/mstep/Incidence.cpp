// mstep.register_min_incidence_deg: vectors seen only along their line (beyond the paper).
#include "mstep/Incidence.h"

#include <algorithm>
#include <cmath>

namespace gridvector
{
// A beam from the origin to a point p of the line meets it under asin(d / |p|), d the line's distance from the
// origin: largest at the segment's point nearest the origin.
double largestIncidence(const MatchSegment& v)
{
	const Eigen::Vector2d u = v.e - v.s;
	const double len2 = u.squaredNorm();
	if (len2 <= 0) return M_PI / 2;
	const double t = std::clamp(-v.s.dot(u) / len2, 0.0, 1.0);
	const double nearest = (v.s + t * u).norm();
	if (nearest <= 0) return M_PI / 2;
	const double d = std::abs(v.s.x() * u.y() - v.s.y() * u.x()) / std::sqrt(len2);
	return std::asin(std::min(1.0, d / nearest));
}

std::vector<std::vector<MatchSegment>> facingVectors(const std::vector<std::vector<MatchSegment>>& scans, double minDeg)
{
	const double minRad = minDeg * M_PI / 180;
	std::vector<std::vector<MatchSegment>> out(scans.size());
	for (size_t t = 0; t < scans.size(); ++t)
		for (const auto& v : scans[t])
			if (largestIncidence(v) >= minRad) out[t].push_back(v);
	return out;
}
}  // namespace gridvector
