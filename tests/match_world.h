// Test helper: world segments (open side on the left) seen from a pose, as the
// MatchSegments VectorMatcher and LoopSearch consume.
#pragma once

#include "mstep/VectorMatcher.h"

#include <mrpt/math/TPose2D.h>

#include <cmath>
#include <random>
#include <vector>

namespace matchtest
{
struct WorldSeg
{
	double x1, y1, x2, y2;
};

/** `world` in the frame of `pose`, endpoints with Gaussian noise (0: exact); ids from firstId. */
inline std::vector<gridvector::MatchSegment> observe(const std::vector<WorldSeg>& world,
													 const mrpt::math::TPose2D& pose, double noise, unsigned seed,
													 uint64_t firstId)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> n(0, noise > 0 ? noise : 1.0);
	auto jitter = [&] { return noise > 0 ? n(rng) : 0.0; };
	const double c = std::cos(pose.phi), s = std::sin(pose.phi);
	auto local = [&](double x, double y) {
		const double dx = x - pose.x, dy = y - pose.y;
		return Eigen::Vector2d(c * dx + s * dy + jitter(), -s * dx + c * dy + jitter());
	};
	std::vector<gridvector::MatchSegment> out;
	for (const auto& w : world)
	{
		gridvector::MatchSegment m;
		m.s = local(w.x1, w.y1);
		m.e = local(w.x2, w.y2);
		m.length = (m.e - m.s).norm();
		m.id = firstId++;
		out.push_back(m);
	}
	return out;
}
}  // namespace matchtest
