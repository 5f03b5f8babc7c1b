// VectorMatcher (Sec. 4.2): registration accuracy, corridor degeneracy, rejection, speed.
#include "match_world.h"

#include <mrpt/math/TPose2D.h>
#include "mstep/VectorMatcher.h"

#include <Eigen/Eigenvalues>
#include <gtest/gtest.h>
#include <mrpt/math/wrap2pi.h>

#include <cmath>
#include <random>

using namespace gridvector;
using mrpt::math::TPose2D;

namespace
{
using matchtest::observe;
using matchtest::WorldSeg;

TPose2D relative(const TPose2D& a, const TPose2D& b)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi);
	const double dx = b.x - a.x, dy = b.y - a.y;
	return {c * dx + s * dy, -s * dx + c * dy, mrpt::math::wrapToPi(b.phi - a.phi)};
}

// An office-like room (walls counter-clockwise, seen from inside) with furniture.
std::vector<WorldSeg> room()
{
	return {{0, 0, 4, 0}, {4.5, 0, 8, 0}, {8, 0, 8, 3},       {8, 3.8, 8, 6},     {8, 6, 3, 6},   {2.2, 6, 0, 6},
			{0, 6, 0, 0}, {2, 2, 2, 3.2}, {2, 3.2, 3.5, 3.2}, {3.5, 3.2, 3.5, 2}, {3.5, 2, 2, 2}, {6, 4, 5.2, 4.6}};
}
}  // namespace

TEST(VectorMatcher, RecoversRelativePoseFromPerturbedGuess)
{
	const TPose2D xa(1.0, 1.0, 0.3), xb(1.6, 1.4, 0.45);
	const auto a = observe(room(), xa, 0.0, 1, 1), b = observe(room(), xb, 0.0, 2, 100);
	const TPose2D truth = relative(xa, xb);
	VectorMatcher m;
	const TPose2D guess(truth.x + 0.25, truth.y - 0.2, truth.phi + 0.12);
	const MatchResult r = m.match(a, b, guess);
	ASSERT_TRUE(r.ok()) << toString(r.status);
	EXPECT_NEAR(r.pose.x, truth.x, 1e-6);
	EXPECT_NEAR(r.pose.y, truth.y, 1e-6);
	EXPECT_NEAR(r.pose.phi, truth.phi, 1e-7);
	EXPECT_LT(r.rms, 1e-6);
	EXPECT_GE(r.pairs.size(), 8u);
	// correspondences are the same wall seen twice: ids 1.. and 100.. in the same order
	for (const auto& p : r.pairs) EXPECT_EQ(p.b - 100, p.a - 1);
	// full rank information, positive definite
	const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(r.information);
	EXPECT_GT(es.eigenvalues()(0), 100.0);
}

// A perfect fit claims the laser's noise, kSigmaFloor (0.03 m), or its scans' range std. dev. where that is
// larger: from scans of 0.3 m the same match is worth (0.03 / 0.3)^2 of the information, at the same pose.
TEST(VectorMatcher, InformationAtMostThatOfTheScansRangeNoise)
{
	const TPose2D xa(1.0, 1.0, 0.3), xb(1.6, 1.4, 0.45);
	auto a = observe(room(), xa, 0.0, 1, 1), b = observe(room(), xb, 0.0, 2, 100);
	const TPose2D truth = relative(xa, xb);
	VectorMatcher m;
	const MatchResult clean = m.match(a, b, truth);
	for (auto& s : a) s.sigma = 0.01;  // the usual scanner: below the floor, nothing changes
	for (auto& s : b) s.sigma = 0.01;
	const MatchResult usual = m.match(a, b, truth);
	for (auto& s : b) s.sigma = 0.3;  // one noisy scan is enough
	const MatchResult noisy = m.match(a, b, truth);
	ASSERT_TRUE(clean.ok() && usual.ok() && noisy.ok());
	EXPECT_EQ(usual.information, clean.information);
	EXPECT_NEAR(noisy.pose.x, truth.x, 1e-6);
	EXPECT_NEAR(noisy.pose.phi, truth.phi, 1e-7);
	EXPECT_TRUE(noisy.information.isApprox(clean.information * (0.03 * 0.03) / (0.3 * 0.3), 1e-3));
	EXPECT_EQ(MatchSegment::fromVectors({GridVector({0, 0}, {1, 0}, GridOptions{})}, 0.2).front().sigma, 0.2);
}

