// gridvector: every tunable parameter of the system, with the paper's defaults.
//
// Each group is a plain struct with a visit() that lists its keys once; loading
// from MRPT .ini files, dumping, rejecting unknown keys and generating the
// parameter table in doc/parameters.md all walk that one list.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <cmath>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

namespace gridvector
{
/** Sec. 3.1: split-and-merge line extraction (Borges & Aldon 2004). */
struct ExtractionOptions
{
	double minRange = 0.02;  //!< readings <= this are invalid [m]
	double maxRangeMargin = 0.01;  //!< readings >= maxRange - margin are "no hit" [m]
	double breakDistance = 0.20;  //!< absolute jump between neighbours that breaks a segment [m]
	double breakAngleDeg = 10.0;  //!< adaptive breakpoint: min incidence angle (Borges & Aldon) [deg]
	double splitThreshold = 0.04;  //!< max point-to-line distance before splitting [m]
	double mergeThreshold = 0.04;  //!< max residual for merging neighbouring segments [m]
	int minPoints = 5;  //!< minimum laser points per vector
	double minLength = 0.30;  //!< minimum vector length [m]
	double maxPointGap = 0.50;  //!< max gap between consecutive points of one vector [m]
	double breakNoiseSigmas = 3.0;  //!< adaptive breakpoint: range noise allowance in scanner std. devs (Borges & Aldon: 3)

	template <class V>
	void visit(V&& v)
	{
		v("min_range", minRange, "Readings at or below this range are invalid [m]");
		v("max_range_margin", maxRangeMargin, "Readings within this of the scanner's maxRange are 'no hit' [m]");
		v("break_distance", breakDistance, "Absolute range-jump threshold between neighbouring points [m]");
		v("break_angle_deg", breakAngleDeg, "Adaptive breakpoint: smallest incidence angle of a surface [deg]");
		v("split_threshold", splitThreshold, "Split a segment where a point lies further than this from its line [m]");
		v("merge_threshold", mergeThreshold, "Merge neighbouring collinear segments when the joint fit's max residual is below this [m]");
		v("min_points", minPoints, "Minimum laser points per vector");
		v("min_length", minLength, "Minimum vector length [m]");
		v("max_point_gap", maxPointGap, "Largest gap between consecutive points inside one vector; caps the adaptive breakpoint [m]");
		v("break_noise_sigmas", breakNoiseSigmas, "Adaptive breakpoint (Borges & Aldon 2004, the extraction Sec. 3.1 cites): the distance threshold adds this many times the scanner's range std. dev. (their 3 sigma_r; the paper gives no value); 0: geometry only");
	}
};

/** Sec. 3.1, Eq. 2: the slender grid carried by each vector. */
struct GridOptions
{
	double resolution = 0.10;  //!< cell size [m] (Table 1 compares with a 10 cm grid)
	int halfWidth = 1;  //!< cells on each side of the vector's own row
	double priorOccupy = 0.5;  //!< prior n_occupy (Sec. 3.1: 1/2)
	double priorVisit = 1.0;  //!< prior n_visit (Sec. 3.1: 1)

	template <class V>
	void visit(V&& v)
	{
		v("resolution", resolution, "Cell size of every vector's grid [m]");
		v("half_width", halfWidth, "Cells on each side of the vector's own row (width = 2*half_width+1)");
		v("prior_occupy", priorOccupy, "Prior n_occupy of a cell (paper: 1/2)");
		v("prior_visit", priorVisit, "Prior n_visit of a cell (paper: 1)");
	}
};

/** Sec. 3.2: global map update (Eq. 8 wipe triangles) and correspondence/merging. */
struct MapOptions
{
	double hitBand = 0.05;  //!< part c: cells whose centre is within this of the new vector count as hits [m]
	double maxDirectionDiffDeg = 10.0;  //!< criterion 1: |psi_a - psi_b| [deg]
	double maxThetaDiffDeg = 10.0;  //!< criterion 2: |theta_a - theta_b| [deg]
	double maxRhoDiff = 0.15;  //!< criterion 2: |rho_a - rho_b| [m]
	double indexCellSize = 2.0;  //!< spatial index bucket size [m]
	bool mergeOnInsert = true;  //!< merge corresponding vectors (Algorithm 2) when inserting
	bool wipeCountsBeams = true;  //!< Eq. 8 increments count the fan's beams through a cell (false: 1 per cell per triangle)
	double mergeRegridTolerance = 0.005;  //!< Algorithm 2 line 20 keeps the reference's grid when the new vector lies within this of it [m]
	bool wipeVectorlessBeams = false;  //!< beyond the paper: beams that made no vector also update the map (BeamWipe)
	bool mergeHoldsWall = true;  //!< refuse a merge whose new grid would not hold the parts' wall (beyond the paper; VectorMerger::tryMerge)
	int mergeCascadeRounds = 8;  //!< Algorithm 2 repeated with the merged vector at most this often per insertion (beyond the paper)
	int mergeGroupRounds = 16;  //!< mergeAll (Eq. 4): a group absorbs the groups its span corresponds to at most this often (beyond the paper)

