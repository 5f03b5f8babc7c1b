#include "eval/TrajectoryEval.h"
#include "io/Counted.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace gridvector::eval
{
namespace
{
using mrpt::math::TPose2D;
using Pairs = PosePairs;

double wrap(double a) { return std::atan2(std::sin(a), std::cos(a)); }

/** b relative to a, in a's frame. */
TPose2D relative(const TPose2D& a, const TPose2D& b)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi), dx = b.x - a.x, dy = b.y - a.y;
	return {c * dx + s * dy, -s * dx + c * dy, wrap(b.phi - a.phi)};
}

/** Umeyama without scale: the rigid transform taking the estimate onto the reference. */
TPose2D bestAlignment(const Pairs& p)
{
	const double n = double(p.size());
	double mx = 0, my = 0, gx = 0, gy = 0;
	for (const auto& [e, g] : p) mx += e.x, my += e.y, gx += g.x, gy += g.y;
	mx /= n, my /= n, gx /= n, gy /= n;
	double sxx = 0, sxy = 0;
	for (const auto& [e, g] : p)
	{
		sxx += (e.x - mx) * (g.x - gx) + (e.y - my) * (g.y - gy);
		sxy += (e.x - mx) * (g.y - gy) - (e.y - my) * (g.x - gx);
	}
	const double th = std::atan2(sxy, sxx), c = std::cos(th), s = std::sin(th);
	return {gx - (c * mx - s * my), gy - (s * mx + c * my), th};
}

/** RMSE of the estimate after the best alignment. */
double alignedRmse(const Pairs& p)
{
	const TPose2D T = bestAlignment(p);
	const double c = std::cos(T.phi), s = std::sin(T.phi);
	double se = 0;
	for (const auto& [e, g] : p)
	{
		const double x = c * e.x - s * e.y + T.x, y = s * e.x + c * e.y + T.y;
		se += (x - g.x) * (x - g.x) + (y - g.y) * (y - g.y);
	}
	return std::sqrt(se / double(p.size()));
}

/** Mean translational [m] and rotational [deg] relation errors over index pairs. */
std::pair<double, double> relationErrors(const Pairs& p, const std::vector<std::pair<size_t, size_t>>& idx)
{
	if (idx.empty()) return {std::nan(""), std::nan("")};
	double st = 0, sr = 0;
	for (const auto& [i, j] : idx)
	{
		const TPose2D re = relative(p[i].first, p[j].first), rg = relative(p[i].second, p[j].second);
		st += std::hypot(re.x - rg.x, re.y - rg.y);
		sr += std::abs(wrap(re.phi - rg.phi) * 180.0 / M_PI);
	}
	return {st / double(idx.size()), sr / double(idx.size())};
}

std::string num(const char* fmt, double v)
{
	if (std::isnan(v)) return "nan";
	char b[64];
	std::snprintf(b, sizeof b, fmt, v);
	return b;
}

bool earlier(const io::Trajectory::value_type& a, const io::Trajectory::value_type& b) { return a.first < b.first; }

io::Trajectory sortedByTime(io::Trajectory t)
{
	std::stable_sort(t.begin(), t.end(), earlier);
	return t;
}

/** The index in `sorted` of the pose nearest in time to t, of the two around t, closer than maxTimeDiff; -1 if none. */
long nearestInTime(const io::Trajectory& sorted, double t, double maxTimeDiff)
{
	const auto it =
		std::lower_bound(sorted.begin(), sorted.end(), t, [](const auto& e, double v) { return e.first < v; });
	const long i = long(it - sorted.begin());
	long best = -1;
	for (long j : {i - 1, i})
		if (j >= 0 && j < long(sorted.size()) && std::abs(sorted[size_t(j)].first - t) < maxTimeDiff)
			if (best < 0 || std::abs(sorted[size_t(j)].first - t) < std::abs(sorted[size_t(best)].first - t)) best = j;
	return best;
}

