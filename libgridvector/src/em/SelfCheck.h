// Beyond the paper (issue 21, item 3): the self-check of an EM-SLAM run. Evidence, from the run
// alone (no ground truth), that its trajectory or map is broken, and a verdict, ok or suspect.
#pragma once

#include "mstep/Constraint.h"
#include "posegraph/PoseGraph.h"
#include <gridvector/GridVector.h>

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

#include <algorithm>
#include <string>
#include <vector>

namespace gridvector
{
/** How well the final pose graph (Eq. 22) fits its own edges. */
struct PoseGraphFit
{
	size_t nodes = 0;
	size_t odometryEdges = 0, registrationEdges = 0;  //!< active edges
	size_t downweighted = 0;  //!< active registration edges the robust kernel (DCS) weighs below kDownweighted
	size_t inactive = 0;  //!< registration edges the chi2 test switched off in the last optimisation
	double odometryChi2 = 0, registrationChi2 = 0;  //!< sum of e^T Omega e over the active edges
	double odometryDof = 0, registrationDof = 0;  //!< their residual dimensions
	/** chi2 / (residual dimensions - 3 (nodes - 1)): ~1 for a graph whose errors are as its
	 * informations say; NaN where the graph has no redundancy. */
	double normalisedChi2() const;
};

/** DCS scale below which an active registration edge counts as rejected by the robust kernel: it then weighs less
 * than half of what its information says (s = 2 Phi / (Phi + chi2) < 0.5: chi2 > 3 Phi). */
constexpr double kDownweighted = 0.5;

/** PoseGraphFit of a graph after PoseGraph::optimize (its edges' chi2 and scale are those of its nodes). */
PoseGraphFit poseGraphFit(const PoseGraph& graph);

/** One scan for the map's self-consistency: its pose, its sensor's origin and its valid beam
 * endpoints, both in the robot frame. */
struct ScanBeams
{
	mrpt::math::TPose2D pose;
	mrpt::math::TPoint2D origin{0, 0};
	std::vector<mrpt::math::TPoint2D> ends;
};

/** The map's self-consistency: of the scans' beams, how many end beyond a static vector of the
 * final map they cross (by kThroughWall or more behind its line), and how many of those cross it
 * where its grid (Eq. 2) says occupied: a cell of the column the beam crosses holds
 * n_occupy / n_visit > kOccupied. In a consistent map a beam stops at the first wall it meets; a
 * trajectory that is broken puts walls of one pass across the beams of another. */
struct BeamConsistency
{
	size_t beams = 0;
	size_t throughWalls = 0;  //!< beams ending behind a static vector they cross
	size_t throughOccupied = 0;  //!< ... that cross it at an occupied cell
	double share() const { return beams ? double(throughOccupied) / double(beams) : 0.0; }
	double geometricShare() const { return beams ? double(throughWalls) / double(beams) : 0.0; }
};

/** A cell is occupied above this n_occupy / n_visit (Eq. 6's even odds). */
constexpr double kOccupied = 0.5;

/** A beam counts as through a wall if its endpoint lies this far behind the wall's line: well above the range
 * noise and the vectors' fit error (a few cm), so a beam that ends on a wall, at any incidence, does not [m]. */
constexpr double kThroughWall = 0.25;

BeamConsistency beamConsistency(const std::vector<GridVector>& staticMap, const std::vector<ScanBeams>& scans);

/** Everything the verdict looks at. */
struct SelfCheckEvidence
{
	bool converged = false;
	size_t iterations = 0;
	size_t registrations = 0, failedRegistrations = 0;  //!< summed over the M-steps
	size_t edges = 0, rejectedEdges = 0;  //!< registration edges at the end, and of them out (chi2) or down-weighted
	size_t keyframes = 0, sequentialEdges = 0;  //!< the scans EM placed, and the active sequential edges at the end
	PoseGraphFit graph;
	BeamConsistency beams;  //!< reported, not judged: good runs reach 8 %, broken ones as little as 1 % (their
							//!< inconsistent walls are dynamic, not static)
	double staticLength = 0, dynamicLength = 0;  //!< of the final map [m]

	double failedShare() const { return registrations ? double(failedRegistrations) / double(registrations) : 0.0; }
	double rejectedShare() const { return edges ? double(rejectedEdges) / double(edges) : 0.0; }
	/** Share of the keyframes after the first that no active sequential edge registers to a predecessor:
	 * 1 - sequential edges / (keyframes - 1), at least 0. */
	double unlinkedShare() const
	{
		return keyframes > 1 ? std::max(0.0, 1.0 - double(sequentialEdges) / double(keyframes - 1)) : 0.0;
	}
	double dynamicShare() const
	{
		return staticLength + dynamicLength > 0 ? dynamicLength / (staticLength + dynamicLength) : 0.0;
	}
};

/** Gathers the evidence of a run: `iterations` its M-steps' reports (the last one's edges are the final graph's),
 * `fit` the final graph's fit, `finalMap` the final vectors (state set). */
SelfCheckEvidence selfCheckEvidence(bool converged, const std::vector<MStepReport>& iterations, size_t keyframes,
									const PoseGraphFit& fit, const BeamConsistency& beams,
									const std::vector<GridVector>& finalMap);

struct SelfCheckVerdict
{
	bool ok = true;
	std::vector<std::string> reasons;  //!< one per failed test, with its figure and threshold
};

// Thresholds of the verdict, from every signal on the good and the broken runs of doc/benchmarks-history.md
// ("Session 14: self-check"); each lies several times the good runs' worst value away from it.

/** The final graph's chi2 per residual dimension above this: its edges fit the trajectory worse than their own
 * informations claim (good runs: 0.09-0.31, the matcher's informations are conservative). */
constexpr double kMaxNormalisedChi2 = 1.0;
/** More than this share of the final registration edges out or down-weighted: the graph disagrees with itself
 * (good runs: at most 0.8 %). */
constexpr double kMaxRejectedShare = 0.05;
/** More keyframes than this not registered to a predecessor: the scan-to-scan registration itself fails (good
 * runs: none). */
constexpr double kMaxUnlinkedShare = 0.2;
/** EM that did not converge while more than this share of its registrations failed has not found its scans in one
 * another (good runs converge; of their registrations, mostly candidate pairs tried, 26-69 % fail). */
constexpr double kMaxFailedShareUnconverged = 0.75;
/** EM that did not converge with more than this share of the final map's length dynamic: the trajectory does not make
 * the scans agree, so the E-step (Eq. 14-15) finds the walls of one pass crossed by the beams of another (good runs:
 * 6-41 %). Not a test on its own: a converged run of a busy world may be mostly dynamic (gv-sim's long-corridor, 69 %).
 */
constexpr double kMaxDynamicShareUnconverged = 0.6;

SelfCheckVerdict judge(const SelfCheckEvidence& e);

/** The verdict's stderr line (doc/io.md): "self-check: ok" or "self-check: suspect (exit status 3): r1; r2". */
std::string verdictLine(const SelfCheckVerdict& v);

}  // namespace gridvector
