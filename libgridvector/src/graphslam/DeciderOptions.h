// Options of the grid-vector registration deciders, read from the graphslam-engine .ini.
#pragma once

#include <mrpt/config/CLoadableOptions.h>

#include <string>

namespace gridvector::graphslam
{
/** CGridVectorNRD options.
 *
 * `[NodeRegistrationDeciderParameters]` holds the keys every MRPT node decider
 * reads (same names, units and meaning as CICPCriteriaNRD's); it is shared with
 * MRPT's deciders, so other keys there are tolerated. `[GridVectorNRD]` holds
 * this decider's own keys; an unknown key there is an error. */
struct NodeDeciderOptions : public mrpt::config::CLoadableOptions
{
	static constexpr const char* sharedSection = "NodeRegistrationDeciderParameters";
	static constexpr const char* ownSection = "GridVectorNRD";

	// [NodeRegistrationDeciderParameters]
	double registrationMaxDistance = 0.5;  //!< [m]
	double registrationMaxAngleDeg = 10.0;  //!< [deg]
	int classVerbosity = 1;  //!< 0 debug .. 3 error

	// [GridVectorNRD]
	double maxCorrectionDistance = 0.5;  //!< [m]
	double maxCorrectionAngleDeg = 15.0;  //!< [deg]
	bool useOdometry = true;

	template <class V>
	void visitShared(V&& v)
	{
		v("registration_max_distance", registrationMaxDistance,
		  "Register a node once the robot moved this far from the last node [m]");
		v("registration_max_angle", registrationMaxAngleDeg, "... or turned this much [deg]");
		v("class_verbosity", classVerbosity, "Logger level: 0 debug, 1 info, 2 warn, 3 error");
	}
	template <class V>
	void visitOwn(V&& v)
	{
		v("max_correction_distance", maxCorrectionDistance,
		  "A vector match whose pose differs from the odometry prediction by more than this is rejected (odometry used "
		  "instead) [m]");
		v("max_correction_angle_deg", maxCorrectionAngleDeg, "... or whose heading differs by more than this [deg]");
		v("use_odometry", useOdometry,
		  "Fuse the odometry increment with the vector match (information form); false: vector match alone, odometry "
		  "only as the initial guess and fallback");
	}

	/** Reads both sections; `section` is ignored (fixed names, see above).
	 * Throws std::runtime_error naming source and key on an unknown key or a
	 * value out of range. */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void load(const mrpt::config::CConfigFileBase& source, const std::string& sourceName);
	void dumpToTextStream(std::ostream& out) const override;
	static std::string markdownTable();
};

/** CGridVectorERD options: `[EdgeRegistrationDeciderParameters]` (shared
 * with MRPT's edge deciders, tolerant) and `[GridVectorERD]` (strict); `LC_min_nodeid_diff`
 * from `[GeneralConfiguration]`, where MRPT 2.5's edge deciders (CICPCriteriaERD,
 * CLoopCloserERD) and CLevMarqGSO read it, so all of them count the same edges as loop closures. */
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

	// [GridVectorERD]
	double maxDistance = 3.0;  //!< [m]
	int sequentialWindow = 3;
	bool matchPreviousNode = false;
	int passGap = 10;
	int maxLoopCandidates = 3;
	double minMatchedShare = 0.3;
	double maxCorrectionDistance = 0.5;  //!< [m]
	double maxCorrectionAngleDeg = 10.0;  //!< [deg]
	double searchOffset = 0.75;  //!< [m]
	double searchAngleDeg = 0.0;  //!< [deg]

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
	void visitOwn(V&& v)
	{
		v("max_distance", maxDistance,
		  "Only nodes whose current estimate lies within this of the new node are registered against it [m]");
		v("sequential_window", sequentialWindow,
		  "Register the new node against this many predecessors before the previous one (n-2 ... n-1-window)");
		v("match_previous_node", matchPreviousNode,
		  "Also register against node n-1 (set it when the node decider is odometry-only, e.g. CFixedIntervalsNRD; "
		  "CGridVectorNRD's edge already is a vector match)");
		v("pass_gap", passGap,
		  "Older candidate nodes whose IDs are closer than this belong to one pass through the place; one candidate "
		  "per pass");
		v("max_loop_candidates", maxLoopCandidates,
		  "At most this many older passes (nearest first) are registered against per new node");
		v("min_matched_share", minMatchedShare,
		  "A non-sequential registration needs this share of the shorter scan's vector length matched (0..1]");
		v("max_correction_distance", maxCorrectionDistance,
		  "A registration that moves the relative pose further than this from the graph's estimate is rejected [m]");
		v("max_correction_angle_deg", maxCorrectionAngleDeg, "... or turns it more than this [deg]");
		v("search_offset", searchOffset,
		  "Earlier passes: if the registration from the graph's estimate fails, retry from the estimate shifted by -d, "
		  "0, +d in x and y (0: no retry); the correction gate widens by d [m]");
		v("search_angle_deg", searchAngleDeg, "... and turned by -a, 0, +a; the angle gate widens by a [deg]");
	}

	void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
	void load(const mrpt::config::CConfigFileBase& source, const std::string& sourceName);
	void dumpToTextStream(std::ostream& out) const override;
	static std::string markdownTable();
};

}  // namespace gridvector::graphslam