	template <class V>
	void visit(V&& v)
	{
		v("hit_band", hitBand, "Eq. 8 part c: cells whose centre lies within this distance of the new vector (and in its beams' cone) get n_occupy and n_visit; half a cell = the cells the vector passes through [m]");
		v("max_direction_diff_deg", maxDirectionDiffDeg, "Correspondence criterion 1: max difference of directions psi [deg]");
		v("max_theta_diff_deg", maxThetaDiffDeg, "Correspondence criterion 2: max difference of line normals theta [deg]; theta is the normal of the directed vector (psi - pi/2), so this repeats criterion 1 and decides only when below max_direction_diff_deg");
		v("max_rho_diff", maxRhoDiff, "Correspondence criterion 2: max difference of line distances rho [m]; both rho are measured from the midpoint of the two vectors' centres, not from the world origin as Eq. 3's (from there a small angle difference becomes a large rho difference far from the origin)");
		v("index_cell_size", indexCellSize, "Bucket size of the spatial index over vectors [m]");
		v("merge_on_insert", mergeOnInsert, "Merge corresponding vectors (Algorithm 2) as scans are inserted");
		v("merge_regrid_tolerance", mergeRegridTolerance, "Algorithm 2, line 20: when the merged vector starts within this distance of the reference part's start and its line stays within it along the reference, the new grid is the reference's grid (extended at the end), so the reference's cells are kept as they are and only the other parts are moved; the merged vector then lies on the reference's axis instead of the fitted line of line 18 (at most this far from it); 0: always build a new grid on the fitted line (the paper's line 19) [m]");
		v("wipe_vectorless_beams", wipeVectorlessBeams, "Beyond the paper (Eq. 8 updates cells only through the wipe triangles of extracted vectors): beams that made no vector (ending in clutter or without a return) add n_visit to the map vectors' cells they cross and, when they end inside one, n_occupy + n_visit to that cell; sequential insertion with the scan's beams only (GlobalMap::insertScan with ScanBeams), not the batch path of the EM loop");
		v("merge_holds_wall", mergeHoldsWall, "Algorithm 2 guard, beyond the paper: a merge is refused when at some column the occupancy-weighted mean of the parts' points lies outside the new grid's band ((half_width + 1/2) x resolution) around the fitted line, so a curved or bent wall is not straightened into one chord whose grid would clamp the wall's counts into its border rows; false: every corresponding set is merged (the paper's Algorithm 2)");
		v("wipe_counts_beams", wipeCountsBeams, "Eq. 8: a wipe increment counts the beams of the triangle's fan crossing the cell, the unit of Algorithm 1 (false: 1 per cell per scan, the paper's Fig. 2)");
		v("merge_cascade_rounds", mergeCascadeRounds, "Beyond the paper (Algorithm 2 merges once; a merged vector may correspond to further map vectors): sequential insertion merges the merged vector again while it finds correspondents, at most this many merges per inserted vector (a bound on one insertion's work); 1: the paper's single merge");
		v("merge_group_rounds", mergeGroupRounds, "Beyond the paper: the batch merge (Eq. 4, GlobalMap::mergeAll) grows a group by the earlier groups its span corresponds to (Sec. 3.2 criteria), repeated with the grown span at most this many times; 1: direct correspondents only");
	}
};

/** Sec. 4.1, Eq. 14-15, Fig. 4: static/dynamic split of each vector. */
struct EStepOptions
{
	double staticThreshold = 0.50;  //!< profile value at or above which a piece is static
	double finalStaticThreshold = 0.70;  //!< the same for the final map, after EM converged
	double finalRelativeDrop = 0.10;  //!< final map: columns this far below their vector's median are dynamic too
	double minPieceLength = 0.30;  //!< smallest sub-vector kept by the split-and-merge [m]
	bool usePeakRow = true;  //!< profile = largest cell probability across the width (false: the mean)
	double minVisits = 3.0;  //!< peak-row profile: a cell counts from this n_visit on, the prior's grid.prior_visit included (3: two observations)
	double freeWeight = 1.0;  //!< peak-row profile: weight of a free observation against an occupied one (1: n_occupy/n_visit)
	double hysteresis = 0.0;  //!< beyond the paper: a column changes state only when it crosses the threshold by this (0: off)
	double rerunTranslation = 0.05;  //!< the E-step is re-run only if a pose moved more than this [m]
	double rerunRotationDeg = 1.0;  //!< ... or turned more than this [deg]

	template <class V>
	void visit(V&& v)
	{
		v("static_threshold", staticThreshold, "Beyond the paper (CGridVectorMap::determineMatching2D, MRPT's ICP against the map): a scan point corresponds to the nearest point of the vectors' stretches whose columns the E-step's occupancy profile (Fig. 4, estep.use_peak_row / min_visits / free_weight) puts at or above this, on vectors not classified dynamic (Eq. 14: a gv-em-slam map's dynamic children are out at any value); 0 (default): every column of those vectors; 0.5 (the E-step's split) keeps the stretches scans saw through out of a map built without an E-step, which aligned more scans on the simulated office (seeds 1-3) but far fewer on long-corridor (doc/benchmarks.md, ICP against a grid-vector map)");
		v("final_static_threshold", finalStaticThreshold, "Final map only (after EM): static children are split again at this profile value; a static place is occupied in nearly every observation");
		v("final_relative_drop", finalRelativeDrop, "Final map only: a column whose profile lies this far below the median of its vector is dynamic too (a door closed most of the time in a wall read ~1); 0: off");
		v("min_piece_length", minPieceLength, "Smallest static/dynamic sub-vector; shorter pieces merge into neighbours [m]");
		v("use_peak_row", usePeakRow, "Profile value of a column: the largest cell probability across the width (true) or the mean across the width (false)");
		v("free_weight", freeWeight, "Peak-row profile: a beam through a cell weighs this many hits (1: the counting model's n_occupy/n_visit; >1: what has been seen through is dynamic sooner)");
		v("min_visits", minVisits, "Peak-row profile: a cell counts only if its n_visit reaches this; n_visit includes the counting model's prior (grid.prior_visit, 1 in Sec. 3.1), so the default 3 asks for two observations (beam endpoints or wipe increments) beyond the prior; a column without such a cell stays static");
		v("hysteresis", hysteresis, "Beyond the paper (Sec. 4.1 classifies each E-step from the map alone): from the second E-step on, a column changes state only when its profile crosses the threshold by this margin; 0 (default): off, the paper's E-step; 0.1, the default before session 11, measured: the 7 simulated rows byte-identical, over 6 real logs x mkbench seeds 1-9 better with 0 on 12 runs (by up to 0.0010 m), worse on 6 (up to 0.0005 m), equal on 36 (doc/paper-fidelity.md, finding 10)");
		v("rerun_translation", rerunTranslation, "The E-step is re-evaluated only if some pose moved more than this since the last one [m]");
		v("rerun_rotation_deg", rerunRotationDeg, "... or turned more than this [deg]");
	}
};

/** Sec. 4.2 (after Sohn & Kim 2008): vector-matching scan registration. */
struct MatcherOptions
{
	int maxIterations = 25;  //!< outer iterations (gating + rotation + translation)
	double gatePsiInitialDeg = 20.0;  //!< criterion 1 gate at the first iteration [deg]
	double gatePsiFinalDeg = 6.0;  //!< criterion 1 gate once tightened [deg]
	double gateRhoInitial = 0.60;  //!< criterion 2 gate (line offset) at the first iteration [m]
	double gateRhoFinal = 0.12;  //!< criterion 2 gate once tightened [m]
	double gateShrink = 0.7;  //!< factor applied to the gates per iteration
	static constexpr double kMinGateShrink = 0.05;  //!< gate_shrink's lower bound (validate(); the matcher clamps to it)
	double minOverlap = 0.10;  //!< matched segments must overlap along the line by this [m]
	int minMatches = 2;  //!< fewest matched vector pairs
	double minMatchedLength = 1.5;  //!< fewest metres of overlapping matched vectors [m]
	double maxRms = 0.06;  //!< largest RMS point-to-line residual of an accepted match [m]
	double degenerateRatio = 0.1;  //!< translation information below this share of the strongest direction falls off quadratically
	bool degenerateProjection = false;  //!< below degenerate_ratio: the weak translation direction is marginalised out (rank-2 information)
	double sigmaFloor = 0.03;  //!< smallest residual std. dev. per metre of line used in the information [m]
	double convergenceTranslation = 1e-4;  //!< stop when a step moves less than this [m]
	double convergenceRotation = 1e-5;  //!< ... and turns less than this [rad]
	double robustScaleGateShare = 0.5;  //!< Cauchy scale while iterating = this x the rho gate (>= sigma_floor)
	bool stepWithinGates = false;  //!< a Gauss-Newton step moves at most the current rho gate and turns at most the current psi gate
	bool angleRotationSeeds = false;  //!< the angle-difference rotation step only while the gates tighten; then Gauss-Newton alone to its fixed point

