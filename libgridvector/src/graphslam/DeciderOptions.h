// Options of the grid-vector registration deciders, read from the graphslam-engine .ini.
#pragma once

#include <mrpt/config/CLoadableOptions.h>

#include <string>

namespace gridvector::graphslam
{
/** CGridVectorNRD options.
 *
 * `[NodeRegistrationDeciderParameters]` holds the keys every MRPT node decider reads; it is shared with
 * MRPT's deciders, so their keys there (registration_max_distance, registration_max_angle) are tolerated:
 * CGridVectorNRD's nodes are the online EM-SLAM's keyframes, spaced by [gridvector_mstep]
 * keyframe_distance and keyframe_rotation_deg. `[GridVectorNRD]` takes no key since the deciders became
 * the online EM-SLAM's (session 16): a key there is an error, so that a file written for the old deciders
 * says so instead of being silently ignored. */
struct NodeDeciderOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* sharedSection = "NodeRegistrationDeciderParameters";
	static constexpr const char* ownSection = "GridVectorNRD";

	int classVerbosity = 1;  //!< 0 debug .. 3 error

	template <class V>
	void visitShared(V&& v)
	{
		v("class_verbosity", classVerbosity, "Logger level: 0 debug, 1 info, 2 warn, 3 error");
	}
	template <class V>
	void visitOwn(V&&)
	{
	}

	/** Reads both sections; `section` is ignored (fixed names, see above).
	 * Throws std::runtime_error naming source and key on an unknown key or a
	 * value out of range. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void load(const mrpt::config::CConfigFileBase& source, const std::string& sourceName);
	void dumpToTextStream(std::ostream& out) const override;
	static std::string markdownTable();
};

/** CGridVectorERD options: `[EdgeRegistrationDeciderParameters]` (shared with MRPT's edge deciders,
 * tolerant), `[GridVectorERD]` (no key, strict: as [GridVectorNRD]) and `LC_min_nodeid_diff` from
 * `[GeneralConfiguration]`, where MRPT 2.5's edge deciders (CICPCriteriaERD, CLoopCloserERD) and
 * CLevMarqGSO read it, so all of them count the same edges as loop closures. Which edges there are is the
 * online EM-SLAM's ([gridvector_mstep]). */
struct EdgeDeciderOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* sharedSection = "EdgeRegistrationDeciderParameters";
	static constexpr const char* ownSection = "GridVectorERD";
	static constexpr const char* engineSection = "GeneralConfiguration";

	// [GeneralConfiguration]
	int lcMinNodeIdDiff = 30;
	// [EdgeRegistrationDeciderParameters]
	int classVerbosity = 1;
	/** After load(): a note when [EdgeRegistrationDeciderParameters] holds an LC_min_nodeid_diff
	 * other than the one read (no MRPT component reads it there); empty otherwise. */
	std::string ignoredKeyNote;

	template <class V>
	void visitEngine(V&& v)
	{
		v("LC_min_nodeid_diff", lcMinNodeIdDiff,
		  "An edge between nodes whose IDs differ by more than this counts as a loop closure (read here, as MRPT's "
		  "edge deciders and CLevMarqGSO read it; a different value in [EdgeRegistrationDeciderParameters] is reported "
		  "and not used)");
	}
	template <class V>
	void visitShared(V&& v)
	{
		v("class_verbosity", classVerbosity, "Logger level: 0 debug, 1 info, 2 warn, 3 error");
	}
	template <class V>
	void visitOwn(V&&)
	{
	}

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void load(const mrpt::config::CConfigFileBase& source, const std::string& sourceName);
	void dumpToTextStream(std::ostream& out) const override;
	static std::string markdownTable();
};

}  // namespace gridvector::graphslam
