#include "extraction/VectorExtractor.h"
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "test_scans.h"

using namespace gridvector;
using mrpt::math::TPoint2D;
using mrpt::math::TPose2D;

namespace
{
double angDiff(double a, double b) { return std::abs(std::remainder(a - b, 2 * M_PI)); }

bool sensorOnLeft(const GridVector& v, const TPoint2D& s)
{
	return (v.end().x - v.start().x) * (s.y - v.start().y) - (v.end().y - v.start().y) * (s.x - v.start().x) > 0;
}

// The vector matching a true wall (same direction up to sign) or nullptr.
const GridVector* findWall(const LocalScan& ls, const gvtest::Seg& w)
{
	const double wpsi = std::atan2(w.y2 - w.y1, w.x2 - w.x1);
	for (const auto& v : ls.vectors)
	{
		if (std::min(angDiff(v.psi(), wpsi), angDiff(v.psi(), wpsi + M_PI)) > 0.05) continue;
		const TPoint2D c = v.centre();
		const double d = std::abs((w.x2 - w.x1) * (w.y1 - c.y) - (w.x1 - c.x) * (w.y2 - w.y1)) /
						 std::hypot(w.x2 - w.x1, w.y2 - w.y1);
		if (d < 0.05) return &v;
	}
	return nullptr;
}

double endpointError(const GridVector& v, const gvtest::Seg& w)
{
	const double a =
		std::max(std::hypot(v.start().x - w.x1, v.start().y - w.y1), std::hypot(v.end().x - w.x2, v.end().y - w.y2));
	const double b =
		std::max(std::hypot(v.start().x - w.x2, v.start().y - w.y2), std::hypot(v.end().x - w.x1, v.end().y - w.y1));
	return std::min(a, b);
}
}  // namespace

TEST(VectorExtractor, RectangularRoomYieldsItsFourWalls)
{
	// Full-circle scan whose seam points exactly at a corner; walls in the sensor frame.
	const double phi = std::atan2(-1.2, -1.5) + M_PI;
	const auto world = gvtest::room(-1.5, -1.2, 2.5, 1.8);
	auto scan = gvtest::castScan(TPose2D(0, 0, phi), world, {}, 1441, 2 * M_PI);
	std::vector<gvtest::Seg> walls;
	const double c = std::cos(-phi), s = std::sin(-phi);
	for (const auto& w : world)
		walls.push_back({c * w.x1 - s * w.y1, s * w.x1 + c * w.y1, c * w.x2 - s * w.y2, s * w.x2 + c * w.y2});
	VectorExtractor ex;
	const LocalScan ls = ex.extract(scan);
	ASSERT_EQ(ls.vectors.size(), 4u);
	for (const auto& w : walls)
	{
		const GridVector* v = findWall(ls, w);
		ASSERT_NE(v, nullptr);
		EXPECT_LT(endpointError(*v, w), 0.02);
		const double wpsi = std::atan2(w.y2 - w.y1, w.x2 - w.x1);
		EXPECT_LT(std::min(angDiff(v->psi(), wpsi), angDiff(v->psi(), wpsi + M_PI)), 0.5 * M_PI / 180);
		EXPECT_TRUE(sensorOnLeft(*v, TPoint2D(0, 0)));
	}
}

