#include <gridvector/GridVectorConfig.h>
#include <gridvector/io/IniLayout.h>
#include <gridvector/io/IniValue.h>

#include <mrpt/config/CConfigFileMemory.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <charconv>
#include <set>
#include <sstream>
#include <stdexcept>
#include <type_traits>

namespace gridvector
{
namespace
{
template <class T>
std::string toText(const T& value)
{
	std::ostringstream os;
	if constexpr (std::is_same_v<T, bool>) os << (value ? "true" : "false");
	else os << value;
	return os.str();
}

template <class Group>
std::set<std::string> keysOf(Group& g)
{
	std::set<std::string> keys;
	g.visit([&](const char* key, auto&, const char*) { keys.insert(key); });
	return keys;
}

/** Every section named `<prefix>_<something>` must be one of ours: a typo in a section name
 * ([gridvector_gird]) would otherwise drop all its keys silently. MRPT matches section names
 * case-insensitively, so this does too. */
void requireKnownSections(const mrpt::config::CConfigFileBase& cfg, const std::string& prefix,
						  const std::vector<std::string>& known, const std::string& sourceName)
{
	const std::string head = io::lowerCase(prefix + "_");
	std::vector<std::string> sections;
	cfg.getAllSections(sections);
	for (const auto& s : sections)
	{
		const std::string l = io::lowerCase(s);
		if (l.size() <= head.size() || l.compare(0, head.size(), head) != 0) continue;
		bool ok = false;
		for (const auto& k : known) ok = ok || l.substr(head.size()) == io::lowerCase(k);
		if (ok) continue;
		std::string list;
		for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
		throw std::runtime_error(sourceName + ": unknown section [" + s + "] (the " + prefix + "_ sections are " + list + ")");
	}
}

}  // namespace

void GridVectorConfig::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& cfg, const std::string& prefix,
	const std::string& sourceName, const std::vector<std::string>& otherSections)
{
	std::vector<std::string> known = otherSections;
	visitGroups([&](const char* group, auto&) { known.emplace_back(group); });
	requireKnownSections(cfg, prefix, known, sourceName);
	visitGroups([&](const char* group, auto& g) {
		const std::string section = prefix + "_" + group;
		if (!cfg.sectionExists(section)) return;
		io::requireKnownKeys(cfg, section, keysOf(g), sourceName);
		g.visit([&](const char* key, auto& field, const char*) { io::readIniValue(cfg, section, key, field, sourceName); });
	});
	validate();
}

void GridVectorConfig::loadFromFile(const std::string& iniPath, const std::string& prefix)
{
	// read here, not by CConfigFile: it sizes the file by seeking, which fails on pipes (--config <(...))
	if (std::filesystem::is_directory(iniPath)) throw std::runtime_error(iniPath + ": cannot read config file (it is a directory)");
	std::ifstream in(iniPath, std::ios::binary);
	if (!in) throw std::runtime_error(iniPath + ": cannot open config file");
	const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
	if (in.bad()) throw std::runtime_error(iniPath + ": cannot read config file (read error)");
	io::requireIniLayout(text, iniPath);
	mrpt::config::CConfigFileMemory cfg(text);
	try
	{
		loadFromConfigFile(cfg, prefix, iniPath);
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(iniPath + ": " + e.what());
	}
}

void GridVectorConfig::dumpAsIni(std::ostream& out, const std::string& prefix) const
{
	auto& self = const_cast<GridVectorConfig&>(*this);
	self.visitGroups([&](const char* group, auto& g) {
		out << "[" << prefix << "_" << group << "]\n";
		g.visit([&](const char* key, auto& field, const char* doc) {
			out << "; " << doc << "\n" << key << " = " << toText(field) << "\n";
		});
		out << "\n";
	});
}

std::string GridVectorConfig::parameterTableMarkdown(const std::string& prefix)
{
	GridVectorConfig defaults;
	std::ostringstream out;
	out << "| section | key | default | meaning |\n|---|---|---|---|\n";
	defaults.visitGroups([&](const char* group, auto& g) {
		g.visit([&](const char* key, auto& field, const char* doc) {
			out << "| `[" << prefix << "_" << group << "]` | `" << key << "` | "
				<< toText(field) << " | " << doc << " |\n";
		});
	});
	return out.str();
}

