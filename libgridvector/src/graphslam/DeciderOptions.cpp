#include <gridvector/graphslam/DeciderOptions.h>
#include <gridvector/graphslam/IniKeys.h>

#include <sstream>

namespace gridvector::graphslam
{
namespace
{
template <class Opts>
void loadBoth(Opts& o, const mrpt::config::CConfigFileBase& cfg, const std::string& source)
{
	readSection(cfg, Opts::sharedSection, false, source, [&](auto&& v) { o.visitShared(v); });
	readSection(cfg, Opts::ownSection, true, source, [&](auto&& v) { o.visitOwn(v); });
}

template <class Opts>
void dumpBoth(const Opts& opts, std::ostream& out)
{
	Opts o = opts;
	dumpSection(out, Opts::sharedSection, [&](auto&& v) { o.visitShared(v); });
	dumpSection(out, Opts::ownSection, [&](auto&& v) { o.visitOwn(v); });
}

template <class Opts>
std::string tableOf()
{
	Opts o;
	std::ostringstream out;
	out << "| section | key | default | meaning |\n|---|---|---|---|\n";
	markdownRows(out, Opts::sharedSection, [&](auto&& v) { o.visitShared(v); });
	markdownRows(out, Opts::ownSection, [&](auto&& v) { o.visitOwn(v); });
	return out.str();
}
}  // namespace

void NodeDeciderOptions::load(const mrpt::config::CConfigFileBase& cfg, const std::string& source)
{
	loadBoth(*this, cfg, source);
	const std::string s = sharedSection, own = ownSection;
	require(registrationMaxDistance > 0, source, s, "registration_max_distance must be > 0");
	require(registrationMaxAngleDeg > 0, source, s, "registration_max_angle must be > 0");
	require(classVerbosity >= 0 && classVerbosity <= 3, source, s, "class_verbosity must be in 0..3");
	require(maxCorrectionDistance > 0, source, own, "max_correction_distance must be > 0");
	require(maxCorrectionAngleDeg > 0, source, own, "max_correction_angle_deg must be > 0");
}

void NodeDeciderOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string&)
{
	load(cfg, "config");
}

void NodeDeciderOptions::dumpToTextStream(std::ostream& out) const { dumpBoth(*this, out); }
std::string NodeDeciderOptions::markdownTable() { return tableOf<NodeDeciderOptions>(); }

void EdgeDeciderOptions::load(const mrpt::config::CConfigFileBase& cfg, const std::string& source)
{
	loadBoth(*this, cfg, source);
	const std::string s = sharedSection, own = ownSection;
	require(lcMinNodeIdDiff >= 1, source, s, "LC_min_nodeid_diff must be >= 1");
	require(classVerbosity >= 0 && classVerbosity <= 3, source, s, "class_verbosity must be in 0..3");
	require(maxDistance > 0, source, own, "max_distance must be > 0");
	require(sequentialWindow >= 0, source, own, "sequential_window must be >= 0");
	require(passGap >= 1, source, own, "pass_gap must be >= 1");
	require(maxLoopCandidates >= 0, source, own, "max_loop_candidates must be >= 0");
	require(minMatchedShare > 0 && minMatchedShare <= 1, source, own, "min_matched_share must be in (0, 1]");
	require(maxCorrectionDistance > 0, source, own, "max_correction_distance must be > 0");
	require(maxCorrectionAngleDeg > 0, source, own, "max_correction_angle_deg must be > 0");
	require(searchOffset >= 0, source, own, "search_offset must be >= 0");
	require(searchAngleDeg >= 0 && searchAngleDeg < 90, source, own, "search_angle_deg must be in [0, 90)");
}

void EdgeDeciderOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string&)
{
	load(cfg, "config");
}

void EdgeDeciderOptions::dumpToTextStream(std::ostream& out) const { dumpBoth(*this, out); }
std::string EdgeDeciderOptions::markdownTable() { return tableOf<EdgeDeciderOptions>(); }

}  // namespace gridvector::graphslam