TEST(VectorExtractor, NoisyRoomKeepsAnglesWithinHalfDegree)
{
	const auto walls = gvtest::room(-3, -2, 5, 3);
	auto scan = gvtest::castScan(TPose2D(0.3, 0.2, 0.4), walls, {}, 361, M_PI);
	std::mt19937 rng(7);
	std::normal_distribution<float> noise(0.f, 0.01f);
	for (size_t i = 0; i < scan.getScanSize(); ++i)
		if (scan.getScanRangeValidity(i)) scan.setScanRange(i, scan.getScanRange(i) + noise(rng));
	// Scan taken from sensor pose (0.3,0.2,0.4): express walls in that frame.
	const double c = std::cos(-0.4), s = std::sin(-0.4);
	auto tf = [&](double x, double y) {
		return TPoint2D(c * (x - 0.3) - s * (y - 0.2), s * (x - 0.3) + c * (y - 0.2));
	};
	VectorExtractor ex;
	const LocalScan ls = ex.extract(scan);
	ASSERT_GE(ls.vectors.size(), 2u);
	for (const auto& v : ls.vectors)
	{
		EXPECT_TRUE(sensorOnLeft(v, TPoint2D(0, 0)));
		double best = 1e9;
		for (const auto& w : walls)
		{
			const TPoint2D a = tf(w.x1, w.y1), b = tf(w.x2, w.y2);
			const double wpsi = std::atan2(b.y - a.y, b.x - a.x);
			const double d = std::abs((b.x - a.x) * (a.y - v.centre().y) - (a.x - v.centre().x) * (b.y - a.y)) /
							 std::hypot(b.x - a.x, b.y - a.y);
			if (d < 0.05) best = std::min(best, std::min(angDiff(v.psi(), wpsi), angDiff(v.psi(), wpsi + M_PI)));
		}
		EXPECT_LT(best, 0.5 * M_PI / 180) << "vector not on any wall within 0.5 deg";
	}
}

TEST(VectorExtractor, PersonInFrontOfWallDoesNotBridgeTheWall)
{
	const std::vector<gvtest::Seg> wall = {{-5, 3, 5, 3}};
	const gvtest::Disc person{0.5, 2.0, 0.25};
	auto scan = gvtest::castScan(TPose2D(0, 0, M_PI / 2), wall, {person}, 181, M_PI);
	VectorExtractor ex;
	const LocalScan ls = ex.extract(scan);
	ASSERT_GE(ls.vectors.size(), 2u);
	// The shadow of the person on the wall (sensor frame: x forward = world +y).
	size_t wallPieces = 0;
	for (const auto& v : ls.vectors)
	{
		// Any vector must not pass through the person's disc...
		const TPoint2D pc(2.0, -0.5);  // person centre in the sensor frame
		const TPoint2D g = v.toGridFrame(pc);
		const double u = std::clamp(g.x, 0.0, v.length());
		EXPECT_GT(std::hypot(g.x - u, g.y), person.r - 0.05);
		// ...nor can a wall vector span across the shadow behind the person.
		if (std::abs(v.centre().x - 3.0) < 0.05)
		{
			++wallPieces;
			const double y0 = std::min(v.start().y, v.end().y), y1 = std::max(v.start().y, v.end().y);
			EXPECT_FALSE(y0 < -0.5 && y1 > -0.5) << "wall vector bridges the shadow";
		}
		// Nothing wall-length is fitted through the blob.
		if (std::abs(v.centre().x - 2.0) < 0.4)
		{
			EXPECT_LT(v.length(), 0.6);
		}
	}
	EXPECT_EQ(wallPieces, 2u);
}

TEST(VectorExtractor, InvalidReadingsBreakSegments)
{
	const std::vector<gvtest::Seg> wall = {{3, -4, 3, 4}};
	auto scan = gvtest::castScan(TPose2D(0, 0, 0), wall, {}, 181, M_PI);
	VectorExtractor ex;
	ASSERT_EQ(ex.extract(scan).vectors.size(), 1u);
	const float bad[] = {std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(), -1.f, 0.f};
	for (float b : bad)
	{
		auto s2 = scan;
		s2.setScanRange(90, b);  // straight ahead, validity flag still true
		const LocalScan ls = ex.extract(s2);
		EXPECT_EQ(ls.vectors.size(), 2u) << "reading " << b;
		EXPECT_EQ(ls.validBeams, ex.extract(scan).validBeams - 1);
	}
	auto s3 = scan;
	s3.setScanRangeValidity(90, false);
	EXPECT_EQ(ex.extract(s3).vectors.size(), 2u);
	auto s4 = scan;
	s4.setScanRange(90, s4.maxRange);  // no hit
	EXPECT_EQ(ex.extract(s4).vectors.size(), 2u);
}

