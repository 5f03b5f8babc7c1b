// OnlineEmSlam on gv-sim's corridor loop with walking people: each vector a person left in the map is
// dynamic within 10 scans of the wall behind its place being seen through it, read mid-run.
#include "extraction/VectorExtractor.h"
#include "online/OnlineEmSlam.h"
#include "sim/Simulator.h"
#include "sim/TruthFiles.h"
#include <gridvector/io/LogReader.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <unistd.h>

using namespace gridvector;
using gridvector::online::OnlineEmSlam;
using gridvector::online::OnlineStep;
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

namespace
{
/** A person's vector: scan s's vector whose centre lies on a person's hit run of that scan. */
struct PersonVector
{
	size_t scan = 0;
	uint64_t id = 0;  //!< in the live map (OnlineEmSlam::map().perScan(), ids position + 1)
	TPoint2D place;  //!< its centre in the true world
	size_t seenThrough = SIZE_MAX;  //!< first later scan a static beam passes its place
	size_t dynamicAt = SIZE_MAX;  //!< first scan from then on at which the live map says Dynamic
};

double distToSegment(const TPoint2D& p, const sim::Segment& s)
{
	const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y, l2 = dx * dx + dy * dy;
	const double u = l2 > 0 ? std::clamp(((p.x - s.a.x) * dx + (p.y - s.a.y) * dy) / l2, 0.0, 1.0) : 0.0;
	return std::hypot(p.x - s.a.x - u * dx, p.y - s.a.y - u * dy);
}

/** Does a static beam of scan `sc` pass `place` and end at least 0.3 m beyond it (the wall seen through)? */
bool seenThrough(const sim::SimResult& r, const sim::SimScan& sc, const TPoint2D& place)
{
	const double d = std::hypot(place.x - sc.truth.x, place.y - sc.truth.y);
	const double bearing = mrpt::math::wrapToPi(std::atan2(place.y - sc.truth.y, place.x - sc.truth.x) - sc.truth.phi);
	const double fov = r.laser.fovDeg * M_PI / 180;
	const long k = std::lround((bearing + 0.5 * fov) / r.laserResolution);
	if (k < 0 || k >= long(sc.ranges.size())) return false;
	return sc.labels[size_t(k)] == 's' && sc.ranges[size_t(k)] > d + 0.3;
}
}  // namespace

TEST(OnlineEmSlam, APersonWhoWalkedPastIsDynamicWithinTenScansOfTheWallSeenThrough)
{
	sim::SimOptions o;
	o.world = "corridor-loop";
	o.seed = 1;
	o.scans = 600;
	const sim::SimResult r = sim::simulate(o);
	const auto dir = std::filesystem::temp_directory_path() / ("online_person_test_" + std::to_string(::getpid()));
	sim::writeSimulation(r, dir.string());
	io::ReadOptions ro;
	ro.quiet = true;
	const io::LogData log = io::readLog((dir / "sim.log").string(), ro);
	std::filesystem::remove_all(dir);
	ASSERT_EQ(log.scans.size(), r.scans.size());

	const GridVectorConfig cfg;
	const VectorExtractor ex(cfg.extraction, cfg.grid);
	std::multimap<double, const sim::HitRun*> personRuns;  // by scan time
	for (const auto& h : r.dynamicHits)
		if (h.kind == sim::HitKind::Person && h.beams >= 5) personRuns.emplace(h.t, &h);
	OnlineEmSlam slam(cfg);
	std::vector<PersonVector> people;
	for (size_t t = 0; t < log.scans.size(); ++t)
	{
		LocalScan s = ex.extract(*log.scans[t].scan);
		s.scanIndex = int64_t(t);
		s.timestamp = log.scans[t].timestamp;
		const size_t before = slam.map().size();
		const OnlineStep st = slam.addScan(s, log.scans[t].odometry);
		if (slam.optimisationDue()) slam.applyOptimisation([&] {
			auto job = slam.takeOptimisation();
			slam.runOptimisation(job);
			return job;
		}());
		// the scan's vectors on a person (true pose: no estimate error in the labelling)
		if (st.keyframe)
		{
			const auto range = personRuns.equal_range(r.scans[t].t);
			for (size_t i = 0; i < s.vectors.size(); ++i)
			{
				if (s.vectors[i].length() < 0.2) continue;
				const TPoint2D c = r.scans[t].truth.composePoint(s.vectors[i].centre());
				for (auto it = range.first; it != range.second; ++it)
					if (distToSegment(c, it->second->seg) < 0.1)
					{
						people.push_back({t, before + i + 1, c});
						break;
					}
			}
		}
		// the state of every person vector as the live map has it now
		for (auto& p : people)
		{
			if (p.seenThrough == SIZE_MAX && t > p.scan && seenThrough(r, r.scans[t], p.place)) p.seenThrough = t;
			if (p.seenThrough == SIZE_MAX || p.dynamicAt != SIZE_MAX) continue;
			const auto& v = slam.map().perScan();
			ASSERT_LT(p.id - 1, v.size());
			if (slam.map().stateOf(v[p.id - 1]) == VectorState::Dynamic) p.dynamicAt = t;
		}
	}
	// every vector of at least Sec. 4.1's minimum length (min_piece_length); shorter ones (a person's
	// side seen in a few beams) need as many free observations as the scans that hit them, which a
	// person standing near the robot for 20 scans has: nine in ten of them
	size_t checked = 0, inTime = 0, checkedLong = 0, inTimeLong = 0;
	for (const auto& p : people)
	{
		if (p.seenThrough == SIZE_MAX || p.seenThrough + 10 >= log.scans.size()) continue;
		const bool ok = p.dynamicAt <= p.seenThrough + 10;
		const bool isLong = slam.map().perScan()[p.id - 1].length() >= cfg.estep.minPieceLength;
		++checked, inTime += ok;
		checkedLong += isLong, inTimeLong += isLong && ok;
		if (!ok)
			std::printf("late: vector of scan %zu, %.2f m, seen through at scan %zu, dynamic at %zd\n", p.scan,
						slam.map().perScan()[p.id - 1].length(), p.seenThrough,
						p.dynamicAt == SIZE_MAX ? -1 : ssize_t(p.dynamicAt));
	}
	std::printf("person vectors %zu, seen through %zu, dynamic within 10 scans %zu; at least %.2f m: %zu, %zu\n",
				people.size(), checked, inTime, cfg.estep.minPieceLength, checkedLong, inTimeLong);
	EXPECT_GT(checkedLong, 20u);
	EXPECT_EQ(inTimeLong, checkedLong);
	EXPECT_GE(double(inTime), 0.9 * double(checked));
}
