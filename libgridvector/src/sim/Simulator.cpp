#include "sim/BuiltinWorlds.h"
#include "sim/OdometryNoise.h"
#include "sim/People.h"
#include "sim/RobotPath.h"
#include "sim/Simulator.h"
#include "sim/WalkGraph.h"

#include <algorithm>
#include <cmath>

namespace gridvector::sim
{
double DoorTimeline::angleAt(double t) const
{
	double a = initial;
	for (const Swing& s : swings)
	{
		if (t < s.t0) break;
		if (t >= s.t1)
			a = s.to;
		else
		{
			const double f = (t - s.t0) / (s.t1 - s.t0);
			return s.from + (s.to - s.from) * (0.5 - 0.5 * std::cos(M_PI * f));  // smooth start and stop
		}
	}
	return a;
}

namespace
{
constexpr double kSeenBin = 0.05, kSeenGap = 0.25;

Vec2 centroid(const std::vector<Vec2>& poly)
{
	Vec2 c;
	for (const auto& p : poly) c = c + p * (1.0 / double(poly.size()));
	return c;
}

void addPolygon(std::vector<Segment>& out, const std::vector<Vec2>& poly)
{
	for (size_t i = 0; i < poly.size(); i++) out.emplace_back(poly[i], poly[(i + 1) % poly.size()]);
}

/** Independent, reproducible random streams per aspect of the simulation. */
Random stream(int64_t seed, int which) { return Random(uint64_t(seed) * 7919u + uint64_t(which)); }

LaserOptions laserOptions(const SimOptions& o)
{
	o.validate();
	LaserOptions l;
	l.beams = o.beams;
	l.fovDeg = o.fovDeg;
	l.maxRange = o.maxRange;
	l.rangeSigma = o.rangeSigma;
	return l;
}

class Simulator
{
   public:
	explicit Simulator(const SimOptions& opt);
	SimResult run(const std::function<void(double)>& progress);

   private:
	void makeDoorTimelines(double duration);
	std::vector<double> swingTimes(double duration);
	void chooseMoveTime(const std::vector<mrpt::math::TPose2D>& path);
	void fillScene(Scene& scene, double runTime, const Crowd& crowd) const;
	void account(const LaserReading& r, const mrpt::math::TPose2D& pose, double t);
	void finishSeenWalls();