TEST(VectorExtractor, EmptyAndDegenerateScansGiveNoVectors)
{
	VectorExtractor ex;
	mrpt::obs::CObservation2DRangeScan empty;
	EXPECT_TRUE(ex.extract(empty).vectors.empty());
	auto scan = gvtest::castScan(TPose2D(0, 0, 0), {}, {}, 181, M_PI);  // nothing in range
	EXPECT_TRUE(ex.extract(scan).vectors.empty());
}

TEST(VectorExtractor, SensorPoseAndScanDirectionAreRespected)
{
	const std::vector<gvtest::Seg> wall = {{3, -4, 3, 4}};
	// Sensor mounted 0.5 m ahead of the robot: the robot sees the wall at x = 3.5.
	auto scan = gvtest::castScan(TPose2D(0, 0, 0), wall, {}, 181, M_PI);
	scan.sensorPose = mrpt::poses::CPose3D(0.5, 0, 0.3, 0, 0, 0);
	VectorExtractor ex;
	LocalScan ls = ex.extract(scan);
	ASSERT_EQ(ls.vectors.size(), 1u);
	EXPECT_NEAR(ls.vectors[0].centre().x, 3.5, 1e-6);
	EXPECT_NEAR(ls.sensorOrigin.x, 0.5, 1e-12);
	EXPECT_TRUE(sensorOnLeft(ls.vectors[0], ls.sensorOrigin));
	// Same ranges stored left-to-right: the wall is mirrored (still on x = 3.5) and
	// the direction still keeps the sensor on the left.
	auto flipped = scan;
	flipped.rightToLeft = false;
	for (size_t i = 0; i < scan.getScanSize(); ++i)
		flipped.setScanRange(i, scan.getScanRange(scan.getScanSize() - 1 - i));
	ls = ex.extract(flipped);
	ASSERT_EQ(ls.vectors.size(), 1u);
	EXPECT_NEAR(ls.vectors[0].centre().x, 3.5, 1e-6);
	EXPECT_TRUE(sensorOnLeft(ls.vectors[0], ls.sensorOrigin));
}

TEST(VectorExtractor, Algorithm1InitialisesTheVectorsGrid)
{
	const std::vector<gvtest::Seg> wall = {{3, -1, 3, 1}};
	auto scan = gvtest::castScan(TPose2D(0, 0, 0), wall, {}, 181, M_PI);
	VectorExtractor ex;
	const LocalScan ls = ex.extract(scan);
	ASSERT_EQ(ls.vectors.size(), 1u);
	const GridVector& v = ls.vectors[0];
	size_t valid = 0;
	for (size_t i = 0; i < scan.getScanSize(); ++i) valid += scan.getScanRangeValidity(i);
	EXPECT_NEAR(v.totalPoints(), double(valid), 1e-9);  // every point landed in the grid
	for (int c = 0; c < v.cols(); ++c)
	{
		EXPECT_FLOAT_EQ(v.cell(0, c).n_acc, 0.f);  // noise-free: all in the centre row
		EXPECT_FLOAT_EQ(v.cell(2, c).n_acc, 0.f);
	}
}

TEST(VectorExtractor, BreakpointAllowsTheConfiguredRangeNoise)
{
	// a range step of 0.25 m at 2 m (1 deg beams): beyond break_distance (0.2 m) and the
	// geometric adaptive threshold (2 sin 1 deg / sin 9 deg = 0.223 m); with std. error
	// 0.02 m, Borges & Aldon's 3 sigma (0.06 m) covers it
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = float(M_PI);
	scan.maxRange = 30.f;
	scan.rightToLeft = true;
	scan.stdError = 0.02f;
	scan.resizeScan(181);
	for (size_t i = 0; i < 181; ++i) scan.setScanRange(i, i < 90 ? 2.0f : 2.25f), scan.setScanRangeValidity(i, true);
	auto runs = [&](double sigmas) {
		ExtractionOptions o;
		o.breakNoiseSigmas = sigmas;
		std::vector<TPoint2D> pts;
		std::vector<size_t> starts;
		VectorExtractor(o).scanToRuns(scan, pts, starts);
		return starts;
	};
	EXPECT_EQ(ExtractionOptions().breakNoiseSigmas, 3.0);
	EXPECT_EQ(runs(3.0), (std::vector<size_t>{0}));  // the default: one run
	EXPECT_EQ(runs(0.0), (std::vector<size_t>{0, 90}));  // geometry only: broken at the step
	EXPECT_EQ(runs(1.0), (std::vector<size_t>{0, 90}));  // 0.02 m allowance: still broken
}

