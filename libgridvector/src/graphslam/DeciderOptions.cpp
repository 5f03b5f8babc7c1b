#include "graphslam/DeciderOptions.h"
#include "graphslam/IniKeys.h"

#include <sstream>
#include <type_traits>

namespace gridvector::graphslam
{
namespace
{
template <class Opts>
void loadBoth(Opts& o, const mrpt::config::CConfigFileBase& cfg, const std::string& source)
{
	readSection(cfg, Opts::sharedSection, false, source, [&](auto&& v) { o.visitShared(v); });
	readSection(cfg, Opts::ownSection, true, source, [&](auto&& v) { o.visitOwn(v); });  // no key: any is an error
}

template <class Opts>
void dumpBoth(const Opts& opts, std::ostream& out)
{
	Opts o = opts;
	if constexpr (std::is_same_v<Opts, EdgeDeciderOptions>)
		dumpSection(out, Opts::engineSection, [&](auto&& v) { o.visitEngine(v); });
	dumpSection(out, Opts::sharedSection, [&](auto&& v) { o.visitShared(v); });  // the own section has no key
}

template <class Opts>
std::string tableOf()
{
	Opts o;
	std::ostringstream out;
	out << "| section | key | default | meaning |\n|---|---|---|---|\n";
	if constexpr (std::is_same_v<Opts, EdgeDeciderOptions>)
		markdownRows(out, Opts::engineSection, [&](auto&& v) { o.visitEngine(v); });
	markdownRows(out, Opts::sharedSection, [&](auto&& v) { o.visitShared(v); });
	return out.str();
}

// LC_min_nodeid_diff where no MRPT component reads it: MRPT's own files hold one there
// (odometry_2DRangeScans.ini: 30 there, 50 in [GeneralConfiguration]), so a note, not an error.
std::string ignoredLcNote(const mrpt::config::CConfigFileBase& cfg, const std::string& source, int used)
{
	const char* key = "LC_min_nodeid_diff";
	if (!cfg.keyExists(EdgeDeciderOptions::sharedSection, key)) return {};
	int there = used;
	detail::readKey(cfg, EdgeDeciderOptions::sharedSection, key, there, source);
	if (there == used) return {};
	return source + ": [" + EdgeDeciderOptions::sharedSection + "] " + key + " = " + std::to_string(there) +
		   " is not used: MRPT's edge deciders, CLevMarqGSO and CGridVectorERD read it from [" +
		   EdgeDeciderOptions::engineSection + "] (" + std::to_string(used) + ")";
}
}  // namespace

void NodeDeciderOptions::load(const mrpt::config::CConfigFileBase& cfg, const std::string& source)
{
	loadBoth(*this, cfg, source);
	require(classVerbosity >= 0 && classVerbosity <= 3, source, sharedSection, "class_verbosity", classVerbosity,
			"must be in 0..3");
}

void NodeDeciderOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string&)
{
	load(cfg, "config");
}

void NodeDeciderOptions::dumpToTextStream(std::ostream& out) const { dumpBoth(*this, out); }
std::string NodeDeciderOptions::markdownTable() { return tableOf<NodeDeciderOptions>(); }

void EdgeDeciderOptions::load(const mrpt::config::CConfigFileBase& cfg, const std::string& source)
{
	readSection(cfg, engineSection, false, source, [&](auto&& v) { visitEngine(v); });
	loadBoth(*this, cfg, source);
	ignoredKeyNote = ignoredLcNote(cfg, source, lcMinNodeIdDiff);
	require(lcMinNodeIdDiff >= 1, source, engineSection, "LC_min_nodeid_diff", lcMinNodeIdDiff, "must be >= 1");
	require(classVerbosity >= 0 && classVerbosity <= 3, source, sharedSection, "class_verbosity", classVerbosity,
			"must be in 0..3");
}

void EdgeDeciderOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string&)
{
	load(cfg, "config");
}

void EdgeDeciderOptions::dumpToTextStream(std::ostream& out) const { dumpBoth(*this, out); }
std::string EdgeDeciderOptions::markdownTable() { return tableOf<EdgeDeciderOptions>(); }

}  // namespace gridvector::graphslam