	template <class V>
	void visit(V&& v)
	{
		v("max_iterations", maxIterations, "Iterations of gating, rotation and translation per registration");
		v("gate_psi_initial_deg", gatePsiInitialDeg, "Correspondence criterion 1 (direction) gate at the first iteration [deg]");
		v("gate_psi_final_deg", gatePsiFinalDeg, "Correspondence criterion 1 (direction) gate after tightening [deg]");
		v("gate_rho_initial", gateRhoInitial, "Correspondence criterion 2 (line offset) gate at the first iteration [m]");
		v("gate_rho_final", gateRhoFinal, "Correspondence criterion 2 (line offset) gate after tightening [m]");
		v("gate_shrink", gateShrink, "Factor by which the gates tighten each iteration, in [0.05, 1] (1: the gates stay at their initial values; the matcher treats a smaller factor as 0.05)");
		v("min_overlap", minOverlap, "Matched vectors must overlap along their line by at least this [m]");
		v("min_matches", minMatches, "Fewest matched vector pairs for an accepted registration");
		v("min_matched_length", minMatchedLength, "Fewest metres of overlapping matched vectors for an accepted registration [m]");
		v("max_rms", maxRms, "Largest RMS point-to-line residual of an accepted registration [m]");
		v("degenerate_ratio", degenerateRatio, "A translation direction whose information is below this share of the strongest one is treated as unconstrained (information scaled down quadratically)");
		v("degenerate_projection", degenerateProjection, "Beyond the paper: a registration whose translation degeneracy is below degenerate_ratio (a corridor seen from both ways) keeps exactly what it observes: the weak translation direction is marginalised out of its information (rank 2, counted with 2 degrees of freedom by the pose graph's kernel and chi2 test) instead of scaled down, and the overlap search then accepts such registrations against a pass's other poses too (mstep.overlap_most_overlapping)");
		v("sigma_floor", sigmaFloor, "Smallest residual std. dev. per metre of matched line used for the information matrix [m]");
		v("convergence_translation", convergenceTranslation, "Registration converged when a step moves less than this [m]");
		v("convergence_rotation", convergenceRotation, "Registration converged when a step turns less than this [rad]");
		v("robust_scale_gate_share", robustScaleGateShare, "Beyond the paper (Sec. 4.2 and Sohn & Kim 2008 weight no residuals): while iterating, a point-to-line residual r weighs 1 / (1 + r^2 / c^2) (Cauchy) with c = this x the current line-offset gate, never below sigma_floor; large: least squares over the gated pairs");
		v("step_within_gates", stepWithinGates, "Beyond the paper: each Gauss-Newton step of a registration is scaled down (its direction kept) so that it translates at most the iteration's line-offset gate and turns at most its direction gate (gate_rho_* and gate_psi_*_deg as they shrink), where the correspondences it solves for were gathered: a few nearly parallel pairs whose offsets disagree (a wall and a cabinet front in the wide first gates) otherwise send the estimate metres away from its guess, where the registration fails or locks onto something else (csail seed 4: scans 0 and 48, 0.8 m / 3 deg apart in the first M-step's chain, jumped 12 m); false (default): the full step. On: csail seed 4 0.204 -> 0.034 m, aces 0.0015-0.0024 m worse on seeds 1-6 (doc/benchmarks-history.md, session 7)");
		v("angle_rotation_seeds", angleRotationSeeds, "The rotation step from the weighted angle differences (Sec. 4.2) seeds the registration while the gates tighten, and once they are final (gate_rho_final, gate_psi_final_deg) only the joint Gauss-Newton step on point-to-line distances runs, tested alone for convergence: the two rotation estimates have different fixed points (noisy vector directions against the lever arms of the line offsets), so with both in every iteration (false, the default) a registration alternates between them and runs all max_iterations, ending wherever the last step lands");
	}
};

/** Sec. 4.2, Eq. 21-22: pose-graph optimisation. */
struct PoseGraphOptions
{
	bool useMrptOptimizer = false;  //!< MRPT's optimize_graph_spa_levmarq instead of the built-in robust Gauss-Newton
	int maxIterations = 30;  //!< optimiser iterations per M-step
	double robustKernelWidth = 3.0;  //!< dynamic covariance scaling Phi (chi2 units) for registration edges
	double rejectChi2 = 50.0;  //!< edges still above this chi2 after optimisation are dropped
	double odometrySigmaXYPerM = 0.08;  //!< odometry translation std. dev. per metre travelled
	double odometrySigmaXYMin = 0.02;  //!< odometry translation std. dev. floor [m]
	double odometrySigmaPhi = 0.03;  //!< odometry rotation std. dev. per step [rad]
	double odometrySigmaPhiPerM = 0.03;  //!< odometry rotation std. dev. per metre travelled [rad/m]
	int rejectRounds = 3;  //!< chi2 rejection + re-optimisation rounds at most (beyond the paper)
	double tolerance = 1e-6;  //!< LM stops when the cost changes by less than this share (final stage)
	double graduationTrigger = 10.0;  //!< graduate Phi when the start's chi2 percentile or a loop edge exceeds this x Phi
	double graduationPercentile = 95.0;  //!< ... the percentile of the registration edges' chi2 [%]
	double graduationStartPhi = 1e4;  //!< first Phi of the graduation (chi2 units)
	double graduationFactor = 0.01;  //!< Phi x this per graduation stage
	int graduationIterations = 8;  //!< LM iterations per graduation stage before the last
	double graduationTolerance = 1e-3;  //!< relative cost change ending a graduation stage before the last
	double lmInitialLambda = 1e-4;  //!< LM damping at the start of each stage
	double lmMinLambda = 1e-9;  //!< Nielsen's update never damps below this
	double lmMaxLambda = 1e8;  //!< a stage gives up once rejections raised the damping above this
	int correlatedGroupGap = 0;  //!< overlap/loop edges sharing a scan, other ends this close: one piece of evidence (0: off)
	double correlatedGroupRho = 1.0;  //!< correlation assumed within such a group (1: covariance intersection)