TEST(VectorMatcher, NoisySegmentsGiveCentimetreAccuracy)
{
	const TPose2D xa(1.0, 1.0, 0.3), xb(2.0, 1.5, -0.2);
	const TPose2D truth = relative(xa, xb);
	VectorMatcher m;
	double worst = 0;
	for (unsigned seed = 0; seed < 20; ++seed)
	{
		const auto a = observe(room(), xa, 0.01, 10 + seed, 1);
		const auto b = observe(room(), xb, 0.01, 50 + seed, 100);
		const MatchResult r = m.match(a, b, TPose2D(truth.x - 0.3, truth.y + 0.2, truth.phi - 0.1));
		ASSERT_TRUE(r.ok()) << toString(r.status);
		worst = std::max(worst, std::hypot(r.pose.x - truth.x, r.pose.y - truth.y));
		EXPECT_NEAR(r.pose.phi, truth.phi, 0.01);
	}
	EXPECT_LT(worst, 0.03);
}

TEST(VectorMatcher, CorridorLeavesTranslationAlongItUnconstrained)
{
	// two parallel walls along x, open space between them (both seen from inside)
	const std::vector<WorldSeg> corridor = {{0, -1, 5, -1}, {5.6, -1, 12, -1}, {12, 1, 0, 1}};
	const TPose2D xa(2, 0, 0), xb(3, 0.1, 0.05);
	const auto a = observe(corridor, xa, 0, 1, 1), b = observe(corridor, xb, 0, 1, 10);
	const TPose2D truth = relative(xa, xb);
	VectorMatcher m;
	const TPose2D guess(truth.x + 0.4, truth.y + 0.1, truth.phi + 0.03);
	const MatchResult r = m.match(a, b, guess);
	ASSERT_GE(r.pairs.size(), 2u);
	// lateral offset and heading are recovered ...
	EXPECT_NEAR(r.pose.phi, truth.phi, 1e-6);
	const Eigen::Vector2d axis(std::cos(0.0), std::sin(0.0));  // corridor axis in A's frame
	const Eigen::Vector2d err(r.pose.x - truth.x, r.pose.y - truth.y);
	EXPECT_NEAR(err.dot(Eigen::Vector2d(-axis.y(), axis.x())), 0.0, 1e-6);
	// ... the axial component stays where the guess put it, and carries no information
	EXPECT_NEAR(err.dot(axis), 0.4, 1e-3);
	const Eigen::Vector3d ax(axis.x(), axis.y(), 0);
	const Eigen::Vector3d lat(-axis.y(), axis.x(), 0);
	EXPECT_LT(ax.dot(r.information * ax), 1e-6 * lat.dot(r.information * lat));
	EXPECT_LT(r.translationDegeneracy, 1e-6);
}

TEST(VectorMatcher, RejectsInsufficientAndOppositeMatches)
{
	VectorMatcher m;
	// a single wall: too few matches
	const std::vector<WorldSeg> one = {{0, 0, 5, 0}};
	const auto a1 = observe(one, TPose2D(1, 1, 0), 0, 1, 1), b1 = observe(one, TPose2D(1.2, 1, 0), 0, 1, 5);
	EXPECT_EQ(m.match(a1, b1, TPose2D(0.2, 0, 0)).status, MatchStatus::TooFewMatches);
	// the same walls seen from the other side (opposite directions) never correspond
	auto rev = room();
	for (auto& w : rev) std::swap(w.x1, w.x2), std::swap(w.y1, w.y2);
	const auto a = observe(room(), TPose2D(1, 1, 0), 0, 1, 1);
	const auto b = observe(rev, TPose2D(1, 1, 0), 0, 1, 100);
	const MatchResult r = m.match(a, b, TPose2D(0, 0, 0));
	EXPECT_FALSE(r.ok());
	EXPECT_TRUE(r.pairs.empty());
	// empty input
	EXPECT_FALSE(m.match({}, b, TPose2D()).ok());
	EXPECT_FALSE(m.match(a, {}, TPose2D()).ok());
}