Pairs matchSorted(const io::Trajectory& sorted, const io::Trajectory& ref, double maxTimeDiff,
				  std::vector<double>* times = nullptr)
{
	Pairs out;
	for (const auto& [t, g] : ref)
		if (const long j = nearestInTime(sorted, t, maxTimeDiff); j >= 0)
		{
			out.emplace_back(sorted[size_t(j)].second, g);
			if (times) times->push_back(t);
		}
	return out;
}

/** "" or why matching by time is arbitrary: "N different estimate poses at t = T", the nearest estimate
 * time of some reference pose. */
std::string timeTie(const io::Trajectory& sorted, const io::Trajectory& ref, double maxTimeDiff)
{
	for (const auto& r : ref)
	{
		const long j = nearestInTime(sorted, r.first, maxTimeDiff);
		if (j < 0) continue;
		const auto& e = sorted[size_t(j)];
		const auto [lo, hi] = std::equal_range(sorted.begin(), sorted.end(), e, earlier);
		if (std::any_of(lo, hi, [&](const auto& o) { return !(o.second == e.second); }))
		{
			char buf[96];
			std::snprintf(buf, sizeof buf, "%ld estimate poses share t = %.6f and differ", long(hi - lo), e.first);
			return buf;
		}
	}
	return "";
}
}  // namespace

Pairs matchByTimestamp(const io::Trajectory& est, const io::Trajectory& ref, double maxTimeDiff)
{
	return matchSorted(sortedByTime(est), ref, maxTimeDiff);
}

PoseMatch matchPoses(const io::Trajectory& est, const io::Trajectory& ref, double maxTimeDiff)
{
	const io::Trajectory sorted = sortedByTime(est);
	PoseMatch m;
	m.why = timeTie(sorted, ref, maxTimeDiff);
	if (m.why.empty())
	{
		m.pairs = matchSorted(sorted, ref, maxTimeDiff, &m.times);
		return m;
	}
	size_t i = 0;
	while (i < est.size() && i < ref.size() && std::abs(est[i].first - ref[i].first) < maxTimeDiff) ++i;
	if (est.size() != ref.size() || i < est.size())
		throw std::runtime_error(
			m.why +
			": matching by time would pick one of them, and matching by order needs one pose per scan of the same log "
			"(" +
			std::to_string(est.size()) + " estimate and " + io::counted(ref.size(), "reference pose") +
			(est.size() == ref.size() ? ", pose " + std::to_string(i + 1) + " at other times" : "") + ")");
	m.byOrder = true;
	for (i = 0; i < est.size(); ++i)
		m.pairs.emplace_back(est[i].second, ref[i].second), m.times.push_back(ref[i].first);
	return m;
}

TrajectoryMetrics evaluatePairs(const Pairs& p, const TrajectoryEvalOptions& opt)
{
	const size_t n = p.size();
	if (n < 3) throw std::runtime_error("too few matched poses (" + std::to_string(n) + ")");
	TrajectoryMetrics m;
	m.matched = n;
	m.ateRmse = alignedRmse(p);
	std::vector<std::pair<size_t, size_t>> cons, loops;
	for (size_t i = 0; i + 1 < n; i++) cons.emplace_back(i, i + 1);
	for (size_t i = 0; i < n; i++)
		for (size_t j = i + opt.loopMinSeparation; j < n; j++)
			if (std::hypot(p[i].second.x - p[j].second.x, p[i].second.y - p[j].second.y) < opt.loopDistance)
				loops.emplace_back(i, j);
	const size_t stride = std::max<size_t>(1, loops.size() / opt.maxLoopPairs);
	std::vector<std::pair<size_t, size_t>> thinned;
	for (size_t k = 0; k < loops.size(); k += stride) thinned.push_back(loops[k]);
	std::tie(m.localT, m.localRDeg) = relationErrors(p, cons);
	std::tie(m.loopT, m.loopRDeg) = relationErrors(p, thinned);
	m.localPairs = cons.size();
	m.loopPairs = thinned.size();
	return m;
}

TrajectoryMetrics evaluateTrajectory(const io::Trajectory& est, const io::Trajectory& ref,
									 const TrajectoryEvalOptions& opt)
{
	return evaluatePairs(matchByTimestamp(est, ref, opt.maxTimeDiff), opt);
}

