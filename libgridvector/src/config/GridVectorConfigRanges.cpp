// GridVectorConfig::validate: the valid range of every key, checked where a configuration is loaded.
#include <gridvector/GridVectorConfig.h>
#include "io/TextParsing.h"

#include <cmath>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace gridvector
{
namespace
{
template <class T>
std::string valueText(T v)
{
	if constexpr (std::is_same_v<T, bool>) return v ? "true" : "false";
	else if constexpr (std::is_floating_point_v<T>) return io::shortestText(v);
	else return std::to_string(v);
}

/** The keys of one group: each check throws std::invalid_argument
 * "[<prefix>_<group>] key = 'value' must be ..." when the value is out of its range. */
class Ranges
{
   public:
	Ranges(const std::string& prefix, const char* group) : section_(prefix + "_" + group) {}

	template <class T>
	void require(const char* key, T value, bool ok, const std::string& why) const
	{
		if (!ok) throw std::invalid_argument("[" + section_ + "] " + key + " = '" + valueText(value) + "' " + why);
	}
	template <class T>
	void atLeast(const char* key, T value, T lo) const
	{
		require(key, value, value >= lo, "must be >= " + valueText(lo));
	}
	template <class T>
	void above(const char* key, T value, T lo) const
	{
		require(key, value, value > lo, "must be > " + valueText(lo));
	}
	template <class T>
	void within(const char* key, T value, T lo, T hi) const
	{
		require(key, value, value >= lo && value <= hi, "must be in [" + valueText(lo) + ", " + valueText(hi) + "]");
	}
	/** A share or probability: in [0, 1]. */
	void share(const char* key, double value) const { within(key, value, 0.0, 1.0); }
	/** An angle between directions [deg]: in [0, 180]. */
	void degrees(const char* key, double value) const { within(key, value, 0.0, 180.0); }
	/** `value` of `key` must not be below `lo`, the value of `loKey` (a minimum above its maximum). */
	template <class T>
	void notBelow(const char* key, T value, const char* loKey, T lo) const
	{
		require(key, value, value >= lo, std::string("must be >= ") + loKey + " (" + valueText(lo) + ")");
	}

   private:
	std::string section_;
};

// Sec. 3.1 (Borges & Aldon 2004).
void extractionRanges(const ExtractionOptions& e, const std::string& prefix)
{
	const Ranges r(prefix, "extraction");
	r.atLeast("min_range", e.minRange, 0.0);
	r.atLeast("max_range_margin", e.maxRangeMargin, 0.0);
	r.above("break_distance", e.breakDistance, 0.0);
	r.require("break_angle_deg", e.breakAngleDeg, e.breakAngleDeg > 0 && e.breakAngleDeg < 90, "must be in (0, 90)");
	r.above("split_threshold", e.splitThreshold, 0.0);
	r.above("merge_threshold", e.mergeThreshold, 0.0);
	r.atLeast("min_points", e.minPoints, 2);
	r.atLeast("min_length", e.minLength, 0.0);
	r.above("max_point_gap", e.maxPointGap, 0.0);
	r.atLeast("break_noise_sigmas", e.breakNoiseSigmas, 0.0);
}

// Sec. 3.1, Eq. 2 and the counting model's prior.
void gridRanges(const GridOptions& g, const std::string& prefix)
{
	const Ranges r(prefix, "grid");
	r.above("resolution", g.resolution, 0.0);
	r.within("half_width", g.halfWidth, 0, 20);
	r.above("prior_visit", g.priorVisit, 0.0);
	r.atLeast("prior_occupy", g.priorOccupy, 0.0);
	r.require("prior_occupy", g.priorOccupy, g.priorOccupy <= g.priorVisit,
			  "must be <= prior_visit (" + valueText(g.priorVisit) + ")");
}

// Sec. 3.2: Eq. 8 and the correspondence criteria.
void mapRanges(const MapOptions& m, const std::string& prefix)
{
	const Ranges r(prefix, "map");
	r.above("hit_band", m.hitBand, 0.0);
	r.degrees("max_direction_diff_deg", m.maxDirectionDiffDeg);
	r.degrees("max_theta_diff_deg", m.maxThetaDiffDeg);
	r.atLeast("max_rho_diff", m.maxRhoDiff, 0.0);
	r.above("index_cell_size", m.indexCellSize, 0.0);
	r.atLeast("merge_regrid_tolerance", m.mergeRegridTolerance, 0.0);
	r.atLeast("merge_cascade_rounds", m.mergeCascadeRounds, 1);
	r.atLeast("merge_group_rounds", m.mergeGroupRounds, 1);
}

// Sec. 4.1, Eq. 14, Fig. 4.
void estepRanges(const EStepOptions& e, const std::string& prefix)
{
	const Ranges r(prefix, "estep");
	r.require("static_threshold", e.staticThreshold, e.staticThreshold > 0 && e.staticThreshold < 1, "must be in (0, 1)");
	r.share("final_static_threshold", e.finalStaticThreshold);
	r.share("final_relative_drop", e.finalRelativeDrop);
	r.atLeast("min_piece_length", e.minPieceLength, 0.0);
	r.atLeast("min_visits", e.minVisits, 0.0);
	r.above("free_weight", e.freeWeight, 0.0);
	r.share("hysteresis", e.hysteresis);
	r.atLeast("rerun_translation", e.rerunTranslation, 0.0);
	r.degrees("rerun_rotation_deg", e.rerunRotationDeg);
}

// Sec. 4.2 (Sohn & Kim 2008): the gates tighten from the initial to the final values.
void matcherRanges(const MatcherOptions& m, const std::string& prefix)
{
	const Ranges r(prefix, "matcher");
	r.atLeast("max_iterations", m.maxIterations, 1);
	r.require("gate_psi_initial_deg", m.gatePsiInitialDeg, m.gatePsiInitialDeg > 0 && m.gatePsiInitialDeg <= 180,
			  "must be in (0, 180]");
	r.above("gate_psi_final_deg", m.gatePsiFinalDeg, 0.0);
	r.require("gate_psi_final_deg", m.gatePsiFinalDeg, m.gatePsiFinalDeg <= m.gatePsiInitialDeg,
			  "must be <= gate_psi_initial_deg (" + valueText(m.gatePsiInitialDeg) + ")");
	r.above("gate_rho_initial", m.gateRhoInitial, 0.0);
	r.above("gate_rho_final", m.gateRhoFinal, 0.0);
	r.require("gate_rho_final", m.gateRhoFinal, m.gateRhoFinal <= m.gateRhoInitial,
			  "must be <= gate_rho_initial (" + valueText(m.gateRhoInitial) + ")");
	r.within("gate_shrink", m.gateShrink, MatcherOptions::kMinGateShrink, 1.0);
	r.atLeast("min_overlap", m.minOverlap, 0.0);
	r.atLeast("min_matches", m.minMatches, 1);
	r.atLeast("min_matched_length", m.minMatchedLength, 0.0);
	r.above("max_rms", m.maxRms, 0.0);
	r.share("degenerate_ratio", m.degenerateRatio);
	r.above("sigma_floor", m.sigmaFloor, 0.0);
	r.atLeast("convergence_translation", m.convergenceTranslation, 0.0);
	r.atLeast("convergence_rotation", m.convergenceRotation, 0.0);
	r.above("robust_scale_gate_share", m.robustScaleGateShare, 0.0);
}

// Eq. 21-22: the odometry model's standard deviations and the optimiser.
void posegraphRanges(const PoseGraphOptions& p, const std::string& prefix)
{
	const Ranges r(prefix, "posegraph");
	r.atLeast("max_iterations", p.maxIterations, 1);
	r.above("robust_kernel_width", p.robustKernelWidth, 0.0);
	r.above("reject_chi2", p.rejectChi2, 0.0);
	r.atLeast("odometry_sigma_xy_per_m", p.odometrySigmaXYPerM, 0.0);
	r.above("odometry_sigma_xy_min", p.odometrySigmaXYMin, 0.0);  // the information of a standstill is finite
	r.above("odometry_sigma_phi", p.odometrySigmaPhi, 0.0);
	r.atLeast("odometry_sigma_phi_per_m", p.odometrySigmaPhiPerM, 0.0);
	r.atLeast("reject_rounds", p.rejectRounds, 0);
	r.atLeast("tolerance", p.tolerance, 0.0);
	r.above("graduation_trigger", p.graduationTrigger, 0.0);
	r.within("graduation_percentile", p.graduationPercentile, 0.0, 100.0);
	r.above("graduation_start_phi", p.graduationStartPhi, 0.0);
	r.require("graduation_factor", p.graduationFactor, p.graduationFactor > 0 && p.graduationFactor < 1, "must be in (0, 1)");
	r.atLeast("graduation_iterations", p.graduationIterations, 1);
	r.atLeast("graduation_tolerance", p.graduationTolerance, 0.0);
	r.above("lm_min_lambda", p.lmMinLambda, 0.0);
	r.notBelow("lm_initial_lambda", p.lmInitialLambda, "lm_min_lambda", p.lmMinLambda);
	r.require("lm_max_lambda", p.lmMaxLambda, p.lmMaxLambda > p.lmInitialLambda,
			  "must be > lm_initial_lambda (" + valueText(p.lmInitialLambda) + ")");
	r.atLeast("correlated_group_gap", p.correlatedGroupGap, 0);
	r.share("correlated_group_rho", p.correlatedGroupRho);
}

// Sec. 4.2-4.3: the EM loop, the edges and their selection (Eq. 24-25).
void mstepEdgeRanges(const MStepOptions& m, const Ranges& r)
{
	r.atLeast("max_iterations", m.maxIterations, 1);
	r.atLeast("keyframe_distance", m.keyframeDistance, 0.0);
	r.degrees("keyframe_rotation_deg", m.keyframeRotationDeg);
	r.atLeast("sequential_window", m.sequentialWindow, 1);
	r.atLeast("overlap_distance", m.overlapDistance, 0.0);
	r.atLeast("overlap_min_length", m.overlapMinLength, 0.0);
	r.share("overlap_min_share", m.overlapMinShare);
	r.atLeast("overlap_run_gap", m.overlapRunGap, 1);
	r.above("consistency_chi2", m.consistencyChi2, 0.0);
	r.atLeast("recheck_gate_factor", m.recheckGateFactor, 1.0);  // widened, not narrowed, gates
	r.share("min_changed_share", m.minChangedShare);
	r.atLeast("pass_heading_weight", m.passHeadingWeight, 0.0);
	r.atLeast("reconsider_limit", m.reconsiderLimit, 0);
	r.atLeast("reconsider_free_steps", m.reconsiderFreeSteps, 0);
	r.above("drop_distance_factor", m.dropDistanceFactor, 0.0);
	r.atLeast("drop_length_share", m.dropLengthShare, 0.0);
	r.atLeast("changed_translation", m.changedTranslation, 0.0);
	r.atLeast("changed_rotation", m.changedRotation, 0.0);
	r.atLeast("moved_gate_share", m.movedGateShare, 0.0);
	r.atLeast("searched_near_distance", m.searchedNearDistance, 0.0);
	r.degrees("searched_near_deg", m.searchedNearDeg);
	r.within("register_min_incidence_deg", m.registerMinIncidenceDeg, 0.0, 90.0);  // an incidence is at most 90 deg
	r.above("consistency_info_xy", m.consistencyInfoXY, 0.0);
	r.above("consistency_info_phi", m.consistencyInfoPhi, 0.0);
	r.atLeast("consistency_chain_var_xy", m.consistencyChainVarXY, 0.0);
	r.atLeast("consistency_chain_var_phi", m.consistencyChainVarPhi, 0.0);
	r.atLeast("strong_min_correspondences", m.strongMinCorrespondences, 0);
	r.share("strong_min_share", m.strongMinShare);
	r.share("strong_min_degeneracy", m.strongMinDegeneracy);
}

// The loop search (beyond the paper): its window, hypotheses and acceptance.
void mstepLoopRanges(const MStepOptions& m, const Ranges& r)
{
	r.above("loop_search_sigmas", m.loopSearchSigmas, 0.0);
	r.atLeast("loop_search_max_radius", m.loopSearchMaxRadius, 0.0);
	r.atLeast("loop_search_vectors", m.loopSearchVectors, 1);
	r.atLeast("loop_search_hypotheses", m.loopSearchHypotheses, 1);
	r.share("loop_search_min_share", m.loopSearchMinShare);
	r.share("loop_search_ambiguity", m.loopSearchAmbiguity);
	r.atLeast("loop_search_distinct", m.loopSearchDistinct, 0.0);
	r.atLeast("loop_search_candidate_spacing", m.loopSearchCandidateSpacing, 0.0);
	r.atLeast("loop_window_min_translation", m.loopWindowMinTranslation, 0.0);
	r.require("loop_window_min_translation", m.loopWindowMinTranslation,
			  m.loopWindowMinTranslation <= m.loopSearchMaxRadius,
			  "must be <= loop_search_max_radius (" + valueText(m.loopSearchMaxRadius) + ")");
	r.degrees("loop_window_min_rotation_deg", m.loopWindowMinRotationDeg);
	r.atLeast("loop_corner_min_length", m.loopCornerMinLength, 0.0);
	r.within("loop_corner_min_angle_deg", m.loopCornerMinAngleDeg, 0.0, 90.0);
	r.atLeast("loop_corner_max_gap", m.loopCornerMaxGap, 0.0);
	r.degrees("loop_corner_turn_tolerance_deg", m.loopCornerTurnToleranceDeg);
	r.atLeast("loop_duplicate_distance", m.loopDuplicateDistance, 0.0);
	r.degrees("loop_duplicate_deg", m.loopDuplicateDeg);
	r.above("loop_score_gate_factor", m.loopScoreGateFactor, 0.0);
	r.degrees("loop_distinct_deg", m.loopDistinctDeg);
}

// Sec. 5.4: door leaves and their states.
void doorRanges(const DoorOptions& d, const std::string& prefix)
{
	const Ranges r(prefix, "doors");
	r.atLeast("max_corner_gap", d.maxCornerGap, 0.0);
	r.degrees("min_corner_angle_deg", d.minCornerAngleDeg);
	r.atLeast("max_vertex_distance", d.maxVertexDistance, 0.0);
	r.atLeast("max_length_diff", d.maxLengthDiff, 0.0);
	r.above("min_door_length", d.minDoorLength, 0.0);
	r.notBelow("max_door_length", d.maxDoorLength, "min_door_length", d.minDoorLength);
	r.degrees("min_state_diff_deg", d.minStateDiffDeg);
	r.atLeast("max_tee_offset", d.maxTeeOffset, 0.0);
	r.within("min_sweep_deg", d.minSweepDeg, 0.0, 360.0);
	r.atLeast("leaf_chain_gap", d.leafChainGap, 0.0);
	r.degrees("leaf_chain_max_turn_deg", d.leafChainMaxTurnDeg);
	r.within("min_open_deg", d.minOpenDeg, 0.0, 90.0);
}

// Eq. 6-7: the occupancy grid made from the vectors.
void occupancyRanges(const OccupancyOptions& o, const std::string& prefix)
{
	const Ranges r(prefix, "occupancy");
	r.above("resolution", o.resolution, 0.0);
	r.atLeast("margin", o.margin, 0.0);
	r.within("samples_per_axis", o.samplesPerAxis, 0, 16);
}

// Beyond the paper: the map as MRPT's ICP reference.
void matchingRanges(const MatchingOptions& m, const std::string& prefix)
{
	const Ranges r(prefix, "matching");
	r.share("static_threshold", m.staticThreshold);
}
}  // namespace

void GridVectorConfig::validate(const std::string& prefix) const
{
	// every floating-point key finite: the .ini reader refuses nan/inf, code that sets a key may not
	const_cast<GridVectorConfig&>(*this).visitGroups([&](const char* group, auto& g) {
		const Ranges r(prefix, group);
		g.visit([&](const char* key, auto& field, const char*) {
			if constexpr (std::is_floating_point_v<std::decay_t<decltype(field)>>)
				r.require(key, field, std::isfinite(field), "must be finite");
		});
	});
	extractionRanges(extraction, prefix);
	gridRanges(grid, prefix);
	mapRanges(map, prefix);
	estepRanges(estep, prefix);
	matcherRanges(matcher, prefix);
	posegraphRanges(posegraph, prefix);
	const Ranges m(prefix, "mstep");
	mstepEdgeRanges(mstep, m);
	mstepLoopRanges(mstep, m);
	doorRanges(doors, prefix);
	occupancyRanges(occupancy, prefix);
	matchingRanges(matching, prefix);
}

}  // namespace gridvector
