#include "eval/MapEval.h"
#include "io/Counted.h"
#include "eval/SegmentIndex.h"
#include "io/FileBytes.h"
#include "io/TextParsing.h"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <functional>
#include <sstream>
#include <stdexcept>

namespace gridvector::eval
{
namespace
{
using sim::Segment;
using sim::Vec2;

/** Integrates over a segment's length: sum of (length share) for sample points where pred holds. */
double lengthWhere(const Segment& s, double step, const std::function<bool(const Vec2&)>& pred)
{
	const double len = s.length();
	if (len <= 0) return 0;
	const int n = sampleCount(len, step);
	int hits = 0;
	for (int i = 0; i < n; i++) hits += pred(s.at((i + 0.5) / n));
	return len * hits / n;
}

std::vector<Segment> doorSweeps(const std::vector<sim::DoorTruth>& doors)
{
	std::vector<Segment> out;
	for (const auto& d : doors)
		for (const auto& s : doorSweep(d)) out.push_back(s);
	return out;
}

double ratio(double a, double b) { return b > 0 ? a / b : 0.0; }

std::string f(double v, const char* fmt = "%.4f")
{
	char b[64];
	std::snprintf(b, sizeof b, fmt, v);
	return b;
}

void evaluateDoors(MapMetrics& m, const sim::Truth& truth, const std::vector<sim::DoorTruth>& detected,
				   const MapEvalOptions& opt)
{
	const double tol = opt.doorTolerance;
	const std::vector<bool> seenSwinging = doorsSeenSwinging(truth, opt);
	m.doorsEvaluated = true;
	m.detectedDoors = detected.size();
	const auto near = [&](const Vec2& a, const Vec2& b) { return (a - b).norm() <= tol; };
	for (size_t i = 0; i < truth.doors.size(); ++i)
	{
		const auto& d = truth.doors[i];
		if (d.swings == 0) continue;
		m.movingDoors++;
		m.observedSwingingDoors += seenSwinging[i];
		for (const auto& q : detected)
			if (near(q.hinge, d.hinge))
			{
				m.doorsFound++;
				m.observedDoorsFound += seenSwinging[i];
				break;
			}
	}
	for (const auto& q : detected)
		for (const auto& d : truth.doors)
			if (near(q.hinge, d.hinge))
			{
				m.detectedCorrect++;
				break;
			}
	m.doorRecall = ratio(double(m.doorsFound), double(m.movingDoors));
	m.doorRecallObserved = ratio(double(m.observedDoorsFound), double(m.observedSwingingDoors));
	m.doorPrecision = ratio(double(m.detectedCorrect), double(m.detectedDoors));
}
}  // namespace

int sampleCount(double length, double step)
{
	constexpr double maxSamples = 1e8;
	const double n = std::ceil(length / step);
	if (!(step > 0) || !(n <= maxSamples))
	{
		char b[160];
		std::snprintf(b, sizeof b, "a %g m long segment sampled every %g m: more than %g samples", length, step,
					  maxSamples);
		throw std::invalid_argument(b);
	}
	return std::max(1, int(n));
}

// Door leaves every 3 deg between closed and open: together they cover the swept sector.
std::vector<Segment> doorSweep(const sim::DoorTruth& d)
{
	std::vector<Segment> out;
	const double span = std::remainder(d.openAngle - d.closedAngle, 2 * M_PI);
	const int n = std::max(1, int(std::ceil(std::abs(span) / (3 * M_PI / 180))));
	for (int k = 0; k <= n; k++)
		out.emplace_back(d.hinge, d.hinge + Vec2::polar(d.length, d.closedAngle + span * k / n));
	return out;
}

// The direction of the leaf's far end from the hinge, so that the angle does not wrap with the run's order.
double leafAngle(const sim::HitRun& h, const sim::DoorTruth& d)
{
	const Vec2 far = (h.seg.a - d.hinge).norm() > (h.seg.b - d.hinge).norm() ? h.seg.a : h.seg.b;
	const double a = std::atan2(far.y - d.hinge.y, far.x - d.hinge.x);
	return std::atan2(std::sin(a - d.closedAngle), std::cos(a - d.closedAngle));
}

bool showsLeafState(const sim::HitRun& h, const MapEvalOptions& opt)
{
	return h.seg.length() >= opt.doorMinRunLength && h.beams >= opt.doorMinRunBeams;
}

std::vector<bool> doorsSeenSwinging(const sim::Truth& truth, const MapEvalOptions& opt)
{
	std::vector<double> lo(truth.doors.size(), 1e9), hi(truth.doors.size(), -1e9);
	for (const auto& h : truth.hits)
	{
		if (h.kind != sim::HitKind::Door || h.id < 0 || size_t(h.id) >= truth.doors.size()) continue;
		if (!showsLeafState(h, opt)) continue;
		const double rel = leafAngle(h, truth.doors[size_t(h.id)]);
		lo[size_t(h.id)] = std::min(lo[size_t(h.id)], rel), hi[size_t(h.id)] = std::max(hi[size_t(h.id)], rel);
	}
	std::vector<bool> seen(truth.doors.size(), false);
	for (size_t i = 0; i < seen.size(); ++i) seen[i] = hi[i] - lo[i] >= opt.doorMinStateDiffDeg * M_PI / 180.0;
	return seen;
}

std::vector<MapVector> readVectors(const std::string& path)
{
	const std::vector<char> text = io::readFileBytes(path);
	io::LineCursor cur(text);
	std::string_view line;
	io::TextPos pos{path, 0};
	std::vector<MapVector> out;
	while (cur.next(line))
	{
		pos.line = cur.lineNumber();
		const auto t = io::splitTokens(line);
		if (t.empty() || t[0][0] == '#') continue;
		if (t.size() != 5 && t.size() != 6)
			io::parseError(pos,
						   "expected 'x1 y1 x2 y2 p_static [static|dynamic]', found " + io::counted(t.size(), "field"));
		MapVector v;
		v.seg = {io::parseDouble(t[0], pos, "x1"), io::parseDouble(t[1], pos, "y1"), io::parseDouble(t[2], pos, "x2"),
				 io::parseDouble(t[3], pos, "y2")};
		v.pStatic = io::parseDouble(t[4], pos, "p_static");
		if (v.pStatic < 0 || v.pStatic > 1)
			io::parseError(pos, "p_static is " + io::printableToken(t[4]) + " (must be in [0, 1])");
		v.isStatic = v.pStatic >= 0.5;
		if (t.size() == 6)
		{
			if (t[5] != "static" && t[5] != "dynamic")
				io::parseError(pos, "label is '" + io::printableToken(t[5]) + "' (expected static or dynamic)");
			v.isStatic = t[5] == "static";
		}
		out.push_back(v);
	}
	return out;
}

MapMetrics evaluateMap(const std::vector<MapVector>& vectors, const sim::Truth& truth,
					   const std::vector<sim::DoorTruth>* detectedDoors, const MapEvalOptions& opt)
{
	std::vector<Segment> staticVecs, dynamicVecs, dynamicPlaces = doorSweeps(truth.doors), hitSegs;
	// the second ghost figure's places: doors seen in one state only are static (Sec. 5.4)
	const std::vector<bool> seenSwinging = doorsSeenSwinging(truth, opt);
	std::vector<sim::DoorTruth> swungDoors;
	for (size_t i = 0; i < truth.doors.size(); ++i)
		if (seenSwinging[i]) swungDoors.push_back(truth.doors[i]);
	std::vector<Segment> swungPlaces = doorSweeps(swungDoors);
	for (const auto& v : vectors) (v.isStatic ? staticVecs : dynamicVecs).push_back(v.seg);
	for (const auto& e : truth.objectEdges) dynamicPlaces.push_back(e.edge), swungPlaces.push_back(e.edge);
	for (const auto& h : truth.hits)
	{
		dynamicPlaces.push_back(h.seg), hitSegs.push_back(h.seg);
		const bool oneStateDoor = h.kind == sim::HitKind::Door &&
								  !(h.id >= 0 && size_t(h.id) < seenSwinging.size() && seenSwinging[size_t(h.id)]);
		if (!oneStateDoor) swungPlaces.push_back(h.seg);
	}
	const SegmentIndex walls(truth.walls), statics(staticVecs), dynamics(dynamicVecs), places(dynamicPlaces),
		placesSwung(swungPlaces);
	const double tw = opt.wallTolerance, td = opt.dynamicTolerance, step = opt.sampleStep;

	MapMetrics m;
	for (const auto& s : staticVecs)
	{
		m.staticLength += s.length();
		m.staticOnWalls += lengthWhere(s, step, [&](const Vec2& p) { return walls.within(p, tw); });
		m.ghostLength +=
			lengthWhere(s, step, [&](const Vec2& p) { return !walls.within(p, tw) && places.within(p, td); });
		m.ghostLengthSeenSwinging +=
			lengthWhere(s, step, [&](const Vec2& p) { return !walls.within(p, tw) && placesSwung.within(p, td); });
	}
	for (const auto& s : dynamicVecs)
	{
		m.dynamicLength += s.length();
		m.dynamicOnWalls += lengthWhere(s, step, [&](const Vec2& p) { return walls.within(p, tw); });
	}
	for (const auto& s : truth.seenWalls)
	{
		m.seenWallLength += s.length();
		m.seenCovered += lengthWhere(s, step, [&](const Vec2& p) { return statics.within(p, tw); });
	}
	for (const auto& s : hitSegs)
	{
		m.dynamicHitLength += s.length();
		m.dynamicHitDetected += lengthWhere(s, step, [&](const Vec2& p) { return dynamics.within(p, td); });
	}
	m.staticPrecision = ratio(m.staticOnWalls, m.staticLength);
	m.staticRecall = ratio(m.seenCovered, m.seenWallLength);
	m.ghostShare = ratio(m.ghostLength, m.staticLength);
	m.ghostShareSeenSwinging = ratio(m.ghostLengthSeenSwinging, m.staticLength);
	// the one-state doors' places are a subset of the ghost places: what the second figure leaves out is correct static
	m.staticPrecisionSeenSwinging = ratio(m.staticOnWalls + m.ghostLength - m.ghostLengthSeenSwinging, m.staticLength);
	m.dynamicDetection = ratio(m.dynamicHitDetected, m.dynamicHitLength);
	if (detectedDoors) evaluateDoors(m, truth, *detectedDoors, opt);
	return m;
}

std::string formatText(const MapMetrics& m)
{
	std::ostringstream os;
	os << "static vectors:    " << f(m.staticLength, "%.2f") << " m, precision " << f(m.staticPrecision) << " ("
	   << f(m.staticOnWalls, "%.2f") << " m on true walls)\n"
	   << "static precision (doors seen in one state are static): " << f(m.staticPrecisionSeenSwinging) << "\n"
	   << "static recall:     " << f(m.staticRecall) << " (" << f(m.seenCovered, "%.2f") << " of "
	   << f(m.seenWallLength, "%.2f") << " m of seen wall covered)\n"
	   << "ghost length:      " << f(m.ghostLength, "%.2f") << " m (" << f(m.ghostShare) << " of static length)\n"
	   << "ghost length (doors seen in one state are static): " << f(m.ghostLengthSeenSwinging, "%.2f") << " m ("
	   << f(m.ghostShareSeenSwinging) << " of static length)\n"
	   << "dynamic vectors:   " << f(m.dynamicLength, "%.2f") << " m (" << f(m.dynamicOnWalls, "%.2f")
	   << " m of it on true walls)\n"
	   << "dynamic detection: " << f(m.dynamicDetection) << " (" << f(m.dynamicHitDetected, "%.2f") << " of "
	   << f(m.dynamicHitLength, "%.2f") << " m of dynamic hits)\n";
	if (m.doorsEvaluated)
		os << "door recall:       " << f(m.doorRecall) << " (" << m.doorsFound << " of " << m.movingDoors
		   << " swinging doors), precision " << f(m.doorPrecision) << " (" << m.detectedCorrect << " of "
		   << m.detectedDoors << " detected)\n"
		   << "door recall (seen swinging): " << f(m.doorRecallObserved) << " (" << m.observedDoorsFound << " of "
		   << m.observedSwingingDoors << " doors whose leaf the laser saw in two states)\n";
	return os.str();
}

nlohmann::ordered_json toJson(const MapMetrics& m)
{
	nlohmann::ordered_json j = {{"static_length_m", m.staticLength},
								{"static_precision", m.staticPrecision},
								{"seen_wall_length_m", m.seenWallLength},
								{"static_recall", m.staticRecall},
								{"ghost_length_m", m.ghostLength},
								{"ghost_share", m.ghostShare},
								{"ghost_length_seen_swinging_m", m.ghostLengthSeenSwinging},
								{"ghost_share_seen_swinging", m.ghostShareSeenSwinging},
								{"static_precision_seen_swinging", m.staticPrecisionSeenSwinging},
								{"dynamic_length_m", m.dynamicLength},
								{"dynamic_on_walls_m", m.dynamicOnWalls},
								{"dynamic_hit_length_m", m.dynamicHitLength},
								{"dynamic_detection", m.dynamicDetection}};
	if (!m.doorsEvaluated) return j;
	j["moving_doors"] = m.movingDoors;
	j["doors_found"] = m.doorsFound;
	j["door_recall"] = m.doorRecall;
	j["detected_doors"] = m.detectedDoors;
	j["door_precision"] = m.doorPrecision;
	j["observed_swinging_doors"] = m.observedSwingingDoors;
	j["observed_doors_found"] = m.observedDoorsFound;
	j["door_recall_observed"] = m.doorRecallObserved;
	return j;
}

namespace
{
sim::Vec2 moved(const sim::Vec2& p, const mrpt::math::TPose2D& T)
{
	const double c = std::cos(T.phi), s = std::sin(T.phi);
	return {c * p.x - s * p.y + T.x, s * p.x + c * p.y + T.y};
}
}  // namespace

std::vector<MapVector> transformVectors(const std::vector<MapVector>& v, const mrpt::math::TPose2D& T)
{
	std::vector<MapVector> out = v;
	for (auto& m : out) m.seg = sim::Segment(moved(m.seg.a, T), moved(m.seg.b, T));
	return out;
}

std::vector<sim::DoorTruth> transformDoors(const std::vector<sim::DoorTruth>& d, const mrpt::math::TPose2D& T)
{
	std::vector<sim::DoorTruth> out = d;
	for (auto& door : out)
	{
		door.hinge = moved(door.hinge, T);
		door.closedAngle += T.phi;
		door.openAngle += T.phi;
	}
	return out;
}

}  // namespace gridvector::eval
