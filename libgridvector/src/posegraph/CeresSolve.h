// Sec. 4.2, Eq. 22: one robust least-squares stage of the pose graph solved by Ceres' Levenberg-Marquardt.
#pragma once

#include "posegraph/PoseGraph.h"

#include <array>
#include <vector>

namespace gridvector
{
/** Minimises sum_k rho_k(e_k^T Omega_k e_k) over x_1..x_{n-1} (x_0 fixed) with Ceres (2D pose-graph
 * cost as in Ceres' slam/pose_graph_2d example: e = error(), residual L^T e with L L^T = Omega, angle
 * normalised, AutoDiff). rho is the dynamic covariance scaling kernel at width phiByDof[dof] for
 * registration edges (its IRLS weight rho' is PoseGraph's scale s^2 = min(1, 2 Phi / (Phi + chi2))^2,
 * so the fixed points are the built-in optimiser's), least squares for odometry edges and when
 * `robust` is false. Stops after maxIterations steps or when a step changes the cost by less than
 * minRelativeDecrease of it. Returns the steps taken. */
int solveWithCeres(std::vector<mrpt::math::TPose2D>& nodes, const std::vector<PoseEdge>& edges,
				   const std::array<double, 4>& phiByDof, bool robust, int maxIterations, double minRelativeDecrease);

}  // namespace gridvector