	template <class V>
	void visit(V&& v)
	{
		v("use_mrpt_optimizer", useMrptOptimizer, "Use MRPT's optimize_graph_spa_levmarq (with chi2 edge rejection) instead of the built-in robust Gauss-Newton");
		v("max_iterations", maxIterations, "Optimiser iterations per M-step");
		v("robust_kernel_width", robustKernelWidth, "Dynamic covariance scaling Phi for registration edges (chi2 units)");
		v("reject_chi2", rejectChi2, "Registration edges whose chi2 stays above this after optimisation are removed");
		v("odometry_sigma_xy_per_m", odometrySigmaXYPerM, "Odometry translation std. dev. per metre travelled");
		v("odometry_sigma_xy_min", odometrySigmaXYMin, "Odometry translation std. dev. floor [m]");
		v("odometry_sigma_phi", odometrySigmaPhi, "Odometry rotation std. dev. per step [rad]");
		v("odometry_sigma_phi_per_m", odometrySigmaPhiPerM, "Odometry rotation std. dev. per metre travelled [rad/m]");
		v("reject_rounds", rejectRounds, "Beyond the paper (Eq. 22 has no outlier test): after optimising, registration edges whose chi2 exceeds reject_chi2 are removed and the graph re-optimised, at most this many times; 0: no rejection");
		v("tolerance", tolerance, "Beyond the paper: the built-in Levenberg-Marquardt's last stage (at robust_kernel_width) and each re-optimisation after a rejection stop when a step changes the cost by less than this share of it");
		v("graduation_trigger", graduationTrigger, "Beyond the paper (graduated robustness of the built-in optimiser): Phi starts wide (graduation_start_phi) when the registration edges' chi2 at graduation_percentile, or any loop-search edge's chi2, exceeds this x robust_kernel_width at the start; otherwise the optimiser starts at robust_kernel_width");
		v("graduation_percentile", graduationPercentile, "Beyond the paper: the percentile of the registration edges' chi2 compared with graduation_trigger x robust_kernel_width [%]");
		v("graduation_start_phi", graduationStartPhi, "Beyond the paper: Phi of the first graduation stage (nearly least squares; never below robust_kernel_width) [chi2]");
		v("graduation_factor", graduationFactor, "Beyond the paper: Phi is multiplied by this from one graduation stage to the next, down to robust_kernel_width (0..1)");
		v("graduation_iterations", graduationIterations, "Beyond the paper: Levenberg-Marquardt iterations per graduation stage before the last (the last has max_iterations)");
		v("graduation_tolerance", graduationTolerance, "Beyond the paper: a graduation stage before the last stops when a step changes the cost by less than this share of it");
		v("lm_initial_lambda", lmInitialLambda, "Beyond the paper: Levenberg-Marquardt damping (added to H's diagonal) at the start of every stage");
		v("lm_min_lambda", lmMinLambda, "Beyond the paper: Nielsen's damping update never lowers the damping below this");
		v("lm_max_lambda", lmMaxLambda, "Beyond the paper: a stage ends once rejected steps have raised the damping above this");
		v("correlated_group_gap", correlatedGroupGap, "Beyond the paper (Eq. 22 treats every edge as independent): overlap and loop edges with one end at the same scan whose other ends are at most this many scans apart, one to the next (one pass), share that scan's error; each one's information is divided by the group's size (covariance intersection with equal weights; correlated_group_rho below 1 divides less), so an alias of one scan registered against consecutive poses weighs as one edge; 0: off");
		v("correlated_group_rho", correlatedGroupRho, "Beyond the paper: the correlation assumed between the members of a correlated_group_gap group: a group of n carries the information of n / (1 + (n - 1) rho) independent edges (each member's divided by 1 + (n - 1) rho); 1: covariance intersection (divided by n), 0: independent (0..1)");
	}
};

/** Sec. 4.2-4.3, Eq. 16-25: edges of the pose graph and the EM loop. */
struct MStepOptions
{
	int maxIterations = 10;  //!< EM iterations at most (stops earlier when no constraint changes)
	double keyframeDistance = 0.2;  //!< EM runs on scans this far apart (odometry); the others follow [m]
	double keyframeRotationDeg = 5.0;  //!< ... or turned this much [deg]
	int sequentialWindow = 5;  //!< register each scan against this many predecessors
	double overlapDistance = 6.0;  //!< poses closer than this are candidates for an overlap edge [m]
	double overlapMinLength = 2.0;  //!< corresponding static length that makes two scans overlap [m]
	double overlapMinShare = 0.25;  //!< matched share of the shorter scan's static length for an overlap edge
	int overlapRunGap = 10;  //!< candidate poses further apart than this in time belong to different passes
	double consistencyChi2 = 16.0;  //!< gate of the pairwise loop-closure consistency test
	double recheckGateFactor = 1.5;  //!< gates x this when testing whether an edge's correspondences changed
	double minChangedShare = 0.0;  //!< converged when the share of changed constraints is at most this
	double passHeadingWeight = 1.0;  //!< an earlier pass's candidate pose: nearest in position + this x heading difference [m/rad]
	bool overlapMostOverlapping = true;  //!< a pass whose nearest-in-view pose shares too little: its most overlapping poses instead (non-degenerate registrations only)
	bool informationInEdgeFrame = true;  //!< rotate a registration's information into the frame of Eq. 21's error before optimising
	bool reconsiderRejected = true;  //!< edges rejected by the chi2 test return to the optimiser at the next M-step
	int reconsiderLimit = 2;  //!< ... until a pair has been rejected this many times with the same correspondences
	int reconsiderFreeSteps = 2;  //!< rejections in the first this many M-steps do not count towards reconsider_limit
	bool loopSearch = true;  //!< search loop closures from vector corners within a window growing with the pose uncertainty
	double loopSearchSigmas = 3.0;  //!< window half-size in odometry-model standard deviations of the path between the poses
	double loopSearchMaxRadius = 8.0;  //!< the translation window never exceeds this [m]
	int loopSearchVectors = 10;  //!< longest static vectors per scan whose corners give hypotheses
	int loopSearchHypotheses = 4;  //!< best-ranked hypotheses refined by the matcher
	double loopSearchMinShare = 0.4;  //!< matched share of the shorter scan's static length for a loop edge
	double loopSearchAmbiguity = 0.7;  //!< a distinct solution matching this share of the best's length makes the place ambiguous
	double loopSearchDistinct = 0.3;  //!< solutions further apart than this are distinct [m]
	bool loopSearchWeakLinks = true;  //!< passes linked only by corridor-degenerate or rejected edges are still searched
	double loopSearchCandidateSpacing = 0.0;  //!< loop search: also register the pass's poses this far apart along the path [m]; 0: nearest only
	bool loopSearchAllVectors = true;  //!< a loop search that finds nothing on the static vectors searches again on all of both scans' vectors
	bool overlapReregisterMoved = false;  //!< an overlap registration that moved beyond the matcher's initial gates is redone from the estimate optimised without it
	bool sequentialOdometryGuess = false;  //!< first M-step: a sequential pair that failed from the chained guess is tried from the odometry between its scans
	double registerMinIncidenceDeg = 0.0;  //!< overlap and loop registrations leave out static vectors every beam saw under less than this incidence [deg]; 0: all
	double dropDistanceFactor = 1.5;  //!< a non-sequential edge whose poses are further apart than this x overlap_distance is dropped
	double dropLengthShare = 0.5;  //!< an overlap edge whose overlap falls below this x overlap_min_length is dropped
	double changedTranslation = 1e-3;  //!< a re-registered edge changed when its pose moved more than this [m]
	double changedRotation = 1e-4;  //!< ... or turned more than this [rad]
	double movedGateShare = 0.5;  //!< a failed pair is retried once its relative pose moved this x the final matcher gates
	double searchedNearDistance = 0.5;  //!< a pair searched from within this of the relative pose is not searched again [m]
	double searchedNearDeg = 10.0;  //!< ... and within this turn [deg]
	double loopWindowMinTranslation = 1.0;  //!< loop-search translation window floor [m]
	double loopWindowMinRotationDeg = 10.0;  //!< loop-search rotation window floor [deg]
	double consistencyInfoXY = 1.0;  //!< information added to an edge's in the consistency test [1/m^2]
	double consistencyInfoPhi = 10.0;  //!< ... [1/rad^2]
	double consistencyChainVarXY = 1e-3;  //!< chain covariance per scan step in the consistency test [m^2]
	double consistencyChainVarPhi = 1e-4;  //!< ... [rad^2]
	int strongMinCorrespondences = 4;  //!< an unsupported overlap edge is kept with at least this many correspondences,
	double strongMinShare = 0.4;  //!< ... this matched share
	double strongMinDegeneracy = 0.05;  //!< ... and this translation degeneracy ratio
	double loopCornerMinLength = 0.3;  //!< loop search: corners only from static vectors this long [m]
	double loopCornerMinAngleDeg = 30.0;  //!< ... whose directions differ by at least this [deg]
	double loopCornerMaxGap = 1.0;  //!< ... and whose lines meet within this of both segments [m]
	double loopCornerTurnToleranceDeg = 10.0;  //!< paired corners' turns agree within this [deg]
	double loopDuplicateDistance = 0.1;  //!< hypotheses closer than this are one [m]
	double loopDuplicateDeg = 2.0;  //!< ... and turned less than this [deg]
	double loopScoreGateFactor = 2.0;  //!< hypotheses scored with the final matcher gates x this
	double loopDistinctDeg = 5.0;  //!< solutions turned more than this apart are distinct [deg]

