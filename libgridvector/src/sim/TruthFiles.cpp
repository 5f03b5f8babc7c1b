#include "io/AtomicFile.h"
#include "io/Counted.h"
#include "io/CarmenWriter.h"
#include "io/FileBytes.h"
#include "io/TextParsing.h"
#include "sim/TruthFiles.h"

#include <cstdio>
#include <filesystem>
#include <functional>

namespace gridvector::sim
{
namespace
{
using gridvector::io::TextPos;
using Tokens = std::vector<std::string_view>;

std::string f6(double v)
{
	char b[48];
	std::snprintf(b, sizeof b, "%.6f", v);
	return b;
}

std::string seg(const Segment& s) { return f6(s.a.x) + " " + f6(s.a.y) + " " + f6(s.b.x) + " " + f6(s.b.y); }

const char* kindName(HitKind k) { return k == HitKind::Person ? "person" : k == HitKind::Door ? "door" : "object"; }

std::string join(const std::string& dir, const char* name) { return (std::filesystem::path(dir) / name).string(); }

void writeLog(const SimResult& r, std::ostream& os)
{
	io::CarmenWriter w(os, "gv-sim");
	w.comment("gridvector gv-sim: world " + r.world.name + ", seed " + std::to_string(r.options.seed) + ", " +
			  io::counted(r.scans.size(), "scan"));
	w.comment("FLASER/ODOM poses are the NOISY odometry; the true path is in truth_trajectory.txt");
	char b[64];
	std::snprintf(b, sizeof b, "%.10g", r.laserResolution * 180.0 / M_PI);
	w.param("laser_front_laser_resolution", b);
	std::snprintf(b, sizeof b, "%.10g", r.laser.fovDeg * M_PI / 180.0);
	w.param("laser_front_laser_fov", b);
	std::snprintf(b, sizeof b, "%.10g", r.laser.maxRange);
	w.param("robot_front_laser_max", b);
	w.param("robot_frontlaser_offset", "0");
	const double dt = r.options.dt;
	for (size_t k = 0; k < r.scans.size(); k++)
	{
		const SimScan& s = r.scans[k];
		double tv = 0, rv = 0;
		if (k > 0)
		{
			const auto& p = r.scans[k - 1].odometry;
			tv = std::hypot(s.odometry.x - p.x, s.odometry.y - p.y) / dt;
			rv = std::remainder(s.odometry.phi - p.phi, 2 * M_PI) / dt;
		}
		w.odom(s.odometry, tv, rv, s.t);
		w.flaser(s.ranges, s.odometry, s.odometry, s.t);
	}
}

void writePoses(const SimResult& r, std::ostream& os, bool truth)
{
	os << "# t x y theta (" << (truth ? "true robot pose" : "noisy odometry, as in sim.log") << ")\n";
	for (const auto& s : r.scans)
	{
		const auto& p = truth ? s.truth : s.odometry;
		os << f6(s.t) << ' ' << f6(p.x) << ' ' << f6(p.y) << ' ' << f6(p.phi) << '\n';
	}
}

void writeLabels(const SimResult& r, std::ostream& os)
{
	os << "# t n labels: one character per beam, in FLASER order: '-' no return, 's' static wall/furniture,\n"
	   << "# 'p' person, 'd' door, 'o' moved object (p/d/o are dynamic)\n";
	for (const auto& s : r.scans) os << f6(s.t) << ' ' << s.labels.size() << ' ' << s.labels << '\n';
}

void writeDoors(const SimResult& r, std::ostream& os)
{
	os << "# hinge_x hinge_y length closed_angle open_angle swings (angles: world direction of the leaf [rad])\n";
	for (size_t i = 0; i < r.world.doors.size(); i++)
	{
		const DoorSpec& d = r.world.doors[i];
		os << f6(d.hinge.x) << ' ' << f6(d.hinge.y) << ' ' << f6(d.length) << ' ' << f6(d.closedAngle) << ' '
		   << f6(d.openAngle) << ' ' << r.doors[i].swings.size() << '\n';
	}
}

void writeDynamic(const SimResult& r, std::ostream& os)
{
	const double t0 = r.options.startTime;
	os << "# object_move t | object NAME first|second x1 y1 x2 y2 | door_swing DOOR t0 t1 from to |\n"
	   << "# hit person|door|object ID t x1 y1 x2 y2 beams (first and last true hit point of a run of beams)\n";
	if (!r.world.objects.empty()) os << "object_move " << f6(t0 + r.objectMoveTime) << '\n';
	for (const auto& o : r.world.objects)
		for (int second = 0; second < 2; second++)
		{
			const auto& p = second ? o.second : o.first;
			for (size_t i = 0; i < p.size(); i++)
				os << "object " << o.name << (second ? " second " : " first ") << seg({p[i], p[(i + 1) % p.size()]})
				   << '\n';
		}
	for (size_t i = 0; i < r.doors.size(); i++)
		for (const auto& s : r.doors[i].swings)
			os << "door_swing " << i << ' ' << f6(t0 + s.t0) << ' ' << f6(t0 + s.t1) << ' ' << f6(s.from) << ' '
			   << f6(s.to) << '\n';
	for (const auto& h : r.dynamicHits)
		os << "hit " << kindName(h.kind) << ' ' << h.id << ' ' << f6(h.t) << ' ' << seg(h.seg) << ' ' << h.beams
		   << '\n';
}

void writeInfo(const SimResult& r, std::ostream& os)
{
	SimOptions o = r.options;
	os.precision(12);
	o.visit([&](const char* key, const auto& v, const char*) { os << key << ' ' << v << '\n'; });
	const SimStats& s = r.stats;
	os << "world_description " << r.world.description << '\n'
	   << "scans_written " << s.scans << "\nduration_s " << s.duration << "\npath_length_m " << s.pathLength
	   << "\nbeams " << s.beams << "\nstatic_hits " << s.staticHits << "\ndynamic_hits " << s.dynamicHits
	   << "\nperson_hits " << s.personHits << "\ndoor_hits " << s.doorHits << "\nobject_hits " << s.objectHits
	   << "\nno_return " << s.noHits << "\ndynamic_share " << s.dynamicShare() << "\npeople_simulated " << s.people
	   << "\ndoor_swings " << s.doorSwings << '\n';
}

void writeSegments(const std::vector<Segment>& segs, const std::string& what, std::ostream& os)
{
	os << "# x1 y1 x2 y2 (" << what << ")\n";
	for (const auto& s : segs) os << seg(s) << '\n';
}

/** Calls each(tokens, pos) for every non-comment line of a text file. */
void forEachLine(const std::string& path, const std::function<void(const Tokens&, const TextPos&)>& each)
{
	const std::vector<char> text = io::readFileBytes(path);
	io::LineCursor cur(text);
	std::string_view line;
	TextPos pos{path, 0};
	while (cur.next(line))
	{
		pos.line = cur.lineNumber();
		const Tokens t = io::splitTokens(line);
		if (!t.empty() && t[0][0] != '#') each(t, pos);
	}
}

void expectFields(const Tokens& t, size_t n, const TextPos& pos, const std::string& what)
{
	if (t.size() != n)
		io::parseError(pos, what + ": expected " + io::counted(n, "field") + ", found " + std::to_string(t.size()));
}

Segment segAt(const Tokens& t, size_t i, const TextPos& pos)
{
	const auto d = [&](size_t k, const char* w) { return io::parseDouble(t[i + k], pos, w); };
	return {d(0, "x1"), d(1, "y1"), d(2, "x2"), d(3, "y2")};
}

HitKind hitKind(std::string_view k, const TextPos& pos)
{
	if (k == "person") return HitKind::Person;
	if (k == "door") return HitKind::Door;
	if (k == "object") return HitKind::Object;
	io::parseError(pos, "unknown hit kind '" + io::printableToken(k) + "'");
}

/** A door's index in truth_doors.txt (read first): a door the doors file lacks would be a dynamic
 * place to evaluateMap's ghost figures but no door to the breakdown and the door recalls. */
int doorId(std::string_view tok, const TextPos& pos, const Truth& t)
{
	const long id = io::parseInt(tok, pos, "door", 0, 1000000);
	if (size_t(id) >= t.doors.size())
		io::parseError(pos, "door " + std::to_string(id) + " is not in " + SimFiles::doors + " (" +
								io::counted(t.doors.size(), "door") + ")");
	return int(id);
}

void readDynamicLine(const Tokens& t, const TextPos& pos, Truth& out)
{
	if (t[0] == "object_move")
		return expectFields(t, 2, pos, "object_move"), void(out.objectMoveTime = io::parseDouble(t[1], pos, "t"));
	if (t[0] == "object")
	{
		expectFields(t, 7, pos, "object");
		if (t[2] != "first" && t[2] != "second") io::parseError(pos, "object place must be first or second");
		return out.objectEdges.push_back({std::string(t[1]), t[2] == "second", segAt(t, 3, pos)});
	}
	if (t[0] == "door_swing")
	{
		expectFields(t, 6, pos, "door_swing");
		return out.doorSwings.push_back({doorId(t[1], pos, out), io::parseDouble(t[2], pos, "t0"),
										 io::parseDouble(t[3], pos, "t1"), io::parseDouble(t[4], pos, "from"),
										 io::parseDouble(t[5], pos, "to")});
	}
	if (t[0] == "hit")
	{
		expectFields(t, 9, pos, "hit");
		HitRun h;
		h.kind = hitKind(t[1], pos);
		h.id = h.kind == HitKind::Door ? doorId(t[2], pos, out) : int(io::parseInt(t[2], pos, "id", 0, 1000000));
		h.t = io::parseDouble(t[3], pos, "t");
		h.seg = segAt(t, 4, pos);
		h.beams = int(io::parseInt(t[8], pos, "beams", 1, 1000000));
		return out.hits.push_back(h);
	}
	io::parseError(pos, "unknown record '" + io::printableToken(t[0]) + "'");
}
}  // namespace

void writeSimulation(const SimResult& r, const std::string& dir)
{
	io::ensureWritableDirectory(dir);
	const auto write = [&](const char* name, const std::function<void(std::ostream&)>& fill) {
		io::writeFileAtomically(join(dir, name), fill);
	};
	write(SimFiles::log, [&](std::ostream& os) { writeLog(r, os); });
	write(SimFiles::trajectory, [&](std::ostream& os) { writePoses(r, os, true); });
	write(SimFiles::odometry, [&](std::ostream& os) { writePoses(r, os, false); });
	write(SimFiles::labels, [&](std::ostream& os) { writeLabels(r, os); });
	write(SimFiles::walls, [&](std::ostream& os) { writeSegments(r.world.walls, "static walls and furniture", os); });
	write(SimFiles::seenWalls,
		  [&](std::ostream& os) { writeSegments(r.seenWalls, "static wall parts hit by static beams", os); });
	write(SimFiles::doors, [&](std::ostream& os) { writeDoors(r, os); });
	write(SimFiles::dynamic, [&](std::ostream& os) { writeDynamic(r, os); });
	write(SimFiles::info, [&](std::ostream& os) { writeInfo(r, os); });
}

std::vector<Segment> readSegments(const std::string& path)
{
	std::vector<Segment> out;
	forEachLine(path, [&](const Tokens& t, const TextPos& pos) {
		expectFields(t, 4, pos, "segment 'x1 y1 x2 y2'");
		out.push_back(segAt(t, 0, pos));
	});
	return out;
}

std::vector<DoorTruth> readDoors(const std::string& path)
{
	std::vector<DoorTruth> out;
	forEachLine(path, [&](const Tokens& t, const TextPos& pos) {
		if (t.size() < 3)
			io::parseError(pos, "door: expected 'hinge_x hinge_y length ...', found " + io::counted(t.size(), "field"));
		DoorTruth d;
		d.hinge = {io::parseDouble(t[0], pos, "hinge_x"), io::parseDouble(t[1], pos, "hinge_y")};
		d.length = io::parseDouble(t[2], pos, "length");
		if (t.size() >= 5)
			d.closedAngle = io::parseDouble(t[3], pos, "closed_angle"),
			d.openAngle = io::parseDouble(t[4], pos, "open_angle");
		if (t.size() >= 6) d.swings = int(io::parseInt(t[5], pos, "swings", 0, 1000000));
		out.push_back(d);
	});
	return out;
}

Truth readTruth(const std::string& dir)
{
	Truth t;
	t.walls = readSegments(join(dir, SimFiles::walls));
	t.seenWalls = readSegments(join(dir, SimFiles::seenWalls));
	t.doors = readDoors(join(dir, SimFiles::doors));
	forEachLine(join(dir, SimFiles::dynamic),
				[&](const Tokens& tok, const TextPos& pos) { readDynamicLine(tok, pos, t); });
	return t;
}

}  // namespace gridvector::sim
