#include "sim/Laser.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace gridvector::sim
{
char labelChar(HitKind k)
{
	switch (k)
	{
		case HitKind::Static:
			return 's';
		case HitKind::Person:
			return 'p';
		case HitKind::Door:
			return 'd';
		case HitKind::Object:
			return 'o';
		default:
			return '-';
	}
}

HitKind labelKind(char c)
{
	switch (c)
	{
		case '-':
			return HitKind::None;
		case 's':
			return HitKind::Static;
		case 'p':
			return HitKind::Person;
		case 'd':
			return HitKind::Door;
		case 'o':
			return HitKind::Object;
		default:
			throw std::invalid_argument(std::string("unknown beam label '") + c + "'");
	}
}

void Scene::clearDynamic()
{
	segs_.clear();
	segIds_.clear();
	circles_.clear();
	circleIds_.clear();
}

void Scene::addSegment(const Segment& s, HitKind kind, int id)
{
	segs_.push_back(s);
	segIds_.emplace_back(kind, id);
}

void Scene::addCircle(const Circle& c, int id)
{
	circles_.push_back(c);
	circleIds_.push_back(id);
}

Hit Scene::cast(const Vec2& o, const Vec2& dir, double maxRange) const
{
	Hit h;
	h.range = maxRange;
	const auto consider = [&](double t, HitKind k, int id) {
		if (t < h.range) h.range = t, h.kind = k, h.id = id;
	};
	for (size_t i = 0; i < walls_.size(); i++) consider(rayToSegment(o, dir, walls_[i]), HitKind::Static, int(i));
	for (size_t i = 0; i < segs_.size(); i++)
		consider(rayToSegment(o, dir, segs_[i]), segIds_[i].first, segIds_[i].second);
	for (size_t i = 0; i < circles_.size(); i++)
		consider(rayToCircle(o, dir, circles_[i]), HitKind::Person, circleIds_[i]);
	if (h.kind == HitKind::None) h.range = kNoHit;
	return h;
}

/** Beams of one scan, and the range of beam indices an object can be hit by. */
struct Scene::Fan
{
	Vec2 o;
	double start, res, maxRange;
	int n;
	std::vector<Vec2> dirs;
	std::vector<Hit> hits;

	/** Angle of p from the first beam, in [0, 2*pi). */
	double rel(const Vec2& p) const
	{
		const double a = std::remainder(std::atan2(p.y - o.y, p.x - o.x) - start, 2 * M_PI);
		return a < 0 ? a + 2 * M_PI : a;
	}
	/** Calls test(i) for beams i whose angle lies in [lo, hi] (rel angles, widened by one beam). */
	template <class F>
	void beamsIn(double lo, double hi, F&& test) const
	{
		if (hi < -res || lo > n * res) return;
		const int i0 = std::max(0, int(std::floor(lo / res)) - 1), i1 = std::min(n - 1, int(std::ceil(hi / res)) + 1);
		for (int i = i0; i <= i1; i++) test(i);
	}
	/** The same for an interval that may reach below 0 or beyond 2*pi (angles wrap). */
	template <class F>
	void wrapped(double lo, double hi, F&& test) const
	{
		for (double shift : {0.0, -2 * M_PI, 2 * M_PI}) beamsIn(lo + shift, hi + shift, test);
	}
	/** Beams within the short arc between rel angles a and b in [0, 2*pi). */
	template <class F>
	void arc(double a, double b, F&& test) const
	{
		if (a > b) std::swap(a, b);
		if (b - a <= M_PI)
			wrapped(a, b, test);
		else
			wrapped(b, a + 2 * M_PI, test);  // the short way round passes through angle 0
	}
	void offer(int i, double t, HitKind k, int id)
	{
		Hit& h = hits[size_t(i)];
		if (t < h.range) h.range = t, h.kind = k, h.id = id;
	}
	void segment(const Segment& s, HitKind k, int id)
	{
		if ((s.a - o).norm() < 1e-9 || (s.b - o).norm() < 1e-9)
			return beamsIn(-1.0, 2 * M_PI, [&](int i) { offer(i, rayToSegment(o, dirs[size_t(i)], s), k, id); });
		arc(rel(s.a), rel(s.b), [&](int i) { offer(i, rayToSegment(o, dirs[size_t(i)], s), k, id); });
	}
	void circle(const Circle& c, int id)
	{
		const double d = (c.c - o).norm();
		if (d <= c.r || d - c.r >= maxRange) return;
		const double a = rel(c.c), half = std::asin(c.r / d);
		wrapped(a - half, a + half, [&](int i) { offer(i, rayToCircle(o, dirs[size_t(i)], c), HitKind::Person, id); });
	}
};

std::vector<Hit> Scene::castFan(const Vec2& o, double start, double res, int n, double maxRange) const
{
	Fan f{o, start, res, maxRange, n, {}, {}};
	f.hits.resize(size_t(n));
	for (int i = 0; i < n; i++) f.dirs.push_back(Vec2::polar(1.0, start + i * res)), f.hits[size_t(i)].range = maxRange;
	for (size_t i = 0; i < walls_.size(); i++) f.segment(walls_[i], HitKind::Static, int(i));
	for (size_t i = 0; i < segs_.size(); i++) f.segment(segs_[i], segIds_[i].first, segIds_[i].second);
	for (size_t i = 0; i < circles_.size(); i++) f.circle(circles_[i], circleIds_[i]);
	for (Hit& h : f.hits)
		if (h.kind == HitKind::None) h.range = kNoHit;
	return f.hits;
}

Laser::Laser(const LaserOptions& o) : opt_(o)
{
	if (o.beams < 2) throw std::invalid_argument("laser needs at least 2 beams");
	fov_ = o.fovDeg * M_PI / 180.0;
	res_ = fov_ / double(o.beams % 2 == 1 ? o.beams - 1 : o.beams);
}

LaserReading Laser::scan(const Scene& scene, const mrpt::math::TPose2D& pose, Random& rng) const
{
	LaserReading r;
	r.ranges.resize(size_t(opt_.beams));
	r.hits = scene.castFan({pose.x, pose.y}, pose.phi + beamAngle(0), res_, opt_.beams, opt_.maxRange);
	for (int i = 0; i < opt_.beams; i++)
	{
		const Hit& h = r.hits[size_t(i)];
		double z = opt_.maxRange;
		if (h.kind != HitKind::None)
			z = std::clamp(h.range + rng.gauss(0, opt_.rangeSigma), 0.005, opt_.maxRange - 0.005);
		r.ranges[size_t(i)] = float(z);
	}
	return r;
}

}  // namespace gridvector::sim