void GridVectorConfig::validate() const
{
	auto require = [](bool ok, const char* what) {
		if (!ok) throw std::invalid_argument(std::string("invalid parameter: ") + what);
	};
	// every floating-point key finite: the .ini reader refuses nan/inf, code that sets a key may not
	const_cast<GridVectorConfig&>(*this).visitGroups([&](const char* group, auto& g) {
		g.visit([&](const char* key, auto& field, const char*) {
			if constexpr (std::is_floating_point_v<std::decay_t<decltype(field)>>)
				if (!std::isfinite(field))
					throw std::invalid_argument(std::string("invalid parameter: ") + group + "." + key + " must be finite");
		});
	});
	require(extraction.splitThreshold > 0, "extraction.split_threshold must be > 0");
	require(extraction.mergeThreshold > 0, "extraction.merge_threshold must be > 0");
	require(extraction.minPoints >= 2, "extraction.min_points must be >= 2");
	require(extraction.minLength >= 0, "extraction.min_length must be >= 0");
	require(extraction.breakDistance > 0, "extraction.break_distance must be > 0");
	require(extraction.breakNoiseSigmas >= 0, "extraction.break_noise_sigmas must be >= 0");
	require(grid.resolution > 0, "grid.resolution must be > 0");
	require(grid.halfWidth >= 0 && grid.halfWidth <= 20, "grid.half_width must be in [0,20]");
	require(grid.priorVisit > 0 && grid.priorOccupy >= 0 && grid.priorOccupy <= grid.priorVisit,
			"grid priors need 0 <= prior_occupy <= prior_visit, prior_visit > 0");
	require(map.hitBand > 0, "map.hit_band must be > 0");
	require(occupancy.resolution > 0, "occupancy.resolution must be > 0");
	require(occupancy.margin >= 0, "occupancy.margin must be >= 0");
	require(occupancy.samplesPerAxis >= 0 && occupancy.samplesPerAxis <= 16,
			"occupancy.samples_per_axis must be in [0,16]");
	require(map.indexCellSize > 0, "map.index_cell_size must be > 0");
	require(map.mergeRegridTolerance >= 0, "map.merge_regrid_tolerance must be >= 0");
	require(map.mergeCascadeRounds >= 1 && map.mergeGroupRounds >= 1,
			"map.merge_cascade_rounds and merge_group_rounds must be >= 1");
	require(estep.staticThreshold > 0 && estep.staticThreshold < 1, "estep.static_threshold must be in (0,1)");
	require(mstep.maxIterations >= 1, "mstep.max_iterations must be >= 1");
	require(mstep.sequentialWindow >= 1, "mstep.sequential_window must be >= 1");
	require(mstep.dropDistanceFactor > 0 && mstep.dropLengthShare >= 0 && mstep.movedGateShare >= 0,
			"mstep: drop_distance_factor must be > 0, drop_length_share and moved_gate_share >= 0");
	require(mstep.changedTranslation >= 0 && mstep.changedRotation >= 0 && mstep.searchedNearDistance >= 0 &&
				mstep.searchedNearDeg >= 0,
			"mstep: changed_* and searched_near_* must be >= 0");
	require(mstep.loopWindowMinTranslation >= 0 && mstep.loopWindowMinTranslation <= mstep.loopSearchMaxRadius &&
				mstep.loopWindowMinRotationDeg >= 0 &&
				mstep.loopWindowMinRotationDeg <= 180,
			"mstep: loop_window_min_translation must be in [0, loop_search_max_radius], loop_window_min_rotation_deg in [0,180]");
	require(mstep.consistencyInfoXY > 0 && mstep.consistencyInfoPhi > 0 && mstep.consistencyChainVarXY >= 0 &&
				mstep.consistencyChainVarPhi >= 0,
			"mstep: consistency_info_* must be > 0, consistency_chain_var_* >= 0");
	require(mstep.strongMinCorrespondences >= 0 && mstep.strongMinShare >= 0 && mstep.strongMinDegeneracy >= 0,
			"mstep: strong_min_* must be >= 0");
	require(mstep.loopCornerMinLength >= 0 && mstep.loopCornerMinAngleDeg >= 0 && mstep.loopCornerMinAngleDeg <= 90 &&
				mstep.loopCornerMaxGap >= 0 && mstep.loopCornerTurnToleranceDeg >= 0,
			"mstep: loop_corner_* must be >= 0, loop_corner_min_angle_deg <= 90");
	require(mstep.loopDuplicateDistance >= 0 && mstep.loopDuplicateDeg >= 0 && mstep.loopScoreGateFactor > 0 &&
				mstep.loopDistinctDeg >= 0,
			"mstep: loop_duplicate_* and loop_distinct_deg must be >= 0, loop_score_gate_factor > 0");
	require(mstep.keyframeDistance >= 0 && mstep.keyframeRotationDeg >= 0, "mstep.keyframe_* must be >= 0");
	require(estep.minPieceLength >= 0 && estep.hysteresis >= 0 && estep.freeWeight > 0,
			"estep: min_piece_length and hysteresis must be >= 0, free_weight > 0");
	require(matcher.maxIterations >= 1 && matcher.minMatches >= 1, "matcher.max_iterations and min_matches must be >= 1");
	require(matcher.gateShrink >= MatcherOptions::kMinGateShrink && matcher.gateShrink <= 1, "matcher.gate_shrink must be in [0.05,1]");
	require(matcher.robustScaleGateShare > 0, "matcher.robust_scale_gate_share must be > 0");
	require(matcher.gateRhoFinal > 0 && matcher.gatePsiFinalDeg > 0 && matcher.sigmaFloor > 0,
			"matcher gates and sigma_floor must be > 0");
	require(posegraph.robustKernelWidth > 0 && posegraph.maxIterations >= 1,
			"posegraph.robust_kernel_width must be > 0, max_iterations >= 1");
	require(posegraph.correlatedGroupGap >= 0 && posegraph.correlatedGroupRho >= 0 && posegraph.correlatedGroupRho <= 1,
			"posegraph.correlated_group_gap must be >= 0, correlated_group_rho in [0,1]");
	require(posegraph.rejectRounds >= 0 && posegraph.graduationIterations >= 1,
			"posegraph.reject_rounds must be >= 0, graduation_iterations >= 1");
	require(posegraph.tolerance >= 0 && posegraph.graduationTolerance >= 0,
			"posegraph.tolerance and graduation_tolerance must be >= 0");
	require(posegraph.graduationTrigger > 0 && posegraph.graduationPercentile >= 0 &&
				posegraph.graduationPercentile <= 100 && posegraph.graduationStartPhi > 0,
			"posegraph: graduation_trigger and graduation_start_phi must be > 0, graduation_percentile in [0,100]");
	require(posegraph.graduationFactor > 0 && posegraph.graduationFactor < 1,
			"posegraph.graduation_factor must be in (0,1)");
	require(posegraph.lmMinLambda > 0 && posegraph.lmInitialLambda >= posegraph.lmMinLambda &&
				posegraph.lmMaxLambda > posegraph.lmInitialLambda,
			"posegraph: need 0 < lm_min_lambda <= lm_initial_lambda < lm_max_lambda");
	require(doors.minDoorLength > 0 && doors.maxDoorLength >= doors.minDoorLength,
			"doors: need 0 < min_door_length <= max_door_length");
	require(doors.minSweepDeg >= 0 && doors.minSweepDeg <= 360, "doors.min_sweep_deg must be in [0,360]");
	require(doors.leafChainGap >= 0 && doors.leafChainMaxTurnDeg >= 0 && doors.leafChainMaxTurnDeg <= 180,
			"doors: need leaf_chain_gap >= 0 and leaf_chain_max_turn_deg in [0,180]");
}

