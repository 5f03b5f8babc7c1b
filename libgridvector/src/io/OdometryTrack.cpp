#include "io/OdometryTrack.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>

namespace gridvector::io
{
void OdometryTrack::add(double t, const mrpt::math::TPose2D& pose)
{
	if (!samples_.empty() && t < samples_.back().first) sorted_ = false;
	samples_.emplace_back(t, pose);
}

void OdometryTrack::sortIfNeeded() const
{
	if (sorted_) return;
	std::stable_sort(samples_.begin(), samples_.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
	sorted_ = true;
}

std::optional<mrpt::math::TPose2D> OdometryTrack::at(double t) const
{
	if (samples_.empty()) return std::nullopt;
	sortIfNeeded();
	const auto it =
		std::lower_bound(samples_.begin(), samples_.end(), t, [](const auto& s, double v) { return s.first < v; });
	if (it == samples_.begin()) return it->second;
	if (it == samples_.end()) return samples_.back().second;
	const auto& [t1, p1] = *it;
	const auto& [t0, p0] = *(it - 1);
	const double f = t1 > t0 ? (t - t0) / (t1 - t0) : 1.0;
	const double dphi = mrpt::math::wrapToPi(p1.phi - p0.phi);
	return mrpt::math::TPose2D(p0.x + f * (p1.x - p0.x), p0.y + f * (p1.y - p0.y),
							   mrpt::math::wrapToPi(p0.phi + f * dphi));
}

}  // namespace gridvector::io