	template <class V>
	void visit(V&& v)
	{
		v("max_iterations", maxIterations, "EM iterations at most");
		v("keyframe_distance", keyframeDistance, "EM works on the scans whose odometry moved this far since the last one; the others follow the odometry between them [m]");
		v("keyframe_rotation_deg", keyframeRotationDeg, "... or turned this much [deg]");
		v("sequential_window", sequentialWindow, "Register each scan against this many predecessors");
		v("overlap_distance", overlapDistance, "Poses closer than this are candidates for an overlap edge [m]");
		v("overlap_min_length", overlapMinLength, "Corresponding static vector length that makes two scans overlap [m]");
		v("overlap_min_share", overlapMinShare, "Matched share of the shorter scan's static length needed to accept an overlap edge");
		v("overlap_run_gap", overlapRunGap, "Candidate poses further apart than this many scans belong to different passes");
		v("consistency_chi2", consistencyChi2, "Two overlap edges near each other support each other when their cycle closes within this chi2");
		v("recheck_gate_factor", recheckGateFactor, "Gates are widened by this when testing whether an edge's correspondences changed (Eq. 24-25)");
		v("min_changed_share", minChangedShare, "EM has converged when at most this share of constraints changed");
		v("pass_heading_weight", passHeadingWeight, "Overlap and loop search: the candidate pose of an earlier pass is the one nearest in position + this x heading difference (a scan sees what lies ahead of it; 0: position only) [m/rad]");
		v("information_in_edge_frame", informationInEdgeFrame, "A registration's information is over the relative pose (x, y, phi) of the later scan in the earlier scan's frame; the pose graph's error (Eq. 21, z^-1 (+) x_i^-1 (+) x_j) has its translation in the later scan's frame. true: the information is rotated by the edge's relative heading into the error's frame (D^T I D, D = diag(R(z_phi), 1)); false: used as it is, which is exact only for edges whose scans face the same way (an edge between passes walked in opposite ways then gets its rotation / translation coupling with the wrong sign)");
		v("overlap_most_overlapping", overlapMostOverlapping, "Beyond the paper: when the earlier pass's pose nearest in view (pass_heading_weight) shares less than overlap_min_length of corresponding static vectors with the pose (a pass walked the other way: the nearest pose faces away from what the pose sees; a crossing), the pass's other poses that share that much are registered, the most overlapping first, and the first registration whose translation is not degenerate (matcher.degenerate_ratio: no corridor slide) is the overlap edge; false: no overlap edge to that pass");
		v("reconsider_rejected", reconsiderRejected, "Edges the pose graph rejected by their chi2 return to the optimiser at every M-step (switchable-constraint behaviour: an edge rejected against a wrong estimate can come back once the estimate has moved); false: a rejection stands until its scans' static vectors change");
		v("reconsider_limit", reconsiderLimit, "With reconsider_rejected: a pair the chi2 test rejected this many times with the same vector correspondences stays out until a re-registration changes them (Eq. 24-25; stops edges flipping in and out between EM iterations); 0: no limit");
		v("reconsider_free_steps", reconsiderFreeSteps, "Rejections in the first this many M-steps (while the estimate still moves from the raw chain and the first loop closures) do not count towards reconsider_limit");
		v("loop_search", loopSearch, "Search loop closures from vector corners within a window growing with the pose uncertainty");
		v("loop_search_sigmas", loopSearchSigmas, "Loop-search window half-size in odometry-model standard deviations of the path between the two poses");
		v("loop_search_max_radius", loopSearchMaxRadius, "Largest loop-search translation window (and candidate distance) [m]");
		v("loop_search_vectors", loopSearchVectors, "Longest static vectors per scan whose corners give loop hypotheses");
		v("loop_search_hypotheses", loopSearchHypotheses, "Best-ranked loop hypotheses refined by the matcher");
		v("loop_search_min_share", loopSearchMinShare, "Matched share of the shorter scan's static length needed for a loop edge");
		v("loop_search_ambiguity", loopSearchAmbiguity, "A loop edge is rejected as ambiguous when a distinct solution matches at least this share of the best one's length");
		v("loop_search_distinct", loopSearchDistinct, "Loop-search solutions further apart than this are distinct [m]");
		v("loop_search_weak_links", loopSearchWeakLinks, "The loop search also runs between passes that only edges with a degenerate translation (below matcher.degenerate_ratio: a corridor slide) or rejected edges link; false: any edge spares the pair");
		v("loop_search_candidate_spacing", loopSearchCandidateSpacing, "The loop search registers a pose against the earlier pass's pose nearest in view and against every pose of that pass inside the window at least this far (odometry path) from the poses already taken, keeping the result with the most matched length (the nearest pose under a misplaced estimate need not be the one that sees the place); 0 (default): the nearest pose only; 1 m lowers the intel loop error but raises the aces one with the EmSlam defaults (doc/benchmarks-history.md) [m]");
		v("loop_search_all_vectors", loopSearchAllVectors, "Beyond the paper: where the loop search between two unlinked passes finds nothing on the static vectors and the E-step made part of either scan dynamic, it searches again on all vectors of both scans as extracted (MStep::setAllVectors); a place the estimate misplaces is where the E-step makes good walls dynamic (the other pass's beams cross them), so the evidence the search needs is what the E-step removed; the edge's acceptance is unchanged (loop_search_min_share, non-degenerate, unambiguous, pairwise consistency), and after the next E-step it is re-registered on the static vectors (Eq. 24-25)");
		v("overlap_reregister_moved", overlapReregisterMoved, "Beyond the paper: an overlap registration whose solution moved the pair's relative pose beyond the matcher's initial gates (gate_rho_initial, gate_psi_initial_deg) did not start from an estimate that shows the overlap (the first M-step's chain, a loop not yet closed), so where it converged is as likely the alias nearest the wrong guess (repeated door recesses along a corridor) as the place; such a pair is left out of the optimisation, then registered again from the estimate optimised with the other edges (the loop search's included), and that registration, pairwise-checked, is the overlap edge (one more optimisation in that M-step)");
		v("sequential_odometry_guess", sequentialOdometryGuess, "Beyond the paper, first M-step: a scan is registered against its sequential_window predecessors from the chained guess (the predecessor's fused pose plus the odometry step), so one predecessor that its own registrations placed a few degrees off (csail seed 8: scan 42, ~10 deg from the scans around it) turns every later guess as much, and the scan after it registers against none of its predecessors and hangs on the odometry alone; true: a pair (j, i) that failed from the chained guess is tried once more from the odometry between j and i when that differs by more than moved_gate_share x the final gates; false: the chained guess only");
		v("register_min_incidence_deg", registerMinIncidenceDeg, "Beyond the paper (Eq. 19-20 register every static vector): a static vector whose every point the scan saw under less than this incidence (the angle between the beam and the vector's line, largest at the vector's point nearest the sensor) is left out of the overlap and loop registrations (sequential ones keep every vector: consecutive scans see a wall from nearly one viewpoint); such a vector seen along a wall from beside it can lie 0.3 m behind where scans facing the wall put it (intel seed 8: the wall at (13.6..15.1, -4.6) seen at 9-16 deg from scans 313-320 at y -4.3), and as the one vector across a corridor it decides the registration's position along it (the sensor is taken at the scan frame's origin, as in the CARMEN logs); off by default: it repairs intel seed 8 but moves the other logs both ways (doc/benchmarks.md, Seeds beyond 1-3); 0: every static vector [deg]");
		v("drop_distance_factor", dropDistanceFactor, "Beyond the paper (Sec. 4.3 drops edges whose scans no longer overlap): a non-sequential edge whose poses are further apart than this x overlap_distance is removed");
		v("drop_length_share", dropLengthShare, "Beyond the paper: an overlap edge whose scans' corresponding static length falls below this x overlap_min_length is removed (Sec. 4.3)");
		v("changed_translation", changedTranslation, "Eq. 24-25 bookkeeping, beyond the paper: a re-registered edge with the same correspondences counts as changed when its relative pose moved more than this [m]");
		v("changed_rotation", changedRotation, "... or turned more than this [rad]");
		v("moved_gate_share", movedGateShare, "Beyond the paper: a pair whose registration failed is tried again once its relative pose moved more than this x matcher.gate_rho_final or turned more than this x matcher.gate_psi_final_deg (or its scans' vectors changed)");
		v("searched_near_distance", searchedNearDistance, "Beyond the paper: the loop search does not search a pair again from a relative pose within this of one it was searched from [m]");
		v("searched_near_deg", searchedNearDeg, "... and turned less than this from it [deg]");
		v("loop_window_min_translation", loopWindowMinTranslation, "Beyond the paper: the loop-search translation window (loop_search_sigmas x the odometry model) is at least this [m]");
		v("loop_window_min_rotation_deg", loopWindowMinRotationDeg, "Beyond the paper: the loop-search rotation window is at least this (and at most 180) [deg]");
		v("consistency_info_xy", consistencyInfoXY, "Beyond the paper, pairwise consistency test of overlap edges: this information is added to each edge's before inverting (caps its translation std. dev. at 1/sqrt(this)) [1/m^2]");
		v("consistency_info_phi", consistencyInfoPhi, "... and this to its rotation information (10: 0.32 rad) [1/rad^2]");
		v("consistency_chain_var_xy", consistencyChainVarXY, "Beyond the paper: consistency test, translation variance of the local trajectory chain per scan step between the two edges' ends (times 1 + steps) [m^2]");
		v("consistency_chain_var_phi", consistencyChainVarPhi, "... its rotation variance per step [rad^2]");
		v("strong_min_correspondences", strongMinCorrespondences, "Beyond the paper: an overlap edge that no other edge supports or contradicts is kept only when it is strong: at least this many vector correspondences,");
		v("strong_min_share", strongMinShare, "... at least this matched share of the shorter scan's static length");
		v("strong_min_degeneracy", strongMinDegeneracy, "... and a translation degeneracy ratio (weakest / strongest direction's information) of at least this");
		v("loop_corner_min_length", loopCornerMinLength, "Beyond the paper (loop search): corners are made only from static vectors at least this long [m]");
		v("loop_corner_min_angle_deg", loopCornerMinAngleDeg, "Beyond the paper: a corner's two vectors differ in direction by at least this [deg]");
		v("loop_corner_max_gap", loopCornerMaxGap, "Beyond the paper: a corner's lines meet within this distance of both segments [m]");
		v("loop_corner_turn_tolerance_deg", loopCornerTurnToleranceDeg, "Beyond the paper: two scans' corners pair into a hypothesis when their turns agree within this [deg]");
		v("loop_duplicate_distance", loopDuplicateDistance, "Beyond the paper: loop hypotheses closer than this are one [m]");
		v("loop_duplicate_deg", loopDuplicateDeg, "... and turned less than this from each other [deg]");
		v("loop_score_gate_factor", loopScoreGateFactor, "Beyond the paper: hypotheses are ranked by the length matched under the final matcher gates widened by this factor");
		v("loop_distinct_deg", loopDistinctDeg, "Beyond the paper: loop-search solutions turned more than this apart are distinct (as loop_search_distinct for translation) [deg]");
	}
};

/** Eq. 6-7: conversion of the grid vector map to an occupancy grid. */
struct OccupancyOptions
{
	double resolution = 0.10;  //!< output cell size [m]
	double margin = 0.5;  //!< border around the vectors' bounding box [m]
	/** Eq. 6 sample points per axis and output cell; 0: ceil(resolution / vector cell). */
	int samplesPerAxis = 0;
	/** true: a cell takes the largest Eq. 6 occupancy of its observed sub-samples;
	 * false: the area average of the counts. */
	bool maxPooling = true;

