#include "extraction/VectorExtractor.h"

#include <algorithm>
#include <cmath>

namespace gridvector
{
using mrpt::math::TPoint2D;

namespace
{
// cos/sin of every beam angle, cached per thread for the last scan geometry.
struct BeamTrig
{
	size_t n = 0;
	float aperture = 0;
	bool rightToLeft = true;
	std::vector<double> c, s;
	const BeamTrig& update(const mrpt::obs::CObservation2DRangeScan& scan)
	{
		if (scan.getScanSize() == n && scan.aperture == aperture && scan.rightToLeft == rightToLeft) return *this;
		n = scan.getScanSize(), aperture = scan.aperture, rightToLeft = scan.rightToLeft;
		c.resize(n), s.resize(n);
		for (size_t i = 0; i < n; ++i) c[i] = std::cos(scan.getScanAngle(i)), s[i] = std::sin(scan.getScanAngle(i));
		return *this;
	}
};
}  // namespace

VectorExtractor::VectorExtractor(const ExtractionOptions& ext, const GridOptions& grid) : ext_(ext), grid_(grid) {}

void VectorExtractor::scanToRuns(const mrpt::obs::CObservation2DRangeScan& scan, std::vector<TPoint2D>& pts,
								 std::vector<size_t>& runStarts) const
{
	pts.clear();
	runStarts.clear();
	const size_t n = scan.getScanSize();
	const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y(), syaw = scan.sensorPose.yaw();
	const double cs = std::cos(syaw), ss = std::sin(syaw);
	const double dPhi = n > 1 ? std::abs(scan.aperture) / (n - 1) : 0.0;
	// Borges & Aldon adaptive breakpoint: D = r sin(dphi) / sin(lambda - dphi) + k sigma (k: break_noise_sigmas, theirs
	// 3)
	const double lambda = ext_.breakAngleDeg * M_PI / 180.0;
	const double adaptive = std::sin(dPhi) / std::max(1e-6, std::sin(lambda - dPhi));
	const double noiseAllowance = ext_.breakNoiseSigmas * std::max(0.0f, scan.stdError);
	thread_local BeamTrig trigCache;
	const BeamTrig& trig = trigCache.update(scan);
	bool prevValid = false;
	double prevR = 0;
	for (size_t i = 0; i < n; ++i)
	{
		const float r = scan.getScanRange(i);
		if (!validBeam(scan, i))
		{
			prevValid = false;
			continue;
		}
		const double lx = r * trig.c[i], ly = r * trig.s[i];
		const TPoint2D p(sx + cs * lx - ss * ly, sy + ss * lx + cs * ly);
		bool brk = !prevValid;
		if (!brk)
		{
			const double jump = std::hypot(p.x - pts.back().x, p.y - pts.back().y);
			brk = jump > std::min(ext_.maxPointGap, std::max(ext_.breakDistance, prevR * adaptive + noiseAllowance));
		}
		if (brk) runStarts.push_back(pts.size());
		pts.push_back(p);
		prevValid = true;
		prevR = r;
	}
}

/** Readings within this of the scanner's maxRange are "no hit": a float tolerance on the
 * value scanners write for no return, not a model choice [m]. */
constexpr double kMaxRangeMargin = 0.01;

bool VectorExtractor::validBeam(const mrpt::obs::CObservation2DRangeScan& scan, size_t i) const
{
	const float r = scan.getScanRange(i);
	return scan.getScanRangeValidity(i) && std::isfinite(r) && r > ext_.minRange && r < scan.maxRange - kMaxRangeMargin;
}

void VectorExtractor::scanToPoints(const mrpt::obs::CObservation2DRangeScan& scan, std::vector<TPoint2D>& pts,
								   size_t stride) const
{
	pts.clear();
	const size_t n = scan.getScanSize();
	const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y(), syaw = scan.sensorPose.yaw();
	const double cs = std::cos(syaw), ss = std::sin(syaw);
	thread_local BeamTrig trigCache;
	const BeamTrig& trig = trigCache.update(scan);
	size_t valid = 0;
	for (size_t i = 0; i < n; ++i)
	{
		if (!validBeam(scan, i) || valid++ % std::max<size_t>(1, stride) != 0) continue;
		const double r = scan.getScanRange(i), lx = r * trig.c[i], ly = r * trig.s[i];
		pts.emplace_back(sx + cs * lx - ss * ly, sy + ss * lx + cs * ly);
	}
}

bool VectorExtractor::fitSegment(const std::vector<TPoint2D>& pts, const PrefixMoments& pm, size_t i, size_t j,
								 ScanSegment& seg, double maxResidual) const
{
	const LineMoments m = pm.range(i, j + 1);
	if (!m.fit(seg.line)) return false;
	// RMS <= max: a joint fit whose RMS already exceeds the bound cannot pass it.
	if (maxResidual > 0 && m.residual(seg.line) > maxResidual * maxResidual * m.w) return false;
	seg.first = i;
	seg.last = j;
	seg.maxResidual = 0;
	const double c = std::cos(seg.line.theta), s = std::sin(seg.line.theta), rho = seg.line.rho;
	for (size_t k = i; k <= j; ++k)
		seg.maxResidual = std::max(seg.maxResidual, std::abs(c * pts[k].x + s * pts[k].y - rho));
	return maxResidual <= 0 || seg.maxResidual <= maxResidual;
}

// Split step: end-point fit, splitting at the point farthest from the chord; depth first, left part first
// (an explicit stack: a run of 10^5 points must not take 10^5 frames).
void VectorExtractor::split(const std::vector<TPoint2D>& pts, const PrefixMoments& pm, size_t first, size_t last,
							double threshold, std::vector<ScanSegment>& out) const
{
	std::vector<std::pair<size_t, size_t>> todo{{first, last}};
	while (!todo.empty())
	{
		const auto [i, j] = todo.back();
		todo.pop_back();
		if (j <= i) continue;
		const TPoint2D a = pts[i], b = pts[j];
		const double len = std::hypot(b.x - a.x, b.y - a.y);
		double best = 0;
		size_t k = i;
		if (len > 1e-9)
		{
			for (size_t q = i + 1; q < j; ++q)
			{
				const double d = std::abs((b.x - a.x) * (a.y - pts[q].y) - (a.x - pts[q].x) * (b.y - a.y)) / len;
				if (d > best) best = d, k = q;
			}
		}
		ScanSegment seg;
		if (best <= threshold && fitSegment(pts, pm, i, j, seg))
		{
			out.push_back(seg);
			continue;
		}
		if (k == i) k = (i + j) / 2;  // degenerate chord (coincident ends): bisect
		if (k == i) continue;  // two points whose fit fails (non-finite or absurd coordinates): no segment
		todo.emplace_back(k, j);
		todo.emplace_back(i, k);
	}
}

VectorExtractor::FitTolerance VectorExtractor::tolerance(double rangeSigma) const
{
	const double noise = ext_.noiseAllowance(rangeSigmaOf(rangeSigma));
	return {std::max(ext_.splitThreshold, noise), std::max(ext_.mergeThreshold, noise)};
}

// Merge step: neighbouring segments whose joint least-squares fit stays tight.
std::vector<ScanSegment> VectorExtractor::splitAndMerge(const std::vector<TPoint2D>& pts, size_t first, size_t last,
														double rangeSigma) const
{
	std::vector<ScanSegment> segs;
	const PrefixMoments pm(pts, first, last + 1);
	const FitTolerance tol = tolerance(rangeSigma);
	split(pts, pm, first, last, tol.split, segs);
	bool merged = true;
	while (merged && segs.size() > 1)
	{
		merged = false;
		for (size_t s = 0; s + 1 < segs.size(); ++s)
		{
			ScanSegment joint;
			if (fitSegment(pts, pm, segs[s].first, segs[s + 1].last, joint, tol.merge))
			{
				segs[s] = joint;
				segs.erase(segs.begin() + long(s) + 1);
				merged = true;
			}
		}
	}
	return segs;
}

// Sec. 3.1: the endpoints are the outermost feet of the perpendiculars from the segment's points onto its
// Eq. 3 line, ordered so the open space (the sensor) lies on the left (Fig. 1); the cells by Algorithm 1.
GridVector VectorExtractor::makeVector(const std::vector<TPoint2D>& pts, const ScanSegment& seg,
									   const TPoint2D& sensor) const
{
	const TPoint2D d(-std::sin(seg.line.theta), std::cos(seg.line.theta));
	size_t kmin = seg.first, kmax = seg.first;
	double umin = 1e300, umax = -1e300;
	for (size_t k = seg.first; k <= seg.last; ++k)
	{
		const double u = pts[k].x * d.x + pts[k].y * d.y;
		if (u < umin) umin = u, kmin = k;
		if (u > umax) umax = u, kmax = k;
	}
	TPoint2D s = seg.line.project(pts[kmin]), e = seg.line.project(pts[kmax]);
	// Open space (the sensor) on the left: cross(e - s, sensor - s) > 0.
	if ((e.x - s.x) * (sensor.y - s.y) - (e.y - s.y) * (sensor.x - s.x) < 0) std::swap(s, e);
	GridVector v(s, e, grid_);
	for (size_t k = seg.first; k <= seg.last; ++k) v.addEndpoint(pts[k]);  // Algorithm 1
	return v;
}

// Sec. 3.1: z_t ~ [v_{1,t}, ..., v_{n,t}], the local map V_t of one scan.
LocalScan VectorExtractor::extract(const mrpt::obs::CObservation2DRangeScan& scan) const
{
	LocalScan out;
	out.sensorOrigin = TPoint2D(scan.sensorPose.x(), scan.sensorPose.y());
	out.timestamp = mrpt::Clock::toDouble(scan.timestamp);
	std::vector<TPoint2D> pts;
	std::vector<size_t> runs;
	scanToRuns(scan, pts, runs);
	out.validBeams = pts.size();
	out.rangeSigma = rangeSigmaOf(scan.stdError);
	runs.push_back(pts.size());
	for (size_t r = 0; r + 1 < runs.size(); ++r)
	{
		if (runs[r + 1] - runs[r] < size_t(ext_.minPoints)) continue;
		for (const auto& seg : splitAndMerge(pts, runs[r], runs[r + 1] - 1, out.rangeSigma))
		{
			if (seg.last - seg.first + 1 < size_t(ext_.minPoints)) continue;
			GridVector v = makeVector(pts, seg, out.sensorOrigin);
			if (v.length() < ext_.minLength) continue;
			out.vectors.push_back(std::move(v));
		}
	}
	return out;
}

}  // namespace gridvector