TEST(VectorMatcher, CorrespondencesUnderFixedPose)
{
	const TPose2D xa(1.0, 1.0, 0.3), xb(1.6, 1.4, 0.45);
	const auto a = observe(room(), xa, 0, 1, 1), b = observe(room(), xb, 0, 2, 100);
	VectorMatcher m;
	std::vector<VectorPair> pairs;
	const double len = m.correspondences(a, b, relative(xa, xb), m.finalGates(), &pairs);
	EXPECT_GT(len, 20.0);
	EXPECT_GE(pairs.size(), 10u);
	EXPECT_TRUE(std::is_sorted(pairs.begin(), pairs.end()));
	// a 1 m shift breaks criterion 2 for every wall
	TPose2D off = relative(xa, xb);
	off.x += 1.0, off.y += 1.0;
	EXPECT_LT(m.correspondences(a, b, off, m.finalGates(), nullptr), len / 4);
}

TEST(VectorMatcher, ReusedWorkspaceGivesIdenticalResults)
{
	// 40 segments per scan: a dense indoor scan. The matcher reuses its workspace
	// between calls (speed is measured by benchmarks, not here): results must not
	// depend on what the previous call left in it.
	std::vector<WorldSeg> w = room();
	for (int k = 0; k < 28; ++k) w.push_back({10.0 + k, 0.0 + 0.1 * k, 10.5 + k, 0.3 + 0.1 * k});
	const TPose2D xa(1, 1, 0.1), xb(1.3, 1.1, 0.15);
	const auto a = observe(w, xa, 0.005, 3, 1), b = observe(w, xb, 0.005, 4, 100);
	const auto small = observe(room(), xa, 0.005, 5, 200);
	VectorMatcher m;
	const MatchResult first = m.match(a, b, TPose2D(0.25, 0.1, 0.1));
	ASSERT_TRUE(first.ok());
	for (int i = 0; i < 20; ++i)
	{
		m.match(small, a, TPose2D(0, 0, 0));  // leaves a different workspace behind
		const MatchResult again = m.match(a, b, TPose2D(0.25, 0.1, 0.1));
		ASSERT_TRUE(again.ok());
		EXPECT_EQ(again.pose.x, first.pose.x);
		EXPECT_EQ(again.pose.y, first.pose.y);
		EXPECT_EQ(again.pose.phi, first.pose.phi);
		EXPECT_EQ(again.pairs, first.pairs);
	}
}

// The Cauchy weights (scale half the line-offset gate, never below the sigma floor): a table and a
// cupboard side that moved 0.1 / 0.08 m between the scans, still inside the final line-offset gate,
// bias the pose by a fraction of their offsets.
TEST(VectorMatcher, MovedFurnitureInsideTheGateBiasesThePoseLittle)
{
	const TPose2D xa(1.0, 1.0, 0.3), xb(1.6, 1.4, 0.45);
	std::vector<WorldSeg> moved = room();
	moved[11] = {6, 4.1, 5.2, 4.7};
	moved[7] = {2.08, 2, 2.08, 3.2};
	const auto a = observe(room(), xa, 0.0, 1, 1);
	const TPose2D truth = relative(xa, xb);
	const TPose2D guess(truth.x + 0.25, truth.y - 0.2, truth.phi + 0.12);
	const VectorMatcher m;
	const MatchResult still = m.match(a, observe(room(), xb, 0.0, 2, 100), guess);
	const MatchResult r = m.match(a, observe(moved, xb, 0.0, 2, 100), guess);
	ASSERT_TRUE(still.ok()) << toString(still.status);
	ASSERT_TRUE(r.ok()) << toString(r.status);
	const double err = std::hypot(r.pose.x - truth.x, r.pose.y - truth.y);
	EXPECT_LT(std::hypot(still.pose.x - truth.x, still.pose.y - truth.y), 1e-6);
	EXPECT_GT(err, 1e-6);  // the moved pieces are in the gates and pull ...
	EXPECT_LT(err, 0.01);  // ... but the Cauchy weights keep it under a tenth of their offsets
}

