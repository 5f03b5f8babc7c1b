#include "eval/FalseStatic.h"
#include "io/Counted.h"
#include "eval/SegmentIndex.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace gridvector::eval
{
namespace
{
using sim::Segment;
using sim::Vec2;

std::string f(double v, const char* fmt = "%.2f")
{
	char b[64];
	std::snprintf(b, sizeof b, fmt, v);
	return b;
}

constexpr double kDeg = 180.0 / M_PI;
}  // namespace

// Passes: a door's leaf hit runs in time order, split where no run came for opt.doorPassGap seconds.
std::vector<DoorObservation> doorObservations(const sim::Truth& truth, const MapEvalOptions& opt)
{
	const std::vector<bool> seen = doorsSeenSwinging(truth, opt);
	std::vector<DoorObservation> out(truth.doors.size());
	std::vector<std::vector<const sim::HitRun*>> runs(truth.doors.size());
	for (const auto& h : truth.hits)
		if (h.kind == sim::HitKind::Door && h.id >= 0 && size_t(h.id) < truth.doors.size())
			runs[size_t(h.id)].push_back(&h);
	for (const auto& s : truth.doorSwings)
		if (s.door >= 0 && size_t(s.door) < out.size()) out[size_t(s.door)].swingTimes.push_back(s);
	for (size_t i = 0; i < out.size(); ++i)
	{
		const sim::DoorTruth& d = truth.doors[i];
		DoorObservation& o = out[i];
		o.swings = d.swings;
		o.openDeg = std::abs(std::remainder(d.openAngle - d.closedAngle, 2 * M_PI)) * kDeg;
		o.seenSwinging = seen[i];
		std::stable_sort(runs[i].begin(), runs[i].end(), [](const auto* a, const auto* b) { return a->t < b->t; });
		for (const sim::HitRun* h : runs[i])
		{
			if (o.passes.empty() || h->t - o.passes.back().t1 > opt.doorPassGap)
				o.passes.push_back({h->t, h->t, 0, false, 0, 0});
			DoorPass& p = o.passes.back();
			p.t1 = h->t;
			p.runs++;
			if (!showsLeafState(*h, opt)) continue;
			const double a = std::abs(leafAngle(*h, d)) * kDeg;
			p.minDeg = p.angled ? std::min(p.minDeg, a) : a;
			p.maxDeg = p.angled ? std::max(p.maxDeg, a) : a;
			p.angled = true;
		}
	}
	return out;
}

FalseStaticBreakdown falseStaticBreakdown(const std::vector<MapVector>& vectors, const sim::Truth& truth,
										  const MapEvalOptions& opt)
{
	FalseStaticBreakdown b;
	b.doors = doorObservations(truth, opt);
	std::vector<std::vector<Segment>> doorPlaces(truth.doors.size());
	std::vector<Segment> object, people;
	for (size_t i = 0; i < truth.doors.size(); ++i) doorPlaces[i] = doorSweep(truth.doors[i]);
	for (const auto& e : truth.objectEdges) object.push_back(e.edge);
	for (const auto& h : truth.hits)
	{
		if (h.kind == sim::HitKind::Door && h.id >= 0 && size_t(h.id) < truth.doors.size())
			doorPlaces[size_t(h.id)].push_back(h.seg);
		else if (h.kind == sim::HitKind::Object)
			object.push_back(h.seg);
		else if (h.kind == sim::HitKind::Person)
			people.push_back(h.seg);
	}
	// places[0..doors) are the doors, then the object, then people
	std::vector<SegmentIndex> places;
	for (auto& p : doorPlaces) places.emplace_back(std::move(p));
	places.emplace_back(std::move(object));
	places.emplace_back(std::move(people));
	const size_t objectIdx = truth.doors.size(), peopleIdx = objectIdx + 1;
	const SegmentIndex walls(truth.walls);
	for (const auto& v : vectors)
	{
		if (!v.isStatic) continue;
		const double len = v.seg.length();
		if (len <= 0) continue;
		const int n = sampleCount(len, opt.sampleStep);
		const double w = len / n;
		for (int k = 0; k < n; ++k)
		{
			const Vec2 p = v.seg.at((k + 0.5) / n);
			if (walls.within(p, opt.wallTolerance)) continue;
			b.total += w;
			double best = sim::kNoHit;
			size_t which = places.size();
			for (size_t q = 0; q < places.size(); ++q)
			{
				const double dq = places[q].nearest(p, opt.dynamicTolerance);
				if (dq < best) best = dq, which = q;
			}
			if (which == places.size())
				b.other += w;
			else if (which == objectIdx)
				b.movedObject += w;
			else if (which == peopleIdx)
				b.people += w;
			else
			{
				b.doors[which].falseStatic += w;
				(b.doors[which].seenSwinging ? b.twoStateDoors : b.oneStateDoors) += w;
			}
		}
	}
	return b;
}

std::string formatText(const FalseStaticBreakdown& b)
{
	std::ostringstream os;
	os << "false static:      " << f(b.total) << " m off every true wall: doors seen in one state "
	   << f(b.oneStateDoors) << ", doors seen in two states " << f(b.twoStateDoors) << ", moved object "
	   << f(b.movedObject) << ", people " << f(b.people) << ", other " << f(b.other) << " m\n";
	for (size_t i = 0; i < b.doors.size(); ++i)
	{
		const DoorObservation& d = b.doors[i];
		os << "door " << i << ": " << d.swings << " swings (open " << f(d.openDeg, "%.0f") << " deg), "
		   << (d.seenSwinging ? "seen in two states" : "seen in one state") << ", false static " << f(d.falseStatic)
		   << " m, " << d.passes.size() << " passes:";
		for (const DoorPass& p : d.passes)
		{
			os << " [" << f(p.t0 - b.timeOrigin, "%.0f") << "-" << f(p.t1 - b.timeOrigin, "%.0f") << " s, "
			   << io::counted(p.runs, "scan") << ", ";
			if (!p.angled)
				os << "no angle]";
			else if (p.maxDeg - p.minDeg < 1)
				os << f(p.minDeg, "%.0f") << " deg]";
			else
				os << f(p.minDeg, "%.0f") << "-" << f(p.maxDeg, "%.0f") << " deg]";
		}
		os << "; swings at";
		for (const auto& s : d.swingTimes)
			os << " " << f(s.t0 - b.timeOrigin, "%.0f") << "-" << f(s.t1 - b.timeOrigin, "%.0f") << " s ("
			   << f(std::abs(s.from) * kDeg, "%.0f") << "->" << f(std::abs(s.to) * kDeg, "%.0f") << ")";
		os << "\n";
	}
	return os.str();
}

nlohmann::ordered_json toJson(const FalseStaticBreakdown& b)
{
	nlohmann::ordered_json doors = nlohmann::ordered_json::array();
	for (const DoorObservation& d : b.doors)
	{
		nlohmann::ordered_json passes = nlohmann::ordered_json::array();
		for (const DoorPass& p : d.passes)
		{
			nlohmann::ordered_json pass = {{"t0", p.t0}, {"t1", p.t1}, {"scans", p.runs}};
			if (p.angled) pass["min_deg"] = p.minDeg, pass["max_deg"] = p.maxDeg;
			passes.push_back(pass);
		}
		doors.push_back({{"swings", d.swings},
						 {"seen_swinging", d.seenSwinging},
						 {"false_static_m", d.falseStatic},
						 {"passes", passes}});
	}
	return {{"false_static_m", b.total},
			{"one_state_doors_m", b.oneStateDoors},
			{"two_state_doors_m", b.twoStateDoors},
			{"moved_object_m", b.movedObject},
			{"people_m", b.people},
			{"other_m", b.other},
			{"doors", doors}};
}

}  // namespace gridvector::eval