	SimResult res_;
	Laser laser_;
	Random doorRng_, peopleRng_, laserRng_, odoRng_;
	std::vector<std::vector<bool>> seenBins_;
};

Simulator::Simulator(const SimOptions& opt)
	: laser_(laserOptions(opt)),
	  doorRng_(stream(opt.seed, 1)),
	  peopleRng_(stream(opt.seed, 2)),
	  laserRng_(stream(opt.seed, 3)),
	  odoRng_(Random(uint64_t(opt.seed)))  // as mkbench.py: Random(seed) drives the odometry noise
{
	res_.options = opt;
	res_.laser = laser_.options();
	res_.laserResolution = laser_.resolution();
	res_.world = makeWorld(opt.world);
	World& w = res_.world;
	if (!opt.doors)  // doors that never move are part of the static world
	{
		for (const auto& d : w.doors) w.walls.push_back(d.leaf(d.closedAngle));
		w.doors.clear();
	}
	if (!opt.movedObject)
	{
		for (const auto& o : w.objects) addPolygon(w.walls, o.first);
		w.objects.clear();
	}
	seenBins_.resize(w.walls.size());
	for (size_t i = 0; i < w.walls.size(); i++) seenBins_[i].assign(size_t(w.walls[i].length() / kSeenBin) + 1, false);
}

// When a door starts to swing: 2-4 times anywhere in the run, or every period..2 period s.
std::vector<double> Simulator::swingTimes(double duration)
{
	const double period = res_.options.doorSwingPeriod;
	std::vector<double> times;
	if (period > 0)
	{
		for (double t = doorRng_.uniform(0, period); t < duration; t += doorRng_.uniform(period, 2 * period))
			times.push_back(t);
		return times;
	}
	times.resize(size_t(doorRng_.uniformInt(2, 4)));
	for (double& t : times) t = doorRng_.uniform(0.05, 0.95) * duration;
	std::sort(times.begin(), times.end());
	return times;
}

void Simulator::makeDoorTimelines(double duration)
{
	for (const DoorSpec& d : res_.world.doors)
	{
		DoorTimeline tl;
		const auto openAngle = [&] {
			return d.closedAngle + (d.openAngle - d.closedAngle) * doorRng_.uniform(0.5, 1.0);
		};
		const bool startsOpen = doorRng_.chance(0.5);
		tl.initial = startsOpen ? openAngle() : d.closedAngle;
		const std::vector<double> times = swingTimes(duration);
		double angle = tl.initial, free = 0;
		for (double t : times)
		{
			const double t0 = std::max(t, free), t1 = t0 + doorRng_.uniform(1.0, 2.5);
			if (t1 > duration) break;
			const bool closed = std::abs(angle - d.closedAngle) < 1e-9;
			const double to = closed ? openAngle() : d.closedAngle;
			tl.swings.push_back({t0, t1, angle, to});
			angle = to;
			free = t1 + 3.0;
		}
		res_.stats.doorSwings += tl.swings.size();
		res_.doors.push_back(tl);
	}
}

/** The object moves while the robot is far from both of its places (between two visits). */
void Simulator::chooseMoveTime(const std::vector<mrpt::math::TPose2D>& path)
{
	res_.objectMoveTime = 0.5 * double(path.size()) * res_.options.dt;
	double best = -1;
	for (size_t k = path.size() * 35 / 100; k < path.size() * 65 / 100; k++)
	{
		double d = kNoHit;
		for (const auto& o : res_.world.objects)
			d = std::min({d, (centroid(o.first) - Vec2(path[k].x, path[k].y)).norm(),
						  (centroid(o.second) - Vec2(path[k].x, path[k].y)).norm()});
		if (d > best) best = d, res_.objectMoveTime = double(k) * res_.options.dt;
	}
}

void Simulator::fillScene(Scene& scene, double runTime, const Crowd& crowd) const
{
	scene.clearDynamic();
	const World& w = res_.world;
	for (size_t i = 0; i < w.doors.size(); i++)
		scene.addSegment(w.doors[i].leaf(res_.doors[i].angleAt(runTime)), HitKind::Door, int(i));
	for (size_t i = 0; i < w.objects.size(); i++)
	{
		std::vector<Segment> edges;
		addPolygon(edges, runTime < res_.objectMoveTime ? w.objects[i].first : w.objects[i].second);
		for (const auto& e : edges) scene.addSegment(e, HitKind::Object, int(i));
	}
	const auto& people = crowd.people();
	for (size_t i = 0; i < people.size(); i++) scene.addCircle({people[i].pos, people[i].radius}, int(i));
}

void Simulator::account(const LaserReading& r, const mrpt::math::TPose2D& pose, double t)
{
	SimStats& s = res_.stats;
	const Vec2 o(pose.x, pose.y);
	const auto point = [&](size_t i) { return o + Vec2::polar(r.hits[i].range, pose.phi + laser_.beamAngle(int(i))); };
	for (size_t i = 0; i < r.hits.size(); i++)
	{
		const Hit& h = r.hits[i];
		s.beams++;
		if (h.kind == HitKind::None)
			s.noHits++;
		else if (h.kind == HitKind::Static)
		{
			s.staticHits++;
			const Segment& w = res_.world.walls[size_t(h.id)];
			auto& bins = seenBins_[size_t(h.id)];
			bins[std::min(bins.size() - 1, size_t((point(i) - w.a).norm() / kSeenBin))] = true;
		}
		else
		{
			s.dynamicHits++;
			s.personHits += h.kind == HitKind::Person;
			s.doorHits += h.kind == HitKind::Door;
			s.objectHits += h.kind == HitKind::Object;
		}
	}
	for (size_t i = 0; i < r.hits.size();)  // runs of beams on the same dynamic thing
	{
		size_t j = i + 1;
		while (j < r.hits.size() && r.hits[j].kind == r.hits[i].kind && r.hits[j].id == r.hits[i].id) j++;
		if (isDynamic(r.hits[i].kind) && j - i >= 2)
			res_.dynamicHits.push_back({r.hits[i].kind, r.hits[i].id, t, {point(i), point(j - 1)}, int(j - i)});
		i = j;
	}
}

void Simulator::finishSeenWalls()
{
	const size_t bridge = size_t(kSeenGap / kSeenBin);
	for (size_t w = 0; w < seenBins_.size(); w++)
	{
		const auto& bins = seenBins_[w];
		const Segment& wall = res_.world.walls[w];
		const double len = wall.length();
		for (size_t i = 0; i < bins.size();)
		{
			if (!bins[i])
			{
				i++;
				continue;
			}
			size_t end = i, gap = 0;  // extend over seen bins and short gaps
			for (size_t j = i + 1; j < bins.size() && gap <= bridge; j++)
				if (bins[j])
					end = j, gap = 0;
				else
					gap++;
			const double a = std::min(len, double(i) * kSeenBin), b = std::min(len, double(end + 1) * kSeenBin);
			if (b > a) res_.seenWalls.emplace_back(wall.at(a / len), wall.at(b / len));
			i = end + 1;
		}
	}
}

SimResult Simulator::run(const std::function<void(double)>& progress)
{
	const SimOptions& opt = res_.options;
	World& w = res_.world;
	MotionOptions motion{opt.speed, opt.turnRateDeg, opt.dt};
	const auto path = followRoute(w.start, w.route, opt.laps ? opt.laps : w.defaultLaps, motion, size_t(opt.scans));
	const double duration = double(path.size()) * opt.dt;
	makeDoorTimelines(duration);
	chooseMoveTime(path);
	const WalkGraph graph(w, 0.35);
	Crowd crowd(graph, w.walls, opt.people >= 0 ? opt.people : w.defaultPeople, {w.start.x, w.start.y}, peopleRng_,
				opt.pauseS);
	res_.stats.people = crowd.people().size();
	NoisyOdometry odometry({opt.sigmaT, opt.sigmaR, opt.driftDegPerM}, odoRng_);
	Scene scene(w.walls);
	for (size_t k = 0; k < path.size(); k++)
	{
		const double runTime = double(k) * opt.dt;
		if (k > 0)
		{
			crowd.step(opt.dt, {path[k].x, path[k].y});
			res_.stats.pathLength += std::hypot(path[k].x - path[k - 1].x, path[k].y - path[k - 1].y);
		}
		fillScene(scene, runTime, crowd);
		SimScan s;
		s.t = opt.startTime + runTime;
		s.truth = path[k];
		s.odometry = odometry.step(path[k]);
		LaserReading r = laser_.scan(scene, path[k], laserRng_);
		account(r, path[k], s.t);
		s.ranges = std::move(r.ranges);
		s.labels.resize(r.hits.size());
		for (size_t i = 0; i < r.hits.size(); i++) s.labels[i] = labelChar(r.hits[i].kind);
		res_.scans.push_back(std::move(s));
		if (progress && k % 50 == 0) progress(double(k) / double(path.size()));
	}
	finishSeenWalls();
	res_.stats.scans = res_.scans.size();
	res_.stats.duration = duration;
	return std::move(res_);
}
}  // namespace

SimResult simulate(const SimOptions& opt, const std::function<void(double)>& progress)
{
	Simulator sim(opt);
	return sim.run(progress);
}

}  // namespace gridvector::sim
