#include "em/SelfCheck.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <unordered_map>

namespace gridvector
{
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

double PoseGraphFit::normalisedChi2() const
{
	const double redundancy = odometryDof + registrationDof - 3.0 * (double(std::max<size_t>(nodes, 1)) - 1);
	return redundancy > 0 ? (odometryChi2 + registrationChi2) / redundancy : std::numeric_limits<double>::quiet_NaN();
}

PoseGraphFit poseGraphFit(const PoseGraph& graph)
{
	PoseGraphFit f;
	f.nodes = graph.nodes().size();
	for (const PoseEdge& e : graph.edges())
	{
		const bool odometry = e.kind == EdgeKind::Odometry;
		if (!e.active)
		{
			f.inactive += !odometry;
			continue;
		}
		(odometry ? f.odometryEdges : f.registrationEdges)++;
		(odometry ? f.odometryChi2 : f.registrationChi2) += e.chi2;
		(odometry ? f.odometryDof : f.registrationDof) += odometry ? 3 : std::clamp(e.dof, 1, 3);
		f.downweighted += !odometry && e.scale < kDownweighted;
	}
	return f;
}

namespace
{
/** Bucket side of the static vectors' spatial index: a few vectors per bucket indoors, a beam of 80 m crosses
 * fewer than 200 buckets [m]. */
constexpr double kBucket = 1.0;

double cross(const TPoint2D& a, const TPoint2D& b, const TPoint2D& c)
{
	return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Every bucket the segment a-b passes, in order (Amanatides & Woo's traversal).
template <class F>
void forEachBucket(const TPoint2D& a, const TPoint2D& b, F&& f)
{
	int ix = int(std::floor(a.x / kBucket)), iy = int(std::floor(a.y / kBucket));
	const int ex = int(std::floor(b.x / kBucket)), ey = int(std::floor(b.y / kBucket));
	const double dx = b.x - a.x, dy = b.y - a.y;
	const int sx = dx > 0 ? 1 : -1, sy = dy > 0 ? 1 : -1;
	const double inf = std::numeric_limits<double>::infinity();
	const double tdx = dx != 0 ? kBucket / std::abs(dx) : inf, tdy = dy != 0 ? kBucket / std::abs(dy) : inf;
	double tx = dx != 0 ? ((sx > 0 ? (ix + 1) * kBucket : ix * kBucket) - a.x) / dx : inf;
	double ty = dy != 0 ? ((sy > 0 ? (iy + 1) * kBucket : iy * kBucket) - a.y) / dy : inf;
	const int steps = std::abs(ex - ix) + std::abs(ey - iy);
	for (int k = 0;; ++k)
	{
		if (!f(ix, iy) || k >= steps) return;
		if (tx < ty)
			ix += sx, tx += tdx;
		else
			iy += sy, ty += tdy;
	}
}

int64_t bucketKey(int ix, int iy) { return (int64_t(ix) << 32) ^ int64_t(uint32_t(iy)); }

class SegmentIndex
{
   public:
	explicit SegmentIndex(const std::vector<GridVector>& vs) : vs_(vs), seen_(vs.size(), 0)
	{
		for (uint32_t i = 0; i < vs.size(); ++i)
			forEachBucket(vs[i].start(), vs[i].end(), [&](int ix, int iy) {
				buckets_[bucketKey(ix, iy)].push_back(i);
				return true;
			});
	}

	enum Crossing
	{
		None,
		Geometric,  //!< ends behind a vector it crosses
		Occupied  //!< ... crossing it at an occupied cell
	};
	// Does the beam o-e cross a vector and end kThroughWall or more behind its line; at an occupied cell?
	Crossing throughWall(const TPoint2D& o, const TPoint2D& e)
	{
		++stamp_;
		Crossing worst = None;
		forEachBucket(o, e, [&](int ix, int iy) {
			const auto b = buckets_.find(bucketKey(ix, iy));
			if (b == buckets_.end()) return true;
			for (uint32_t i : b->second)
			{
				if (seen_[i] == stamp_) continue;
				seen_[i] = stamp_;
				worst = std::max(worst, crosses(i, o, e));
				if (worst == Occupied) return false;
			}
			return true;
		});
		return worst;
	}

   private:
	Crossing crosses(uint32_t i, const TPoint2D& o, const TPoint2D& e)
	{
		const GridVector& v = vs_[i];
		const TPoint2D &s = v.start(), &t = v.end();
		const double len = v.length();
		if (len <= 0) return None;
		const double co = cross(s, t, o), ce = cross(s, t, e);
		if ((co > 0) == (ce > 0) || std::abs(ce) < kThroughWall * len) return None;
		const double cs = cross(o, e, s), ct = cross(o, e, t);
		if ((cs > 0) == (ct > 0)) return None;
		const double u = len * cs / (cs - ct);  // the crossing, along the vector from its start
		return columnOccupied(i, u) ? Occupied : Geometric;
	}

	// Does a cell of the vector's column at u (metres from its start) hold occupancy above kOccupied?
	bool columnOccupied(uint32_t i, double u)
	{
		std::vector<bool>& cols = occupied_[i];
		const GridVector& v = vs_[i];
		if (cols.empty())
		{
			cols.assign(size_t(std::max(v.cols(), 1)), false);
			for (int c = 0; c < v.cols(); ++c)
				for (int r = 0; r < v.rows(); ++r)
					cols[size_t(c)] = cols[size_t(c)] || v.cell(r, c).occupancy(v.priorRatio()) > kOccupied;
		}
		const int c = std::clamp(int(std::floor(u / v.resolution())), 0, int(cols.size()) - 1);
		return cols[size_t(c)];
	}

	const std::vector<GridVector>& vs_;
	std::unordered_map<int64_t, std::vector<uint32_t>> buckets_;
	std::vector<uint32_t> seen_;
	uint32_t stamp_ = 0;
	std::unordered_map<uint32_t, std::vector<bool>> occupied_;  //!< per vector crossed: its columns' occupancy
};

TPoint2D compose(const TPose2D& p, const TPoint2D& q)
{
	const double c = std::cos(p.phi), s = std::sin(p.phi);
	return {p.x + c * q.x - s * q.y, p.y + s * q.x + c * q.y};
}
}  // namespace

BeamConsistency beamConsistency(const std::vector<GridVector>& staticMap, const std::vector<ScanBeams>& scans)
{
	SegmentIndex index(staticMap);
	BeamConsistency out;
	for (const ScanBeams& sc : scans)
	{
		const TPoint2D o = compose(sc.pose, sc.origin);
		for (const TPoint2D& q : sc.ends)
		{
			++out.beams;
			const auto c = index.throughWall(o, compose(sc.pose, q));
			out.throughWalls += c != SegmentIndex::None;
			out.throughOccupied += c == SegmentIndex::Occupied;
		}
	}
	return out;
}

SelfCheckEvidence selfCheckEvidence(bool converged, const std::vector<MStepReport>& iterations, size_t keyframes,
									const PoseGraphFit& fit, const BeamConsistency& beams,
									const std::vector<GridVector>& finalMap)
{
	SelfCheckEvidence e;
	e.converged = converged;
	e.keyframes = keyframes;
	e.iterations = iterations.size();
	for (const MStepReport& m : iterations)
		e.registrations += m.registrations, e.failedRegistrations += m.failedRegistrations;
	if (!iterations.empty())
	{
		const MStepReport& last = iterations.back();
		e.edges = last.constraints;
		e.sequentialEdges = last.sequential;
		e.rejectedEdges = last.constraints - std::min(last.active, last.constraints) + fit.downweighted;
	}
	e.graph = fit;
	e.beams = beams;
	for (const GridVector& v : finalMap)
		(v.state == VectorState::Dynamic ? e.dynamicLength : e.staticLength) += v.length();
	return e;
}

namespace
{
std::string reason(const char* what, double value, const char* op, double limit)
{
	char buf[160];
	std::snprintf(buf, sizeof buf, "%s %.3g %s %.3g", what, value, op, limit);
	return buf;
}
}  // namespace

SelfCheckVerdict judge(const SelfCheckEvidence& e)
{
	SelfCheckVerdict v;
	auto test = [&](bool bad, std::string why) {
		if (bad) v.reasons.push_back(std::move(why));
	};
	const double chi2 = e.graph.normalisedChi2();
	test(std::isfinite(chi2) && chi2 > kMaxNormalisedChi2, reason("normalised chi2", chi2, ">", kMaxNormalisedChi2));
	test(e.rejectedShare() > kMaxRejectedShare, reason("rejected edges", e.rejectedShare(), ">", kMaxRejectedShare));
	test(e.unlinkedShare() > kMaxUnlinkedShare,
		 reason("keyframes without a sequential edge", e.unlinkedShare(), ">", kMaxUnlinkedShare));
	test(!e.converged && e.failedShare() > kMaxFailedShareUnconverged,
		 reason("EM did not converge and failed registrations", e.failedShare(), ">", kMaxFailedShareUnconverged));
	test(
		!e.converged && e.dynamicShare() > kMaxDynamicShareUnconverged,
		reason("EM did not converge and dynamic share of the map", e.dynamicShare(), ">", kMaxDynamicShareUnconverged));
	v.ok = v.reasons.empty();
	return v;
}

std::string verdictLine(const SelfCheckVerdict& v)
{
	std::string why;
	for (const auto& r : v.reasons) why += (why.empty() ? "" : "; ") + r;
	return std::string("self-check: ") + (v.ok ? "ok" : "suspect (exit status 3): ") + why;
}

}  // namespace gridvector