namespace
{
// The shortest text that reads back as the same double.
std::string shortest(double v)
{
	char buf[32];
	const auto r = std::to_chars(buf, buf + sizeof buf, v);
	return std::string(buf, r.ptr);
}

template <class T>
bool assignNamed(T& field, double value, const std::string& name)
{
	if constexpr (std::is_same_v<T, double>) field = value;
	else if constexpr (std::is_same_v<T, bool>)
	{
		if (value != 0 && value != 1)
			throw std::invalid_argument(name + " is a bool, got " + toText(value));
		field = value != 0;
	}
	else
	{
		if (!(value == std::floor(value) && std::abs(value) <= 2147483647.0))
			throw std::invalid_argument(name + " is an integer, got " + toText(value));
		field = T(value);
	}
	return true;
}
}  // namespace

std::vector<std::pair<std::string, double>> GridVectorConfig::namedValues() const
{
	std::vector<std::pair<std::string, double>> out;
	auto self = *this;
	self.visitGroups([&](const char* group, auto& g) {
		g.visit([&](const char* key, auto& field, const char*) {
			out.emplace_back(std::string(group) + "." + key, double(field));
		});
	});
	return out;
}

bool GridVectorConfig::setNamedValue(const std::string& name, double value)
{
	bool found = false;
	visitGroups([&](const char* group, auto& g) {
		if (found || name.compare(0, std::strlen(group), group) != 0 || name.size() <= std::strlen(group) ||
			name[std::strlen(group)] != '.')
			return;
		const std::string key = name.substr(std::strlen(group) + 1);
		g.visit([&](const char* k, auto& field, const char*) {
			if (!found && key == k) found = assignNamed(field, value, name);
		});
	});
	return found;
}

std::string GridVectorConfig::toJson() const
{
	std::ostringstream out;
	out << "{";
	auto self = *this;
	const char* groupSep = "";
	self.visitGroups([&](const char* group, auto& g) {
		out << groupSep << "\"" << group << "\": {";
		groupSep = ", ";
		const char* sep = "";
		g.visit([&](const char* key, auto& field, const char*) {
			out << sep << "\"" << key << "\": ";
			if constexpr (std::is_same_v<std::decay_t<decltype(field)>, bool>) out << (field ? "true" : "false");
			else if (std::isfinite(double(field))) out << shortest(double(field));
			else out << "null";  // JSON has no inf/nan
			sep = ", ";
		});
		out << "}";
	});
	out << "}";
	return out.str();
}

}  // namespace gridvector