	template <class V>
	void visit(V&& v)
	{
		v("resolution", resolution, "Cell size of the occupancy grid made from the vectors by Eq. 6 (occupancy.png/.pgm, MRPT grid) [m]");
		v("margin", margin, "Border added around the vectors' bounding box [m]");
		v("samples_per_axis", samplesPerAxis, "Eq. 6 is evaluated at this many points per axis of an output cell; 0: one per vector cell (at the vectors' own resolution: Eq. 6 at the cell centre)");
		v("max_pooling", maxPooling, "An output cell takes the largest Eq. 6 occupancy among its observed sample points (a cell holding any obstacle is occupied, as in a ray-casting grid); false: the area average of the counts");
	}
};

/** Sec. 5.4: door detection from static/dynamic corners. */
struct DoorOptions
{
	double maxCornerGap = 0.30;  //!< a static and a dynamic vector form a corner when their ends are this close [m]
	double minCornerAngleDeg = 10.0;  //!< ... and their directions differ by at least this [deg]
	double maxVertexDistance = 0.25;  //!< corners' vertices closer than this share a hinge [m]
	double maxLengthDiff = 0.25;  //!< door leaves of equal length within this [m]
	double minDoorLength = 0.6;  //!< door leaf length range [m]
	double maxDoorLength = 1.4;
	double minStateDiffDeg = 10.0;  //!< two door states differ by at least this [deg]
	double maxTeeOffset = 0.10;  //!< a candidate's end this close to a wall's interior is a T corner [m]
	double minSweepDeg = 90.0;  //!< a leaf's swept arc is widened to at least this from its closed state [deg]
	double leafChainGap = 0.10;  //!< a dynamic and a static piece of one leaf meet end to end within this [m]
	double leafChainMaxTurnDeg = 10.0;  //!< ... and turn by at most this at the joint [deg]
	double minOpenDeg = 30.0;  //!< a door has a state at least this far from its wall's line [deg]
	bool closedLeafHiddenEnds = false;  //!< a closed leaf's ends hidden in the walls are matched as intervals
	bool closedLeafToLatch = false;  //!< a closed leaf seen in part may reach the collinear wall ahead
	bool duringEm = false;  //!< Sec. 5.3: doors detected after each E-step, their states kept out of the M-step

