// gridvector: every tunable parameter of the system, with its default and valid range.
//
// Each group is a plain struct with a visit() that lists its keys once, each as
// v("key", field, "help [unit]", range); loading from MRPT .ini files, dumping,
// rejecting unknown keys, range checks and the parameter table in
// doc/parameters.md all walk that one list.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <algorithm>
#include <cmath>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace gridvector
{
/** The valid values of one key: a lower and an upper bound (both finite), each closed or
 * open; a bool's range is just true/false. Printed as "[0, 1]", "(0, 90)", "true/false". */
struct Range
{
	double lo = 0, hi = 1;
	bool loOpen = false, hiOpen = false;
	bool flag = false;  //!< a bool key

	static constexpr Range closed(double lo, double hi) { return {lo, hi, false, false, false}; }  //!< [lo, hi]
	static constexpr Range above(double lo, double hi) { return {lo, hi, true, false, false}; }  //!< (lo, hi]
	static constexpr Range open(double lo, double hi) { return {lo, hi, true, true, false}; }  //!< (lo, hi)
	static constexpr Range boolean() { return {0, 1, false, false, true}; }  //!< true/false

	constexpr bool contains(double v) const { return (loOpen ? v > lo : v >= lo) && (hiOpen ? v < hi : v <= hi); }
	/** "[0, 1]", "(0, 90)", ..., or "true/false". */
	std::string text() const;
};

/** Sec. 3.1: split-and-merge line extraction (Borges & Aldon 2004). */
struct ExtractionOptions
{
	double minRange = 0.02;
	double breakDistance = 0.20;
	double breakAngleDeg = 10.0;
	double splitThreshold = 0.04;
	double mergeThreshold = 0.04;
	int minPoints = 3;
	double minLength = 0.12;
	double maxPointGap = 1.0;
	double breakNoiseSigmas = 3.0;

	/** A noise allowance stops here: the thresholds' own upper bound [m]. */
	static constexpr double kMaxNoiseAllowance = 1.0;
	/** break_noise_sigmas x a scanner's range std. dev. `sigma` (>= 0, LocalScan::rangeSigma), at most
	 * kMaxNoiseAllowance: how far the split and merge thresholds and Eq. 8's hit band widen for it [m]. */
	double noiseAllowance(double sigma) const { return std::min(kMaxNoiseAllowance, breakNoiseSigmas * sigma); }

	template <class V>
	void visit(V&& v)
	{
		v("min_range", minRange, "Readings at or below this range are invalid [m]", Range::closed(0, 10));
		v("break_distance", breakDistance, "Range jump between neighbouring points that breaks a segment [m]",
		  Range::above(0, 10));
		v("break_angle_deg", breakAngleDeg, "Adaptive breakpoint: smallest incidence angle of a surface [deg]",
		  Range::open(0, 90));
		v("split_threshold", splitThreshold,
		  "Split a segment where a point lies further than this from its line; at least break_noise_sigmas x the "
		  "scan's stdError [m]",
		  Range::above(0, 1));
		v("merge_threshold", mergeThreshold,
		  "Merge neighbouring segments when the joint fit's largest residual is below this; at least "
		  "break_noise_sigmas x the scan's stdError [m]",
		  Range::above(0, 1));
		v("min_points", minPoints, "Fewest laser points per vector", Range::closed(2, 1000));
		v("min_length", minLength, "Shortest vector [m]", Range::closed(0, 100));
		v("max_point_gap", maxPointGap, "Largest gap between consecutive points of one vector [m]",
		  Range::above(0, 10));
		v("break_noise_sigmas", breakNoiseSigmas,
		  "Range noise allowance in scanner std. devs (stdError) of the breakpoint (Borges & Aldon: 3; 0: geometry "
		  "only), split, merge and hit band",
		  Range::closed(0, 10));
	}
};

/** Sec. 3.1, Eq. 2: the slender grid carried by each vector. */
struct GridOptions
{
	double resolution = 0.10;
	int halfWidth = 1;
	double priorOccupy = 0.5;
	double priorVisit = 1.0;

	template <class V>
	void visit(V&& v)
	{
		v("resolution", resolution, "Cell size of every vector's grid [m]", Range::above(0, 1));
		v("half_width", halfWidth, "Cells on each side of the vector's own row (width 2 half_width + 1)",
		  Range::closed(0, 20));
		v("prior_occupy", priorOccupy, "Prior n_occupy of a cell (Sec. 3.1: 1/2); at most prior_visit",
		  Range::closed(0, 100));
		v("prior_visit", priorVisit, "Prior n_visit of a cell (Sec. 3.1: 1)", Range::above(0, 100));
	}
};

/** Sec. 3.2: global map update (Eq. 8 wipe triangles) and correspondence/merging. */
struct MapOptions
{
	double hitBand = 0.05;
	double maxDirectionDiffDeg = 10.0;
	double maxThetaDiffDeg = 10.0;
	double maxRhoDiff = 0.15;
	bool mergeOnInsert = true;
	bool mergeHoldsWall = true;

	template <class V>
	void visit(V&& v)
	{
		v("hit_band", hitBand,
		  "Eq. 8 part c: cells within this of the new vector count as hits; at least the scan's range noise "
		  "allowance (extraction.break_noise_sigmas x its stdError) [m]",
		  Range::above(0, 1));
		v("max_direction_diff_deg", maxDirectionDiffDeg,
		  "Correspondence criterion 1: largest difference of directions psi [deg]", Range::closed(0, 180));
		v("max_theta_diff_deg", maxThetaDiffDeg,
		  "Correspondence criterion 2: largest difference of line normals theta [deg]", Range::closed(0, 180));
		v("max_rho_diff", maxRhoDiff,
		  "Correspondence criterion 2: largest difference of line offsets rho, measured from the pair's midpoint [m]",
		  Range::closed(0, 10));
		v("merge_on_insert", mergeOnInsert, "Merge corresponding vectors (Algorithm 2) as scans are inserted",
		  Range::boolean());
		v("merge_holds_wall", mergeHoldsWall,
		  "Beyond the paper: refuse a merge whose new grid would not hold the parts' wall (a bent wall)",
		  Range::boolean());
	}
};

/** Sec. 4.1, Eq. 14-15, Fig. 4: static/dynamic split of each vector. */
struct EStepOptions
{
	double staticThreshold = 0.50;
	double finalStaticThreshold = 0.70;
	double finalRelativeDrop = 0.10;
	double minPieceLength = 0.30;
	bool usePeakRow = true;
	double minVisits = 3.0;
	double freeWeight = 1.0;

	template <class V>
	void visit(V&& v)
	{
		v("static_threshold", staticThreshold,
		  "Eq. 14: a column whose profile p(c_i | M) is at or above this is static", Range::open(0, 1));
		v("final_static_threshold", finalStaticThreshold, "The same for the final map, after EM converged",
		  Range::closed(0, 1));
		v("final_relative_drop", finalRelativeDrop,
		  "Final map: a column this far below its vector's median profile is dynamic too (0: off)",
		  Range::closed(0, 1));
		v("min_piece_length", minPieceLength,
		  "Shortest static/dynamic sub-vector; shorter pieces join their neighbours [m]", Range::closed(0, 100));
		v("use_peak_row", usePeakRow,
		  "Fig. 4 profile of a column: its largest cell probability across the width (false: the mean)",
		  Range::boolean());
		v("free_weight", freeWeight,
		  "Peak-row profile: weight of a beam through a cell against a hit (1: n_occupy / n_visit)",
		  Range::above(0, 100));
		v("min_visits", minVisits,
		  "Peak-row profile: a cell counts from this n_visit on, the prior included (3: two observations)",
		  Range::closed(0, 1000));
	}
};

/** Sec. 4.2 (after Sohn & Kim 2008): vector-matching scan registration. */
struct MatcherOptions
{
	double gatePsiInitialDeg = 20.0;
	double gatePsiFinalDeg = 6.0;
	double gateRhoInitial = 0.60;
	double gateRhoFinal = 0.12;
	double minOverlap = 0.10;
	int minMatches = 2;
	double minMatchedLength = 1.5;
	double maxRms = 0.06;
	double degenerateRatio = 0.1;
	bool stepWithinGates = true;

	template <class V>
	void visit(V&& v)
	{
		v("gate_psi_initial_deg", gatePsiInitialDeg, "Criterion 1 (direction) gate at the first iteration [deg]",
		  Range::above(0, 180));
		v("gate_psi_final_deg", gatePsiFinalDeg, "Criterion 1 gate once tightened; at most gate_psi_initial_deg [deg]",
		  Range::above(0, 180));
		v("gate_rho_initial", gateRhoInitial, "Criterion 2 (line offset) gate at the first iteration [m]",
		  Range::above(0, 10));
		v("gate_rho_final", gateRhoFinal, "Criterion 2 gate once tightened; at most gate_rho_initial [m]",
		  Range::above(0, 10));
		v("min_overlap", minOverlap, "Matched vectors overlap along their line by at least this [m]",
		  Range::closed(0, 100));
		v("min_matches", minMatches, "Fewest matched vector pairs of an accepted registration", Range::closed(1, 1000));
		v("min_matched_length", minMatchedLength,
		  "Fewest metres of overlapping matched vectors of an accepted registration [m]", Range::closed(0, 1000));
		v("max_rms", maxRms, "Largest RMS point-to-line residual of an accepted registration [m]", Range::above(0, 1));
		v("degenerate_ratio", degenerateRatio,
		  "A translation direction with less than this share of the strongest one's information is scaled down "
		  "quadratically",
		  Range::closed(0, 1));
		v("step_within_gates", stepWithinGates,
		  "Beyond the paper: a Gauss-Newton step moves at most the current rho gate and turns at most the psi gate",
		  Range::boolean());
	}
};

/** Sec. 4.2, Eq. 21-22: pose-graph optimisation. */
struct PoseGraphOptions
{
	int maxIterations = 30;
	double robustKernelWidth = 3.0;
	double rejectChi2 = 50.0;
	double odometrySigmaXYPerM = 0.06;
	double odometrySigmaXYMin = 0.02;
	double odometrySigmaPhi = 0.03;
	double odometrySigmaPhiPerM = 0.03;
	int rejectRounds = 3;
	double graduationTrigger = 10.0;
	double graduationStartPhi = 1e4;
	double graduationFactor = 0.01;

	template <class V>
	void visit(V&& v)
	{
		v("max_iterations", maxIterations, "Optimiser iterations per M-step", Range::closed(1, 10000));
		v("robust_kernel_width", robustKernelWidth, "Dynamic covariance scaling Phi of registration edges [chi2]",
		  Range::above(0, 1e6));
		v("reject_chi2", rejectChi2, "Registration edges whose chi2 stays above this after optimising are removed",
		  Range::above(0, 1e9));
		v("odometry_sigma_xy_per_m", odometrySigmaXYPerM,
		  "Eq. 21 odometry edges: translation std. dev. per metre travelled [m/m]", Range::closed(0, 10));
		v("odometry_sigma_xy_min", odometrySigmaXYMin, "... its floor [m]", Range::above(0, 10));
		v("odometry_sigma_phi", odometrySigmaPhi, "... rotation std. dev. per step [rad]", Range::above(0, 10));
		v("odometry_sigma_phi_per_m", odometrySigmaPhiPerM, "... rotation std. dev. per metre travelled [rad/m]",
		  Range::closed(0, 10));
		v("reject_rounds", rejectRounds,
		  "Beyond the paper: chi2 rejection and re-optimisation rounds at most (0: no rejection)",
		  Range::closed(0, 100));
		v("graduation_trigger", graduationTrigger,
		  "Beyond the paper: graduate Phi when the start's chi2 percentile or a loop edge exceeds this x "
		  "robust_kernel_width",
		  Range::above(0, 1e9));
		v("graduation_start_phi", graduationStartPhi, "Beyond the paper: Phi of the first graduation stage [chi2]",
		  Range::above(0, 1e12));
		v("graduation_factor", graduationFactor, "Beyond the paper: Phi x this from one graduation stage to the next",
		  Range::open(0, 1));
	}
};

/** Sec. 4.2-4.3, Eq. 16-25: edges of the pose graph and the EM loop. */
struct MStepOptions
{
	int maxIterations = 10;
	double keyframeDistance = 0.2;
	double keyframeRotationDeg = 5.0;
	int sequentialWindow = 5;
	double overlapDistance = 6.0;
	double overlapMinLength = 2.0;
	double overlapMinShare = 0.25;
	int overlapRunGap = 10;
	double consistencyChi2 = 16.0;
	double minChangedShare = 0.0;
	double passHeadingWeight = 1.0;
	bool overlapMostOverlapping = true;
	bool informationInEdgeFrame = true;
	bool reconsiderRejected = true;
	int reconsiderLimit = 2;
	bool loopSearch = true;
	double loopSearchSigmas = 3.0;
	double loopSearchMaxRadius = 8.0;
	int loopSearchVectors = 10;
	int loopSearchHypotheses = 4;
	double loopSearchMinShare = 0.4;
	double loopSearchAmbiguity = 0.7;
	bool loopSearchWeakLinks = true;
	bool loopSearchAllVectors = true;
	bool overlapReregisterMoved = true;
	bool sequentialOdometryGuess = true;

	template <class V>
	void visit(V&& v)
	{
		v("max_iterations", maxIterations, "EM iterations at most (fewer when no constraint changes)",
		  Range::closed(1, 1000));
		v("keyframe_distance", keyframeDistance,
		  "EM works on scans whose odometry moved this far; the others follow [m]", Range::closed(0, 100));
		v("keyframe_rotation_deg", keyframeRotationDeg, "... or turned this much [deg]", Range::closed(0, 180));
		v("sequential_window", sequentialWindow, "Register each scan against this many predecessors",
		  Range::closed(1, 1000));
		v("overlap_distance", overlapDistance, "Poses closer than this are candidates for an overlap edge [m]",
		  Range::closed(0, 1000));
		v("overlap_min_length", overlapMinLength, "Corresponding static length that makes two scans overlap [m]",
		  Range::closed(0, 1000));
		v("overlap_min_share", overlapMinShare, "Matched share of the shorter scan's static length for an overlap edge",
		  Range::closed(0, 1));
		v("overlap_run_gap", overlapRunGap,
		  "Candidate poses further apart than this many scans belong to different passes", Range::closed(1, 1000000));
		v("consistency_chi2", consistencyChi2,
		  "Two overlap edges support each other when their cycle closes within this chi2", Range::above(0, 1e9));
		v("min_changed_share", minChangedShare, "EM has converged when at most this share of constraints changed",
		  Range::closed(0, 1));
		v("pass_heading_weight", passHeadingWeight,
		  "An earlier pass's candidate pose: nearest in position + this x heading difference [m/rad]",
		  Range::closed(0, 1000));
		v("information_in_edge_frame", informationInEdgeFrame,
		  "Rotate a registration's information into the frame of Eq. 21's error", Range::boolean());
		v("overlap_most_overlapping", overlapMostOverlapping,
		  "Beyond the paper: a pass whose nearest pose shares too little offers its most overlapping poses",
		  Range::boolean());
		v("reconsider_rejected", reconsiderRejected,
		  "Beyond the paper: edges the chi2 test rejected return to the optimiser at the next M-step",
		  Range::boolean());
		v("reconsider_limit", reconsiderLimit,
		  "... until a pair was rejected this many times with the same correspondences (0: no limit)",
		  Range::closed(0, 1000));
		v("loop_search", loopSearch,
		  "Beyond the paper: search loop closures from vector corners in a window growing with the pose uncertainty",
		  Range::boolean());
		v("loop_search_sigmas", loopSearchSigmas,
		  "Loop-search window half-size in odometry-model std. devs of the path between the poses",
		  Range::above(0, 100));
		v("loop_search_max_radius", loopSearchMaxRadius,
		  "Largest loop-search translation window (and candidate distance) [m]", Range::closed(0, 1000));
		v("loop_search_vectors", loopSearchVectors,
		  "Longest static vectors per scan whose corners give loop hypotheses", Range::closed(1, 1000));
		v("loop_search_hypotheses", loopSearchHypotheses, "Best-ranked loop hypotheses refined by the matcher",
		  Range::closed(1, 1000));
		v("loop_search_min_share", loopSearchMinShare,
		  "Matched share of the shorter scan's static length for a loop edge", Range::closed(0, 1));
		v("loop_search_ambiguity", loopSearchAmbiguity,
		  "A distinct solution matching this share of the best's length makes the place ambiguous",
		  Range::closed(0, 1));
		v("loop_search_weak_links", loopSearchWeakLinks,
		  "Also search between passes linked only by degenerate or rejected edges", Range::boolean());
		v("loop_search_all_vectors", loopSearchAllVectors,
		  "Beyond the paper: a loop search that finds nothing on the static vectors searches all vectors",
		  Range::boolean());
		v("overlap_reregister_moved", overlapReregisterMoved,
		  "Beyond the paper: an overlap registration that moved beyond the initial gates is redone from the estimate "
		  "optimised without it",
		  Range::boolean());
		v("sequential_odometry_guess", sequentialOdometryGuess,
		  "Beyond the paper, first M-step: a sequential pair that failed from the chained guess is tried from the "
		  "odometry",
		  Range::boolean());
	}
};

/** Eq. 6-7: conversion of the grid vector map to an occupancy grid. */
struct OccupancyOptions
{
	double resolution = 0.10;
	double margin = 0.5;
	int samplesPerAxis = 0;
	bool maxPooling = true;

	template <class V>
	void visit(V&& v)
	{
		v("resolution", resolution, "Cell size of the occupancy grid made by Eq. 6 [m]", Range::above(0, 10));
		v("margin", margin, "Border around the vectors' bounding box [m]", Range::closed(0, 100));
		v("samples_per_axis", samplesPerAxis, "Eq. 6 sample points per axis of an output cell (0: one per vector cell)",
		  Range::closed(0, 16));
		v("max_pooling", maxPooling,
		  "An output cell takes its samples' largest Eq. 6 occupancy (false: the area average)", Range::boolean());
	}
};

/** Sec. 5.4: door detection from static/dynamic corners. */
struct DoorOptions
{
	double maxCornerGap = 0.30;
	double minCornerAngleDeg = 10.0;
	double maxVertexDistance = 0.25;
	double maxLengthDiff = 0.25;
	double minDoorLength = 0.6;
	double maxDoorLength = 1.4;
	double minStateDiffDeg = 10.0;
	bool duringEm = false;

	template <class V>
	void visit(V&& v)
	{
		v("max_corner_gap", maxCornerGap,
		  "A static and a dynamic vector form a corner when an end of each is this close [m]", Range::closed(0, 10));
		v("min_corner_angle_deg", minCornerAngleDeg, "... and their directions differ by at least this [deg]",
		  Range::closed(0, 180));
		v("max_vertex_distance", maxVertexDistance, "Corners whose vertices are closer than this share a hinge [m]",
		  Range::closed(0, 10));
		v("max_length_diff", maxLengthDiff, "Door leaves whose lengths differ by less than this are one door [m]",
		  Range::closed(0, 10));
		v("min_door_length", minDoorLength, "Shortest door leaf [m]", Range::above(0, 10));
		v("max_door_length", maxDoorLength, "Longest door leaf; at least min_door_length [m]", Range::above(0, 10));
		v("min_state_diff_deg", minStateDiffDeg, "Two door states (leaf angles) differ by at least this [deg]",
		  Range::closed(0, 180));
		v("during_em", duringEm, "Sec. 5.3: detect doors after each E-step and keep their states out of later M-steps",
		  Range::boolean());
	}
};

/** Beyond the paper: CGridVectorMap as the reference map of MRPT's ICP
 * (determineMatching2D and friends; see StaticFootPoints). */
struct MatchingOptions
{
	double staticThreshold = 0.0;

	template <class V>
	void visit(V&& v)
	{
		v("static_threshold", staticThreshold,
		  "Beyond the paper, ICP against the map: only columns whose Fig. 4 profile is at least this take part (0: "
		  "every column of non-dynamic vectors)",
		  Range::closed(0, 1));
	}
};

/** All parameters of gridvector. Sections in an .ini file are named
 * `<prefix>_<group>`: e.g. [gridvector_extraction], [gridvector_grid]. */
struct GridVectorConfig
{
	ExtractionOptions extraction;
	GridOptions grid;
	MapOptions map;
	EStepOptions estep;
	MatcherOptions matcher;
	PoseGraphOptions posegraph;
	MStepOptions mstep;
	DoorOptions doors;
	OccupancyOptions occupancy;
	MatchingOptions matching;

	template <class V>
	void visitGroups(V&& v)
	{
		v("extraction", extraction);
		v("grid", grid);
		v("map", map);
		v("estep", estep);
		v("matcher", matcher);
		v("posegraph", posegraph);
		v("mstep", mstep);
		v("doors", doors);
		v("occupancy", occupancy);
		v("matching", matching);
	}

	/** Reads every `<prefix>_<group>` section present. Throws std::runtime_error
	 * naming `sourceName` and the key if a section holds a key this version
	 * does not know (a typo must not silently fall back to a default), and naming
	 * the section if a `<prefix>_...` section is neither a group nor one of
	 * `otherSections` (read by the caller, e.g. a map's "likelihoodOpts"). */
	void loadFromConfigFile(const mrpt::config::CConfigFileBase& cfg, const std::string& prefix = "gridvector",
							const std::string& sourceName = "config",
							const std::vector<std::string>& otherSections = {});
	/** Loads an .ini file; throws std::runtime_error("FILE: problem"), also "FILE:LINE: problem"
	 * for a key outside any section or a section header without its ']'. */
	void loadFromFile(const std::string& iniPath, const std::string& prefix = "gridvector");
	/** Writes all sections as a valid .ini file. */
	void dumpAsIni(std::ostream& out, const std::string& prefix = "gridvector") const;
	/** Markdown table of every parameter (section, key, default, range, meaning). */
	static std::string parameterTableMarkdown(const std::string& prefix = "gridvector");
	/** Throws std::invalid_argument "[<prefix>_group] key = 'value' must be ..." for the first value outside
	 * its visit() range, not finite, or a minimum above its maximum. */
	void validate(const std::string& prefix = "gridvector") const;

	// --- by-name access (the .gvmap config record, report.json) ---
	/** Every key as "group.key" with its value (ints and bools as 0/1), in visit() order. */
	std::vector<std::pair<std::string, double>> namedValues() const;
	/** Sets "group.key" (e.g. "grid.resolution"). Returns false if this version has no such key;
	 * throws std::invalid_argument if the value does not fit the key's type (int, bool). */
	bool setNamedValue(const std::string& name, double value);
	/** {"extraction": {"min_range": 0.02, ...}, ...}: every key, bools as true/false, a non-finite value
	 * (set in code; an .ini cannot give one) as null: always valid JSON. */
	std::string toJson() const;
	/** The same with every key's value, range and help: {"grid": {"resolution": {"value": 0.1,
	 * "range": "(0, 1]", "help": "Cell size of every vector's grid [m]"}, ...}, ...} (gv-config --json). */
	std::string parametersJson() const;
};

}  // namespace gridvector
