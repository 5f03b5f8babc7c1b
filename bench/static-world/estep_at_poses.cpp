// The E-step and the final map of a log at given poses, without EM (doc/benchmarks-history.md,
// "Session 14: static world, door ghosts"): does a static world stay static when the trajectory
// is right? Per-scan vectors of every STRIDE-th scan (library defaults), Eq. 8 product
// (GlobalMap::buildPerScan), Eq. 14 (EStep::run), the final map (SplitMap::of: finalSplit, static
// and dynamic merged) and the doors on it (DoorDetector), as gv-em-slam makes its final map.
//
// build (from the worktree root, after cmake --build build):
//   g++ -O2 -std=c++17 bench/static-world/estep_at_poses.cpp -o /tmp/estep_at_poses -Ilibgridvector/src \
//     -Ilibgridvector/include $(for m in maps obs opengl poses bayes math serialization rtti core typemeta random \
//     system containers config expr img io tfest graphs slam; do echo -n "-isystem /usr/include/mrpt/$m/include ";
//     done) \
//     -isystem /usr/include/eigen3 -Lbuild/libgridvector -lgridvector -lmrpt-maps -lmrpt-obs -lmrpt-poses \
//     -lmrpt-math -lmrpt-core -lmrpt-serialization -lmrpt-system -Wl,-rpath,$PWD/build/libgridvector
// usage: estep_at_poses LOG POSES.txt STRIDE   (POSES: 't x y theta', paired with the scans by nearest t)
#include "doors/DoorExclusion.h"
#include "estep/EStep.h"
#include "extraction/VectorExtractor.h"
#include "map/GlobalMap.h"
#include <gridvector/GridVectorConfig.h>
#include <gridvector/io/LogReader.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>

using namespace gridvector;

int main(int argc, char** argv)
{
	if (argc != 4) return fprintf(stderr, "usage: estep_at_poses LOG POSES.txt STRIDE\n"), 2;
	const auto log = io::readLog(argv[1]);
	std::vector<std::pair<double, mrpt::math::TPose2D>> track;
	std::ifstream f(argv[2]);
	double t, x, y, th;
	while (f >> t >> x >> y >> th) track.push_back({t, {x, y, th}});
	if (track.empty()) return fprintf(stderr, "estep_at_poses: %s: no poses\n", argv[2]), 1;
	const size_t stride = size_t(std::max(1, atoi(argv[3])));
	const GridVectorConfig cfg;
	const VectorExtractor ex(cfg.extraction, cfg.grid);
	std::vector<LocalScan> scans;
	std::vector<mrpt::math::TPose2D> poses;
	size_t j = 0;
	for (size_t i = 0; i < log.scans.size(); i += stride)
	{
		const double ts = log.scans[i].timestamp;
		while (j + 1 < track.size() && std::abs(track[j + 1].first - ts) <= std::abs(track[j].first - ts)) ++j;
		LocalScan s = ex.extract(*log.scans[i].scan);
		s.scanIndex = int64_t(poses.size());
		scans.push_back(std::move(s));
		poses.push_back(track[j].second);
	}
	const EStep estep(cfg.estep, cfg.grid);
	const EStepResult e = estep.run(GlobalMap::buildPerScan(poses, scans, cfg));
	const auto share = [](const std::vector<GridVector>& vs) {
		double s = 0, a = 0;
		for (const auto& v : vs) a += v.length(), s += v.state == VectorState::Static ? v.length() : 0;
		return std::make_pair(s / std::max(a, 1e-9), a);
	};
	const SplitMap m = SplitMap::of(e.children, estep, cfg);
	std::vector<GridVector> vs = m.vectors;
	const auto doors = DoorDetector(cfg.doors).detect(vs);
	for (const auto& d : doors)
		for (size_t leaf : d.leaves) vs[leaf].state = VectorState::Dynamic;
	printf(
		"%zu scans: E-step children static %.4f of %.0f m; after finalSplit %.4f; final map %zu vectors, "
		"static %.4f of %.1f m, %zu doors\n",
		scans.size(), share(e.children).first, share(e.children).second, share(m.perScan).first, vs.size(),
		share(vs).first, share(vs).second, doors.size());
	// per-scan dynamic length by range from the scan's pose
	double st[8] = {0}, dy[8] = {0};
	for (const auto& v : m.perScan)
	{
		if (v.scanIndex < 0 || size_t(v.scanIndex) >= poses.size()) continue;
		const auto c = v.centre();
		const auto& p = poses[size_t(v.scanIndex)];
		const int b = std::min(7, int(std::hypot(c.x - p.x, c.y - p.y) / 5));
		(v.state == VectorState::Static ? st : dy)[b] += v.length();
	}
	for (int b = 0; b < 8; ++b)
		printf("  range %2d-%2d m: static %8.1f m, dynamic %6.1f m (%.4f)\n", b * 5, b * 5 + 5, st[b], dy[b],
			   dy[b] / std::max(st[b] + dy[b], 1e-9));
}
