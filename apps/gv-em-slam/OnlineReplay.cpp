#include "OnlineReplay.h"
#include "EmOutputs.h"

#include "online/OnlineEmSlam.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <ctime>
#include <limits>

namespace gridvector::app
{
using Clock = std::chrono::steady_clock;

namespace
{
double since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// CPU time of this thread [s]: what a scan costs on one core, whatever else the machine runs.
double threadSeconds()
{
	timespec ts{};
	clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
	return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// The q-quantile (nearest rank) of `v` [s], in ms.
double quantileMs(std::vector<double> v, double q)
{
	if (v.empty()) return 0;
	const size_t k = std::min(v.size() - 1, size_t(std::ceil(q * double(v.size()))) - (q > 0 ? 1 : 0));
	std::nth_element(v.begin(), v.begin() + long(k), v.end());
	return 1e3 * v[k];
}

// Debugging aid, as the batch's edges_<k>.txt (main.cpp): GV_EM_DEBUG_DIR=dir writes dir/online_edges_<stage>.txt,
// the online graph's registration edges (writeEdgeDump, for bench/em-slam/edge_errors.py).
void dumpEdges(const online::OnlineEmSlam& slam, const GridVectorConfig& cfg, const char* stage)
{
	const char* dir = std::getenv("GV_EM_DEBUG_DIR");
	if (!dir) return;
	writeEdgeDump(std::string(dir) + "/online_edges_" + stage + ".txt", slam.constraints(), slam.keyframes(),
				  [&](const Constraint& c) { return graphInformation(c, cfg.mstep); });
}
}  // namespace

OnlineReplay replayOnline(const io::LogData& log, const std::vector<mrpt::math::TPose2D>& odometry,
						  const VectorExtractor& ex, const GridVectorConfig& cfg, io::Progress& progress,
						  bool keepVectors)
{
	OnlineReplay out;
	online::OnlineEmSlam slam(cfg);
	const size_t n = log.scans.size();
	out.scans.reserve(n), out.causal.reserve(n), out.latency.reserve(n), out.synchronous.reserve(n);
	for (size_t t = 0; t < n; ++t)
	{
		progress.show("online EM-SLAM", t + 1, n);
		const auto t0 = Clock::now();
		const double c0 = threadSeconds();
		LocalScan s = ex.extract(*log.scans[t].scan);
		s.scanIndex = int64_t(t);
		s.timestamp = log.scans[t].timestamp;
		const online::OnlineStep st = slam.addScan(s, odometry[t]);
		double bg = 0, bgCpu = 0;
		if (slam.optimisationDue())
		{
			auto job = slam.takeOptimisation();
			const auto tb = Clock::now();
			const double cb = threadSeconds();
			slam.runOptimisation(job);
			bg = since(tb), bgCpu = threadSeconds() - cb;
			out.background.push_back(bg), out.backgroundCpu.push_back(bgCpu);
			slam.applyOptimisation(job);
		}
		out.latency.push_back(since(t0) - bg);
		out.latencyCpu.push_back(threadSeconds() - c0 - bgCpu);
		out.synchronous.push_back(out.latency.back() + bg);
		out.causal.push_back(st.pose);
		out.loopScans += st.loops > 0;
		out.registeredScans += st.registered;
		out.localVectors += s.vectors.size();
		if (!keepVectors) std::vector<GridVector>().swap(s.vectors);  // OnlineEmSlam copied a keyframe's; the self-check needs sensorOrigin only
		out.scans.push_back(std::move(s));
	}
	progress.done();
	dumpEdges(slam, cfg, "before_finish");
	out.live = slam.vectors();
	const auto t0 = Clock::now();
	slam.finish();
	dumpEdges(slam, cfg, "final");
	EmResult& res = out.result;
	res.poses = slam.trajectory();
	if (!keepVectors)  // (--refine's batch EM builds its own final map)
		res.finalVectors = slam.finalMap(&res.doors);  // Sec. 5.4's doors in it (timed with the final map)
	res.keyframes = slam.keyframes().size();
	res.converged = true;  // no EM iterations to converge: the self-check judges the graph and the map
	res.finalGraph = poseGraphFit(slam.graph());
	res.finalMapSeconds = out.finishSeconds = since(t0);
	// Sec. 5.4 and the final merges run inside finish() and finalMap(), not timed apart: report.json says null, not 0
	res.doorSeconds = res.finalMergeSeconds = std::numeric_limits<double>::quiet_NaN();
	out.report = slam.report();
	return out;
}

std::string onlineJson(const OnlineReplay& r, bool refined)
{
	nlohmann::ordered_json j;
	j["latency_ms"] = {{"median", quantileMs(r.latency, 0.5)},
					   {"p99", quantileMs(r.latency, 0.99)},
					   {"max", quantileMs(r.latency, 1.0)}};
	j["cpu_ms"] = {{"median", quantileMs(r.latencyCpu, 0.5)},
				   {"p99", quantileMs(r.latencyCpu, 0.99)},
				   {"max", quantileMs(r.latencyCpu, 1.0)}};
	j["background_ms"] = {{"optimisations", r.background.size()},
						  {"median", quantileMs(r.background, 0.5)},
						  {"max", quantileMs(r.background, 1.0)},
						  {"cpu_median", quantileMs(r.backgroundCpu, 0.5)},
						  {"cpu_max", quantileMs(r.backgroundCpu, 1.0)}};
	j["synchronous_ms"] = {{"median", quantileMs(r.synchronous, 0.5)}, {"p99", quantileMs(r.synchronous, 0.99)}};
	j["keyframes"] = r.result.keyframes;
	j["registered_scans"] = r.registeredScans;
	j["loop_scans"] = r.loopScans;
	j["edges"] = {{"sequential", r.report.sequential}, {"overlap", r.report.overlap}, {"loop", r.report.loop},
				  {"active", r.report.active}, {"registrations", r.report.registrations},
				  {"loop_searches", r.report.loopSearches}};
	j["finish_seconds"] = r.finishSeconds;
	j["refined"] = refined;
	return j.dump();
}

}  // namespace gridvector::app
