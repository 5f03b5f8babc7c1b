#include "config/ConfigProfile.h"
#include "em/EmSlam.h"

#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace gridvector
{
namespace
{
std::vector<ConfigProfile> makeProfiles()
{
	ConfigProfile lib{"library", "GridVectorConfig{}: the paper's defaults (gv-map, gv-sim, CGridVectorMap, gv-graphslam)", {}, {}};
	ConfigProfile em{"em-slam", "EmSlam::defaultConfig(): the built-in defaults of gv-em-slam (used when --config is not given, and under it)",
					 EmSlam::defaultConfig(), {}};
	const char* dense =
		"denser extraction for registration: cluttered rooms need the small features (door frames, cabinets) that "
		"constrain motion along corridors";
	em.reasons["extraction.min_points"] = std::string(dense) + " (3-point runs kept)";
	em.reasons["extraction.min_length"] = std::string(dense) + " (short vectors kept)";
	em.reasons["extraction.max_point_gap"] =
		std::string(dense) + " (a vector may span sparser points, e.g. a wall seen at a grazing angle)";
	em.reasons["map.wipe_counts_beams"] =
		"the paper's Fig. 2 unit (one increment per cell and wipe triangle) for the per-scan maps the E-step "
		"classifies; the library default counts beams to keep Algorithm 1's endpoint counts and the wipes in one "
		"unit (doc/benchmarks-history.md, Global map)";
	const char* seeds =
		"together with the other of matcher.step_within_gates / mstep.overlap_reregister_moved: over mkbench seeds "
		"1-9 the worst loop error goes from 0.4670 to 0.0466 m on aces (seed 8: a corridor registration locked onto "
		"the neighbouring door recess) and from 0.2037 to 0.1228 m on csail (seed 4: a first-M-step registration ran "
		"away from its guess); aces seeds 1-3 cost 0.0015-0.0025 m (doc/benchmarks.md, Seeds beyond 1-3); off in the "
		"library for gv-graphslam and CGridVectorMap";
	em.reasons["matcher.step_within_gates"] = seeds;
	em.reasons["mstep.overlap_reregister_moved"] = seeds;
	em.reasons["mstep.sequential_odometry_guess"] =
		"csail seed 8: the first M-step's chain placed scan 42 ~10 deg off its neighbours and scan 43 then "
		"registered against none of its predecessors; from the odometry guess 41-43 registers and the loop error "
		"goes from 0.1228 to 0.0412 m; over mkbench seeds 1-9 csail 0.0345-0.0412 (was 0.0343-0.1228), no log or "
		"seed worse by more than 0.0003 m (doc/benchmarks.md, Seeds beyond 1-3); off in the library for "
		"gv-graphslam and CGridVectorMap";
	em.reasons["posegraph.odometry_sigma_xy_per_m"] =
		"odometry edges (Eq. 21) weighted by what the benchmark logs' residuals show: at the optimum the estimate "
		"departs from the odometry by 0.036-0.052 m per metre (per axis), well inside 0.08; 0.06 lowered the loop "
		"error on intel, aces, csail, freiburg-101 and seattle, freiburg-079 equal within 0.0001 m (doc/benchmarks-history.md, "
		"Real logs); the library default stays for gv-graphslam";
	return {lib, em};
}

bool isBoolKey(const std::string& name)
{
	bool isBool = false;
	GridVectorConfig c;
	c.visitGroups([&](const char* group, auto& g) {
		g.visit([&](const char* key, auto& field, const char*) {
			if (name == std::string(group) + "." + key) isBool = std::is_same_v<std::decay_t<decltype(field)>, bool>;
		});
	});
	return isBool;
}

std::string number(double v)
{
	std::ostringstream os;
	os << v;
	return os.str();
}
}  // namespace

const std::vector<ConfigProfile>& configProfiles()
{
	static const std::vector<ConfigProfile> profiles = makeProfiles();
	return profiles;
}

const ConfigProfile& configProfile(const std::string& name)
{
	std::string known;
	for (const auto& p : configProfiles())
	{
		if (p.name == name) return p;
		known += (known.empty() ? "" : ", ") + p.name;
	}
	throw std::invalid_argument("unknown profile '" + name + "' (known: " + known + ")");
}

std::vector<ProfileDifference> profileDifferences(const ConfigProfile& p)
{
	const auto lib = GridVectorConfig().namedValues();
	const auto mine = p.config.namedValues();
	std::vector<ProfileDifference> out;
	for (size_t i = 0; i < lib.size(); ++i)
	{
		if (lib[i].second == mine[i].second) continue;
		const auto r = p.reasons.find(lib[i].first);
		if (r == p.reasons.end())
			throw std::logic_error("profile " + p.name + ": " + lib[i].first + " differs from the library default without a documented reason");
		out.push_back({lib[i].first, lib[i].second, mine[i].second, r->second});
	}
	if (out.size() != p.reasons.size())
		throw std::logic_error("profile " + p.name + ": a documented reason names a key that does not differ");
	return out;
}

std::string profileTableMarkdown(const ConfigProfile& p, const std::string& prefix)
{
	std::ostringstream out;
	out << "| `[section]` key | library default | " << p.name << " | why |\n|---|---|---|---|\n";
	for (const auto& d : profileDifferences(p))
	{
		const auto dot = d.key.find('.');
		const bool isBool = isBoolKey(d.key);
		auto text = [&](double v) { return isBool ? std::string(v != 0 ? "true" : "false") : number(v); };
		out << "| `[" << prefix << "_" << d.key.substr(0, dot) << "] " << d.key.substr(dot + 1) << "` | "
			<< text(d.library) << " | " << text(d.profile) << " | " << d.reason << " |\n";
	}
	return out.str();
}

}  // namespace gridvector
