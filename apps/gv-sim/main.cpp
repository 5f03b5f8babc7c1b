// gv-sim: simulate a robot with a 2D laser in a dynamic built-in world; writes a
// CARMEN log (noisy odometry) and the truth files gv-eval scores against.
#include "PeerTiming.h"

#include "eval/TrajectoryEval.h"
#include "common/ArgParser.h"
#include "io/Counted.h"
#include "io/AtomicFile.h"
#include "io/FileBytes.h"
#include "io/IniLayout.h"
#include "io/IniValue.h"
#include "io/Progress.h"
#include "sim/BuiltinWorlds.h"
#include "sim/SimOptions.h"
#include "sim/Simulator.h"
#include "sim/TruthFiles.h"

#include <mrpt/config/CConfigFile.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <map>
#include <set>
#include <sstream>

using namespace gridvector;

namespace
{
std::string dashed(std::string k)
{
	for (char& c : k)
		if (c == '_') c = '-';
	return k;
}

/** Sets v from text as the .ini reader does (io/IniValue.h: whole, finite, in range);
 * booleans also take on/off (doc/simulator.md). Returns false if the text does not fit v. */
bool assign(std::string& v, const std::string& s) { return v = s, true; }
bool assign(bool& v, const std::string& s)
{
	const std::string l = io::lowerCase(s);
	if (l == "on" || l == "off") return v = l == "on", true;
	return io::parseIniValue(s, v);
}
template <class T>
bool assign(T& v, const std::string& s)
{
	return io::parseIniValue(s, v);
}

/** What assign accepts for v's type, for .ini messages. */
template <class T>
const char* kindOf(const T&)
{
	if constexpr (std::is_same_v<T, bool>)
		return "on/off, true/false, yes/no or 1/0";
	else if constexpr (std::is_integral_v<T>)
		return "an integer";
	else
		return "a finite number";
}

template <class T>
const char* typeName(const T&)
{
	if constexpr (std::is_same_v<T, bool>)
		return "on|off";
	else if constexpr (std::is_integral_v<T>)
		return "N";
	else if constexpr (std::is_floating_point_v<T>)
		return "X";
	else
		return "NAME";
}

/** SimOptions::validate on the values an .ini file set (the flags' range checks), naming the file. */
void requireValid(const sim::SimOptions& o, const std::map<std::string, std::string>& given, const std::string& path)
{
	try
	{
		o.validate();
	}
	catch (const sim::SimOptionError& e)
	{
		const auto it = given.find(e.key);
		if (it == given.end()) throw std::runtime_error(path + ": [gv_sim] " + e.what());
		throw std::runtime_error(path + ": [gv_sim] " + e.key + " = '" + it->second + "' " + e.problem);
	}
}

/** [gv_sim] keys from an .ini file; unknown keys, bad values and out-of-range values are errors. */
void loadIni(sim::SimOptions& o, const std::string& path)
{
	if (!std::filesystem::is_regular_file(path)) throw std::runtime_error(path + ": cannot read (no such file)");
	const std::vector<char> text = io::readFileBytes(path);
	io::requireIniLayout(std::string(text.begin(), text.end()), path);  // 'seed = 3' before [gv_sim] was ignored
	mrpt::config::CConfigFile ini(path);
	if (!ini.sectionExists("gv_sim"))
		throw std::runtime_error(path + ": no [gv_sim] section (gv-sim reads its options from [gv_sim] only)");
	std::set<std::string> known;
	o.visit([&](const char* k, auto&, const char*) { known.insert(k); });
	io::requireKnownKeys(ini, "gv_sim", known, path);
	std::map<std::string, std::string> given;  // key -> its text, for range messages
	o.visit([&](const char* k, auto& v, const char*) {
		if (!ini.keyExists("gv_sim", k)) return;
		const std::string s = io::iniValueText(ini, "gv_sim", k);
		if (!assign(v, s)) throw std::runtime_error(path + ": [gv_sim] " + k + " = '" + s + "' is not " + kindOf(v));
		given[k] = s;
	});
	requireValid(o, given, path);
}

std::string pct(double part, double whole)
{
	char b[32];
	std::snprintf(b, sizeof b, "%.2f%%", whole > 0 ? 100.0 * part / whole : 0.0);
	return b;
}

void printSummary(const sim::SimResult& r, const std::string& dir, double seconds)
{
	const sim::SimStats& s = r.stats;
	io::Trajectory truth, odo;
	for (const auto& k : r.scans) truth.emplace_back(k.t, k.truth), odo.emplace_back(k.t, k.odometry);
	char b[512];
	std::snprintf(b, sizeof b, "gv-sim: world %s, seed %lld: %s, %.1f m path, %.0f s, %s, %s (%s), %s",
				  r.world.name.c_str(), (long long)r.options.seed, io::counted(s.scans, "scan").c_str(), s.pathLength,
				  s.duration, io::counted(s.people, "person", "people").c_str(),
				  io::counted(r.world.doors.size(), "door").c_str(), io::counted(s.doorSwings, "swing").c_str(),
				  io::counted(r.world.objects.size(), "moved object").c_str());
	std::cout << b << "\n  beams " << s.beams << ": static " << pct(double(s.staticHits), double(s.beams))
			  << ", dynamic " << pct(double(s.dynamicHits), double(s.beams)) << " (people "
			  << pct(double(s.personHits), double(s.beams)) << ", doors " << pct(double(s.doorHits), double(s.beams))
			  << ", moved object " << pct(double(s.objectHits), double(s.beams)) << "), no return "
			  << pct(double(s.noHits), double(s.beams)) << "\n";
	if (r.scans.size() >= 3)
		std::cout << "  odometry vs truth: " << eval::formatText(eval::evaluateTrajectory(odo, truth)) << "\n";
	std::snprintf(b, sizeof b, "%.2f", seconds);
	std::cout << "wrote " << (std::filesystem::path(dir) / sim::SimFiles::log).string() << " and the truth files in "
			  << dir << "/ (" << b << " s)\n";
}
}  // namespace

