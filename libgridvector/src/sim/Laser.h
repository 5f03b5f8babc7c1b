// The simulated 2D laser: a snapshot of the scene (static walls, door leaves,
// the moved object, people) and ray casting against it.
#pragma once

#include "sim/Geometry.h"
#include "sim/Random.h"

#include <mrpt/math/TPose2D.h>

#include <cstdint>
#include <vector>

namespace gridvector::sim
{
enum class HitKind : uint8_t
{
	None,  //!< no return within max range
	Static,  //!< wall or static furniture
	Person,
	Door,
	Object  //!< the object moved during the run
};

/** Label characters of truth_labels.txt: '-' none, 's' static, 'p' person, 'd' door, 'o' moved object. */
char labelChar(HitKind k);
HitKind labelKind(char c);  //!< inverse; throws std::invalid_argument for other characters
inline bool isDynamic(HitKind k) { return k == HitKind::Person || k == HitKind::Door || k == HitKind::Object; }

struct Hit
{
	double range = kNoHit;
	HitKind kind = HitKind::None;
	int id = -1;  //!< wall / person / door / object index
};

/** Everything a beam can hit at one instant. */
class Scene
{
   public:
	explicit Scene(const std::vector<Segment>& staticWalls) : walls_(staticWalls) {}
	void clearDynamic();
	void addSegment(const Segment& s, HitKind kind, int id);
	void addCircle(const Circle& c, int id);
	/** The first thing along the ray from o in direction dir (unit), within maxRange. */
	Hit cast(const Vec2& o, const Vec2& dir, double maxRange) const;
	/** The same for n rays at angles start + i*res (world frame): every segment and
	 * circle is tested only against the beams inside the angle it covers. */
	std::vector<Hit> castFan(const Vec2& o, double start, double res, int n, double maxRange) const;

   private:
	struct Fan;
	const std::vector<Segment>& walls_;
	std::vector<Segment> segs_;
	std::vector<std::pair<HitKind, int>> segIds_;
	std::vector<Circle> circles_;
	std::vector<int> circleIds_;
};

struct LaserOptions
{
	int beams = 361;  //!< 180/181 (1 deg) or 360/361 (0.5 deg) for a 180 deg scanner
	double fovDeg = 180;
	double maxRange = 30;  //!< [m]; "no return" beams read exactly this
	double rangeSigma = 0.01;  //!< Gaussian range noise [m]
};

struct LaserReading
{
	std::vector<float> ranges;
	std::vector<Hit> hits;  //!< true (noise-free) hits
};

/** Beams in CARMEN's layout: beam i at -fov/2 + i*res from the heading, res =
 * fov/(n-1) for odd n and fov/n for even n (so 180 beams cover -90..+89 deg). */
class Laser
{
   public:
	explicit Laser(const LaserOptions& o);
	double resolution() const { return res_; }  //!< [rad]
	double beamAngle(int i) const { return -0.5 * fov_ + i * res_; }
	LaserReading scan(const Scene& scene, const mrpt::math::TPose2D& pose, Random& rng) const;
	const LaserOptions& options() const { return opt_; }

   private:
	LaserOptions opt_;
	double fov_, res_;
};

}  // namespace gridvector::sim
