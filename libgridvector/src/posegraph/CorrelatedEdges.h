// Eq. 22 with correlated registrations: edges that share a scan weighed as one piece of evidence (covariance intersection).
#pragma once

#include "posegraph/PoseGraph.h"

#include <vector>

namespace gridvector
{
/** Eq. 22 sums e^T Omega e over the edges as if each edge's error were independent. Registrations
 * of one scan s against consecutive scans b, b+1, b+2 of another pass (the overlap search pairs
 * every scan of a pass with the other pass's nearest pose, so one scan is often the partner of
 * several) are not: their errors share s's own extraction error, and an alias of s (a wall piece
 * matched one recess off) repeats in all of them, so three such edges outvote two independent
 * correct ones although they carry the evidence of one registration.
 *
 * The principle is covariance intersection (Julier and Uhlmann, "A non-divergent estimation
 * algorithm in the presence of unknown correlations", ACC 1997): fusing n estimates whose
 * cross-correlation is unknown with information sum_k w_k Omega_k, sum_k w_k = 1, is consistent
 * whatever the correlation; equal weights w_k = 1/n are the choice that does not prefer a member.
 * The same grouping appears in robust back ends as a shared switch or a shared DCS scale for
 * edges that stand or fall together (Suenderhauf and Protzel's switchable constraints with one
 * switch per group; Agarwal et al.'s dynamic covariance scaling): here the scale stays per edge
 * and the group is expressed in the information, so the kernel and the chi2 rejection see each
 * member's share of the evidence.
 *
 * Between independence and covariance intersection: n measurements of one quantity with equal
 * variance and pairwise correlation rho carry together the information of n / (1 + (n - 1) rho)
 * of them (the variance of their mean is sigma^2 (1 + (n - 1) rho) / n), so each member's weight is
 * 1 / (1 + (n - 1) rho): rho = 1 is covariance intersection's 1 / n, rho = 0 independence.
 *
 * A group: the active overlap and loop edges with one end at scan s whose other ends, sorted,
 * are at most `gap` scans apart one to the next (one pass near s). Each member's weight is
 * 1 / (1 + (n - 1) rho) for a group of n; an edge in groups at both of its ends takes the smaller weight. Odometry and
 * sequential edges keep 1 (the sequential window registers every scan against the same number
 * of predecessors; its correlation is the same everywhere). gap <= 0: every weight 1. */
std::vector<double> correlatedEdgeWeights(const std::vector<PoseEdge>& edges, int gap, double rho = 1.0);

}  // namespace gridvector