	template <class V>
	void visit(V&& v)
	{
		v("max_corner_gap", maxCornerGap, "A static and a dynamic vector form a corner when an end of each is this close [m]");
		v("min_corner_angle_deg", minCornerAngleDeg, "A corner's two vectors differ in direction by at least this [deg]");
		v("max_vertex_distance", maxVertexDistance, "Corners whose vertices are closer than this share a hinge [m]");
		v("max_length_diff", maxLengthDiff, "Door leaves (states) whose lengths differ by less than this are one door [m]");
		v("min_door_length", minDoorLength, "Shortest door leaf [m]");
		v("max_door_length", maxDoorLength, "Longest door leaf [m]");
		v("min_state_diff_deg", minStateDiffDeg, "Two door states (leaf angles) differ by at least this [deg]");
		v("min_sweep_deg", minSweepDeg, "Beyond the paper (Sec. 5.4 gives no door model): the arc a door leaf sweeps, where other vectors from the hinge count as its states, is at least this wide from the state nearest the wall (a hinged door opens to a right angle) even when the states seen span less [deg]");
		v("leaf_chain_gap", leafChainGap, "Beyond the paper: a short dynamic vector and a static vector no longer than max_door_length whose ends meet within this are one door leaf cut by the E-step (Fig. 4), its never-seen-through-again part static [m]");
		v("leaf_chain_max_turn_deg", leafChainMaxTurnDeg, "Beyond the paper: the two pieces of such a leaf turn by at most this at their joint (collinear) [deg]");
		v("min_open_deg", minOpenDeg, "Beyond the paper (Fig. 10's leaf turns from its wall): a door has at least one state this far or farther from its wall's line (a leaf seen open); doors whose every state lies closer to the wall's line are a wall seen dynamic in kinked pieces (real logs, doc/benchmarks.md) [deg]; 0: off");
		v("max_tee_offset", maxTeeOffset, "A door candidate's end this close to the interior of a static vector longer than max_door_length makes a T corner (a wall merged across the doorway) [m]; 0: end corners only");
		v("closed_leaf_hidden_ends", closedLeafHiddenEnds, "Beyond the paper (Fig. 10 compares corners at one vertex and whole leaves): a dynamic closed state along its wall's line that overlaps the wall's end has its hinge anywhere from its end inside the wall to the wall's end, and one that runs into the latch-side wall (a static vector on the wall's line starting between its ends) its tip anywhere from that wall's start to its end; corners are compared over those intervals, the door's hinge placed on the closed state's line nearest the other corners' vertices and its length taken nearest their longest leaf; and a new hinge whose states all lie within min_open_deg of its wall's line gives its leaves back at once (the wider matches make such hinges, which took a true door's closed state); false: the wall's end and, reaching into the wall by more than max_corner_gap, its own end inside the wall are its vertices (two corners), its whole length from there");
		v("during_em", duringEm, "Sec. 5.3 (\"the dynamic doors can be detected gradually in the EM procedure and excluded from data associations\"): after each E-step the doors are detected on its map (split and merged as the final map is), accumulated over the iterations (a door stays until a later one is found at its hinge), and every static child that is a door state is kept out of the later M-steps' registrations: whole where it went into a door's leaf, its stretch along a door state where a wall runs across one, as decided the first time (the exclusion only grows); such a child counts once as changed for Eq. 25. doors.txt stays the detection on the final map. Off by default: on the real logs, whose doors are mostly corners and clutter, it costs loop error (doc/benchmarks.md, \"Doors during EM\"); false: doors only on the final map, the M-step registers every static child");
		v("closed_leaf_to_latch", closedLeafToLatch, "Beyond the paper (Fig. 10 compares whole leaves): a dynamic closed state along its wall's line that ends short of the next collinear static vector ahead (the latch-side wall) is a leaf seen in part, so its length is matched as anything from its own up to the distance to that wall (at most max_door_length); false: its own length");
	}
};

/** Beyond the paper: CGridVectorMap as the reference map of MRPT's ICP
 * (determineMatching2D and friends; see StaticFootPoints). */
struct MatchingOptions
{
	double staticThreshold = 0.0;  //!< a column takes part when its Fig. 4 profile is at least this (0: every column)