// A straight wall seen by a scanner with 0.1 m range noise: split-and-merge at the 0.04 m keys cuts it at its
// noise; raised to 3 x the scan's stdError it keeps it whole. The usual 0.01 m leaves the keys as they are.
TEST(VectorExtractor, FitTolerancesFollowTheScannersRangeNoise)
{
	VectorExtractor ex;
	EXPECT_EQ(ex.tolerance(0.01).split, ExtractionOptions().splitThreshold);
	EXPECT_EQ(ex.tolerance(0.01).merge, ExtractionOptions().mergeThreshold);
	EXPECT_NEAR(ex.tolerance(0.1).split, 0.3, 1e-12);
	EXPECT_EQ(ex.tolerance(50.0).merge, VectorExtractor::kMaxTolerance);
	EXPECT_EQ(ex.tolerance(std::numeric_limits<double>::quiet_NaN()).split, ExtractionOptions().splitThreshold);
	EXPECT_EQ(ex.tolerance(-1.0).split, ExtractionOptions().splitThreshold);

	const std::vector<gvtest::Seg> wall{{3, -4, 3, 4}};
	auto scan = gvtest::castScan(TPose2D(0, 0, 0), wall, {}, 181, M_PI);
	std::mt19937 rng(3);
	std::normal_distribution<float> noise(0.f, 0.1f);
	for (size_t i = 0; i < scan.getScanSize(); ++i)
		if (scan.getScanRangeValidity(i)) scan.setScanRange(i, scan.getScanRange(i) + noise(rng));
	auto longest = [&](float stdError) {
		scan.stdError = stdError;
		double best = 0;
		for (const auto& v : ex.extract(scan).vectors) best = std::max(best, v.length());
		return best;
	};
	EXPECT_LT(longest(0.01f), 2.0);  // the noise read as corners: pieces
	EXPECT_GT(longest(0.1f), 7.5);  // the wall of 8 m in one
}

TEST(VectorExtractor, ScanToPointsIsEveryStrideThValidPointOfScanToRuns)
{
	// invalid beams of every kind (flagged, NaN, inf, too short, at max range), a sensor offset
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = float(M_PI);
	scan.maxRange = 10.f;
	scan.rightToLeft = true;
	scan.sensorPose = mrpt::poses::CPose3D(0.2, -0.1, 0, 0.3, 0, 0);
	scan.resizeScan(181);
	for (size_t i = 0; i < 181; ++i)
	{
		float r = 2.0f + 0.01f * float(i % 37);
		if (i % 11 == 3) r = std::numeric_limits<float>::quiet_NaN();
		if (i % 13 == 5) r = std::numeric_limits<float>::infinity();
		if (i % 17 == 7) r = 0.01f;
		if (i % 19 == 9) r = 10.f;
		scan.setScanRange(i, r), scan.setScanRangeValidity(i, i % 23 != 4);
	}
	const VectorExtractor ex;
	std::vector<TPoint2D> all, some;
	std::vector<size_t> starts;
	ex.scanToRuns(scan, all, starts);
	ASSERT_GT(all.size(), 100u);
	ASSERT_LT(all.size(), 181u);
	for (size_t stride : {1, 2, 7, 20, 500})
	{
		ex.scanToPoints(scan, some, stride);
		ASSERT_EQ(some.size(), (all.size() + stride - 1) / stride) << "stride " << stride;
		for (size_t k = 0; k < some.size(); ++k)
		{
			EXPECT_EQ(some[k].x, all[k * stride].x) << "stride " << stride << " point " << k;
			EXPECT_EQ(some[k].y, all[k * stride].y) << "stride " << stride << " point " << k;
		}
	}
}