std::string formatText(const TrajectoryMetrics& m)
{
	return "n=" + std::to_string(m.matched) + " ate_rmse_m=" + num("%.4f", m.ateRmse) +
		   " rel_local_t_m=" + num("%.4f", m.localT) + " rel_local_r_deg=" + num("%.3f", m.localRDeg) +
		   " rel_loop_t_m=" + num("%.4f", m.loopT) + " rel_loop_r_deg=" + num("%.3f", m.loopRDeg) +
		   " loop_pairs=" + std::to_string(m.loopPairs);
}

nlohmann::ordered_json toJson(const TrajectoryMetrics& m)
{
	return {{"n", m.matched},
			{"ate_rmse_m", m.ateRmse},
			{"rel_local_t_m", m.localT},
			{"rel_local_r_deg", m.localRDeg},
			{"local_pairs", m.localPairs},
			{"rel_loop_t_m", m.loopT},
			{"rel_loop_r_deg", m.loopRDeg},
			{"loop_pairs", m.loopPairs}};
}

TPose2D alignmentTransform(const Pairs& p)
{
	if (p.size() < 3) throw std::runtime_error("too few matched poses (" + std::to_string(p.size()) + ")");
	return bestAlignment(p);
}

TPose2D alignmentTransform(const io::Trajectory& est, const io::Trajectory& ref, double maxTimeDiff)
{
	return alignmentTransform(matchPoses(est, ref, maxTimeDiff).pairs);
}

LocalizationMetrics evaluateLocalization(const Pairs& p, const std::vector<double>& times, double threshold)
{
	const size_t n = p.size();
	if (n < 3) throw std::runtime_error("too few matched poses (" + std::to_string(n) + ")");
	if (times.size() != n) throw std::invalid_argument("evaluateLocalization: one time per pair");
	std::vector<double> err(n);
	for (size_t i = 0; i < n; ++i) err[i] = std::hypot(p[i].first.x - p[i].second.x, p[i].first.y - p[i].second.y);
	LocalizationMetrics m;
	m.matched = n;
	double sum = 0;
	for (double e : err) sum += e * e;
	m.rmse = std::sqrt(sum / double(n));
	m.finalT = err.back();
	m.finalRDeg = std::abs(wrap(p.back().first.phi - p.back().second.phi)) * 180.0 / M_PI;
	m.converged = m.finalT < threshold;
	if (const auto below = std::find_if(err.begin(), err.end(), [&](double e) { return e < threshold; });
		below != err.end())
		m.firstBelow = times[size_t(below - err.begin())] - times.front();
	if (!m.converged) return m;
	size_t from = n - 1;
	while (from > 0 && err[from - 1] < threshold) --from;
	m.convergedAfter = times[from] - times.front();
	double after = 0, worst = 0;
	for (size_t i = from; i < n; ++i) after += err[i] * err[i], worst = std::max(worst, err[i]);
	m.rmseAfter = std::sqrt(after / double(n - from));
	m.maxAfter = worst;
	return m;
}

std::string formatText(const LocalizationMetrics& m)
{
	return "n=" + std::to_string(m.matched) + " abs_rmse_m=" + num("%.4f", m.rmse) +
		   " final_t_m=" + num("%.4f", m.finalT) + " final_r_deg=" + num("%.3f", m.finalRDeg) +
		   " first_below_s=" + num("%.1f", m.firstBelow) + " converged=" + (m.converged ? "yes" : "no") +
		   " converged_after_s=" + num("%.1f", m.convergedAfter) + " rmse_after_m=" + num("%.4f", m.rmseAfter) +
		   " max_after_m=" + num("%.4f", m.maxAfter);
}

nlohmann::ordered_json toJson(const LocalizationMetrics& m)
{
	return {{"n", m.matched},
			{"abs_rmse_m", m.rmse},
			{"final_t_m", m.finalT},
			{"final_r_deg", m.finalRDeg},
			{"first_below_s", m.firstBelow},
			{"converged", m.converged},
			{"converged_after_s", m.convergedAfter},
			{"rmse_after_m", m.rmseAfter},
			{"max_after_m", m.maxAfter}};
}

}  // namespace gridvector::eval