int main(int argc, char** argv)
{
	io::ArgParser args("gv-sim", "[--out DIR] [options]");
	args.option("out", "DIR", "output directory", "gv-sim-WORLD-seedN");
	args.option("config", "FILE", "read options from the [gv_sim] section of an .ini file (flags override)", "none");
	args.flag("list-worlds", "list the built-in worlds and exit");
	args.flag("quiet", "no progress and no summary");
	args.flag("peer-timing", "also time MRPT's grid laser simulator on the same poses (a speed reference)");
	sim::SimOptions opt;
	opt.visit([&](const char* k, auto& v, const char* help) {
		std::ostringstream def;
		def << std::boolalpha << std::setprecision(12) << v;
		args.option(dashed(k), typeName(v), help, def.str());
	});
	return io::runTool(args, argc, argv, [&] {
		args.requirePositional(0, 0);
		if (args.has("list-worlds"))
		{
			for (const auto& n : sim::builtinWorldNames())
				std::cout << n << ": " << sim::makeWorld(n).description << "\n";
			return 0;
		}
		if (args.has("config")) loadIni(opt, args.get("config"));
		opt.visit([&](const char* k, auto& v, const char*) {
			const std::string flag = dashed(k);
			if (args.has(flag) && !assign(v, args.get(flag)))
				args.fail("--" + flag + " needs " + kindOf(v) + ", got '" + args.get(flag) + "'");
		});
		try
		{
			opt.validate();
		}
		catch (const sim::SimOptionError& e)  // a flag's value: the .ini values were checked when read
		{
			const std::string flag = dashed(e.key);
			args.fail("--" + flag + " " + e.problem + ", got '" + args.get(flag, "?") + "'");
		}
		const std::string dir = args.get("out", "gv-sim-" + opt.world + "-seed" + std::to_string(opt.seed));
		io::OutputDirectory outDir(
			dir, sim::SimFiles::info);  // fail before simulating, create when writing; sim_info.txt last
		const bool quiet = args.has("quiet");
		const auto t0 = std::chrono::steady_clock::now();
		io::Progress progress("simulating " + opt.world, quiet);
		const sim::SimResult r = sim::simulate(opt, [&](double f) { progress.update(f, size_t(f * 100)); });
		progress.done();
		const auto tSim = std::chrono::steady_clock::now();
		sim::writeSimulation(r, outDir.create());
		const double secs = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		if (!quiet) printSummary(r, dir, secs);
		if (args.has("peer-timing"))
		{
			const double simSecs = std::chrono::duration<double>(tSim - t0).count();
			std::printf(
				"timing: gv-sim %.3f s for %zu scans (simulation only); MRPT COccupancyGridMap2D::laserScanSimulator "
				"on a 5 cm grid of the static walls, same poses: %.3f s\n",
				simSecs, r.scans.size(), timeMrptLaserSimulator(r));
		}
		return 0;
	});
}
