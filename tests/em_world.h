// A synthetic corridor loop for the EM-SLAM tests: directed walls (open side on
// the left), a robot path around the central block, drifting odometry, and the
// local maps V_t each pose sees (grid vectors with Algorithm 1 points).
#pragma once

#include <gridvector/GridVector.h>
#include <mrpt/math/TPose2D.h>
#include "extraction/VectorExtractor.h"
#include "mstep/VectorMatcher.h"

#include <cmath>
#include <random>
#include <vector>

namespace emtest
{
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

struct Wall
{
	double x1, y1, x2, y2;
};

/** A 16 x 10 m ring corridor (2 m wide) around a 12 x 6 m block; door frames
 * every 2 m on the outer wall break the corridor's symmetry along its axis. */
inline std::vector<Wall> corridorWorld()
{
	std::vector<Wall> w;
	// outer wall, counter-clockwise seen from inside, in 2 m panels with 0.2 m recesses
	auto panels = [&](double x0, double y0, double x1, double y1, double nx, double ny) {
		const double len = std::hypot(x1 - x0, y1 - y0);
		const int n = int(len / 2.0);
		const double dx = (x1 - x0) / len, dy = (y1 - y0) / len;
		for (int k = 0; k < n; ++k)
		{
			const double a = 2.0 * k, b = 2.0 * k + 1.6;
			w.push_back({x0 + dx * a, y0 + dy * a, x0 + dx * b, y0 + dy * b});
			// recess: two short walls perpendicular to the corridor
			const double px = x0 + dx * b, py = y0 + dy * b, qx = x0 + dx * (b + 0.4), qy = y0 + dy * (b + 0.4);
			w.push_back({px, py, px - nx * 0.3, py - ny * 0.3});
			w.push_back({qx - nx * 0.3, qy - ny * 0.3, qx, qy});
		}
	};
	panels(0, 0, 16, 0, 0, 1);
	panels(16, 0, 16, 10, -1, 0);
	panels(16, 10, 0, 10, 0, -1);
	panels(0, 10, 0, 0, 1, 0);
	// central block, clockwise (open side towards the corridor)
	w.push_back({2, 2, 2, 8});
	w.push_back({2, 8, 14, 8});
	w.push_back({14, 8, 14, 2});
	w.push_back({14, 2, 2, 2});
	return w;
}

/** Poses around the ring (counter-clockwise), `laps` times, every `step` metres. */
inline std::vector<TPose2D> ringPath(int laps, double step)
{
	std::vector<TPose2D> p;
	const double cx[4] = {1, 15, 15, 1}, cy[4] = {1, 1, 9, 9};
	for (int l = 0; l < laps; ++l)
		for (int side = 0; side < 4; ++side)
		{
			const double x0 = cx[side], y0 = cy[side], x1 = cx[(side + 1) % 4], y1 = cy[(side + 1) % 4];
			const double len = std::hypot(x1 - x0, y1 - y0), th = std::atan2(y1 - y0, x1 - x0);
			for (double d = 0; d < len - 1e-9; d += step)
				p.emplace_back(x0 + d * (x1 - x0) / len, y0 + d * (y1 - y0) / len, th);
		}
	return p;
}

/** Odometry: relative motions with seeded noise and a yaw drift (as mkbench.py). */
inline std::vector<TPose2D> odometryOf(const std::vector<TPose2D>& truth, unsigned seed, double driftDegPerM = 2.0)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> n(0, 1);
	std::vector<TPose2D> o{TPose2D(0, 0, 0)};
	for (size_t i = 1; i < truth.size(); ++i)
	{
		TPose2D d = truth[i] - truth[i - 1];
		const double dist = std::hypot(d.x, d.y);
		d.x *= 1 + 0.03 * n(rng);
		d.y *= 1 + 0.03 * n(rng);
		d.phi += 0.01 * n(rng) + driftDegPerM * M_PI / 180 * dist;
		o.push_back(o.back() + d);
	}
	return o;
}

/** What pose x sees of `walls` within `range`: the visible (facing) parts as grid
 * vectors in the robot frame, each filled with points every 5 cm (Algorithm 1). */
inline gridvector::LocalScan observe(const std::vector<Wall>& walls, const TPose2D& x, double range, unsigned seed,
									 double noise = 0.005)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> n(0, noise);
	gridvector::LocalScan s;
	const double c = std::cos(x.phi), sn = std::sin(x.phi);
	auto local = [&](double wx, double wy) {
		const double dx = wx - x.x, dy = wy - x.y;
		return TPoint2D(c * dx + sn * dy, -sn * dx + c * dy);
	};
	for (const auto& w : walls)
	{
		TPoint2D a = local(w.x1, w.y1), b = local(w.x2, w.y2);
		if ((b.x - a.x) * (-a.y) - (b.y - a.y) * (-a.x) <= 0) continue;  // robot not on the open side
		// clip to the disc of radius `range` (parametric)
		const double dx = b.x - a.x, dy = b.y - a.y, A = dx * dx + dy * dy;
		const double B = 2 * (a.x * dx + a.y * dy), C = a.x * a.x + a.y * a.y - range * range;
		const double disc = B * B - 4 * A * C;
		if (disc <= 0) continue;
		const double t0 = std::max(0.0, (-B - std::sqrt(disc)) / (2 * A));
		const double t1 = std::min(1.0, (-B + std::sqrt(disc)) / (2 * A));
		if ((t1 - t0) * std::sqrt(A) < 0.3) continue;
		const TPoint2D p(a.x + t0 * dx, a.y + t0 * dy), q(a.x + t1 * dx, a.y + t1 * dy);
		gridvector::GridVector v(p, q, gridvector::GridOptions{});
		const double len = (t1 - t0) * std::sqrt(A);
		for (double u = 0.025; u < len; u += 0.05)
			v.addEndpoint(TPoint2D(p.x + (q.x - p.x) * u / len, p.y + (q.y - p.y) * u / len + n(rng)));
		s.vectors.push_back(v);
	}
	return s;
}

inline double ate(const std::vector<TPose2D>& est, const std::vector<TPose2D>& truth)
{
	// align the first poses, then RMS of the positions
	const TPose2D d = truth[0] + (TPose2D(0, 0, 0) - est[0]);
	double s = 0;
	for (size_t i = 0; i < est.size(); ++i)
	{
		const TPose2D e = d + est[i];
		s += std::pow(e.x - truth[i].x, 2) + std::pow(e.y - truth[i].y, 2);
	}
	return std::sqrt(s / est.size());
}

}  // namespace emtest