// matcher.step_within_gates: a wall and a cabinet front 0.45 m before it, turned 3 deg. From a guess
// 0.6-1 m and 5 deg off, the wide first gates pair each with both: a few nearly parallel pairs whose
// residuals disagree, and the full Gauss-Newton step slides metres along them (csail seed 4: the
// first M-step's registration of scans 0 and 48 jumped 12 m and failed).
TEST(VectorMatcher, StepWithinGatesKeepsNearlyParallelPairsFromSendingTheRegistrationAway)
{
	const std::vector<WorldSeg> world = {
		{0, 0, 6, 0}, {0.5, 0.45, 4.5, 0.45 + 4 * std::tan(3 * M_PI / 180)}, {6, 0, 6, 4}, {6, 4, 0, 4}};
	const TPose2D xa(1, 2, 0), xb(2.5, 2.2, 0.3);
	const auto a = observe(world, xa, 0.0, 1, 1), b = observe(world, xb, 0.0, 2, 100);
	const TPose2D truth = relative(xa, xb);
	MatcherOptions off, on;
	off.stepWithinGates = false;  // the full step (on by default)
	on.stepWithinGates = true;
	const VectorMatcher full(off), bounded(on);
	const TPose2D guess(truth.x + 0.8 * std::cos(M_PI / 8), truth.y + 0.8 * std::sin(M_PI / 8),
						truth.phi + 5 * M_PI / 180);
	EXPECT_GT(std::hypot(full.match(a, b, guess).pose.x - guess.x, full.match(a, b, guess).pose.y - guess.y),
			  3.0);  // ran away
	const MatchResult r = bounded.match(a, b, guess);
	ASSERT_TRUE(r.ok()) << toString(r.status);
	EXPECT_LT(std::hypot(r.pose.x - truth.x, r.pose.y - truth.y), 1e-3);
	EXPECT_NEAR(r.pose.phi, truth.phi, 1e-4);
	// guesses 0.6, 0.8, 1 m off in 16 directions, turned +-5 deg: none runs away with the bound
	int fullFar = 0, boundedFar = 0, fullGood = 0, boundedGood = 0;
	for (double d : {0.6, 0.8, 1.0})
		for (int k = 0; k < 16; ++k)
			for (double dphi : {-5.0, 5.0})
			{
				const TPose2D g(truth.x + d * std::cos(k * M_PI / 8), truth.y + d * std::sin(k * M_PI / 8),
								truth.phi + dphi * M_PI / 180);
				const MatchResult f = full.match(a, b, g), s = bounded.match(a, b, g);
				fullFar += std::hypot(f.pose.x - g.x, f.pose.y - g.y) > 2.0;
				boundedFar += std::hypot(s.pose.x - g.x, s.pose.y - g.y) > 2.0;
				fullGood += f.ok() && std::hypot(f.pose.x - truth.x, f.pose.y - truth.y) < 0.01;
				boundedGood += s.ok() && std::hypot(s.pose.x - truth.x, s.pose.y - truth.y) < 0.01;
			}
	EXPECT_GT(fullFar, 0);
	EXPECT_EQ(boundedFar, 0);
	EXPECT_GT(boundedGood, fullGood);
}

TEST(VectorMatcher, StepScaleKeepsTheDirectionWithinBothGates)
{
	MatchGates g;
	g.rho = 0.3;
	g.psi = 0.1;
	EXPECT_DOUBLE_EQ(VectorMatcher::stepScale(Eigen::Vector3d(0.1, 0.1, 0.05), g), 1.0);
	EXPECT_DOUBLE_EQ(VectorMatcher::stepScale(Eigen::Vector3d(3.0, 4.0, 0.0), g), 0.3 / 5.0);
	EXPECT_DOUBLE_EQ(VectorMatcher::stepScale(Eigen::Vector3d(0.0, 0.3, -0.4), g), 0.25);
}
