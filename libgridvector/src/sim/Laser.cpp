#include <gridvector/sim/Laser.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace gridvector::sim
{
char labelChar(HitKind k)
{
	switch (k)
	{
		case HitKind::Static: return 's';
		case HitKind::Person: return 'p';
		case HitKind::Door: return 'd';
		case HitKind::Object: return 'o';
		default: return '-';
	}
}

HitKind labelKind(char c)
{
	switch (c)
	{
		case '-': return HitKind::None;
		case 's': return HitKind::Static;
		case 'p': return HitKind::Person;
		case 'd': return HitKind::Door;
		case 'o': return HitKind::Object;
		default: throw std::invalid_argument(std::string("unknown beam label '") + c + "'");
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
	for (size_t i = 0; i < segs_.size(); i++) consider(rayToSegment(o, dir, segs_[i]), segIds_[i].first, segIds_[i].second);
	for (size_t i = 0; i < circles_.size(); i++) consider(rayToCircle(o, dir, circles_[i]), HitKind::Person, circleIds_[i]);
	if (h.kind == HitKind::None) h.range = kNoHit;
	return h;
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
	r.hits.resize(size_t(opt_.beams));
	const Vec2 o(pose.x, pose.y);
	for (int i = 0; i < opt_.beams; i++)
	{
		const Hit h = scene.cast(o, Vec2::polar(1.0, pose.phi + beamAngle(i)), opt_.maxRange);
		r.hits[size_t(i)] = h;
		double z = opt_.maxRange;
		if (h.kind != HitKind::None)
			z = std::clamp(h.range + rng.gauss(0, opt_.rangeSigma), 0.005, opt_.maxRange - 0.005);
		r.ranges[size_t(i)] = float(z);
	}
	return r;
}

}  // namespace gridvector::sim