	template <class V>
	void visit(V&& v)
	{
		v("static_threshold", staticThreshold, "Beyond the paper (CGridVectorMap::determineMatching2D, MRPT's ICP against the map): a scan point corresponds to the nearest point of the vectors' stretches whose columns the E-step's occupancy profile (Fig. 4, estep.use_peak_row / min_visits / free_weight) puts at or above this, on vectors not classified dynamic (Eq. 14); 0.5 is estep.static_threshold's default (Eq. 14's split); 0: every column of every vector not classified dynamic");
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
	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& cfg, const std::string& prefix = "gridvector",
		const std::string& sourceName = "config", const std::vector<std::string>& otherSections = {});
	/** Loads an .ini file; throws std::runtime_error("FILE: problem"), also "FILE:LINE: problem"
	 * for a key outside any section or a section header without its ']'. */
	void loadFromFile(const std::string& iniPath, const std::string& prefix = "gridvector");
	/** Writes all sections as a valid .ini file. */
	void dumpAsIni(std::ostream& out, const std::string& prefix = "gridvector") const;
	/** Markdown table of every parameter (section, key, default, meaning). */
	static std::string parameterTableMarkdown(const std::string& prefix = "gridvector");
	/** Throws std::invalid_argument "[<prefix>_group] key = 'value' must be ..." for the first value out of its
	 * valid range (a negative count, a zero window, a share outside [0,1], a minimum above its maximum). */
	void validate(const std::string& prefix = "gridvector") const;

	// --- by-name access (the .gvmap config record, report.json, profiles) ---
	/** Every key as "group.key" with its value (ints and bools as 0/1), in visit() order. */
	std::vector<std::pair<std::string, double>> namedValues() const;
	/** Sets "group.key" (e.g. "grid.resolution"). Returns false if this version has no such key;
	 * throws std::invalid_argument if the value does not fit the key's type (int, bool). */
	bool setNamedValue(const std::string& name, double value);
	/** {"extraction": {"min_range": 0.02, ...}, ...}: every key, bools as true/false, a non-finite value
	 * (set in code; an .ini cannot give one) as null: always valid JSON. */
	std::string toJson() const;
};

}  // namespace gridvector
