// issue 22: geometry a corrupt input could carry into the core must fail or be dropped, never crash
// or recurse without end: GridVector::cellOf with non-finite points, grids sized from absurd
// lengths, the split step on points a line fit cannot take.
#include "extraction/VectorExtractor.h"
#include <gridvector/GridVector.h>

#include <gtest/gtest.h>

#include <cmath>
#include <pthread.h>
#include <limits>

using gridvector::GridVector;
using mrpt::math::TPoint2D;

TEST(BadGeometry, CellOfANonFinitePointIsOutside)
{
	const GridVector v(TPoint2D(0, 0), TPoint2D(1, 0), gridvector::GridOptions{});
	const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
	int row = -7, col = -7;
	for (const TPoint2D p :
		 {TPoint2D(nan, 0), TPoint2D(0, nan), TPoint2D(inf, 0), TPoint2D(-inf, inf), TPoint2D(1e308, 0)})
		EXPECT_FALSE(v.cellOf(p, row, col)) << p.x << " " << p.y;
	EXPECT_EQ(row, -7);
	GridVector w = v;
	EXPECT_FALSE(w.addEndpoint(TPoint2D(nan, nan)));
	EXPECT_TRUE(v.cellOf(TPoint2D(0.55, 0.01), row, col));
	EXPECT_EQ(col, 5);
}

TEST(BadGeometry, AGridOfMoreThanTenMillionColumnsIsAnError)
{
	const gridvector::GridOptions g;  // 0.1 m cells
	EXPECT_THROW(GridVector(TPoint2D(0, 0), TPoint2D(1e15, 0), g), std::invalid_argument);
	EXPECT_THROW(GridVector(TPoint2D(0, 0), TPoint2D(std::nan(""), 0), g), std::invalid_argument);
	EXPECT_NO_THROW(GridVector(TPoint2D(0, 0), TPoint2D(1000, 0), g));
	// fromParts sizes nothing from the length: the stored cells are the grid
	std::vector<gridvector::GridCell> cells(3 * 2);
	const GridVector p = GridVector::fromParts(TPoint2D(0, 0), TPoint2D(1e5, 0), g, 2, cells);
	EXPECT_EQ(p.cols(), 2);
	EXPECT_THROW(GridVector::fromParts(TPoint2D(0, 0), TPoint2D(1, 0), g, 2, std::vector<gridvector::GridCell>(5)),
				 std::invalid_argument);
}

TEST(BadGeometry, SplitEndsOnPointsNoLineFits)
{
	const gridvector::VectorExtractor ex;
	// two points 1e15 m out, non-finite ones, and a long run: the split step terminates
	for (const double far : {1e15, 1e300, std::numeric_limits<double>::infinity()})
	{
		std::vector<TPoint2D> pts = {TPoint2D(far, 1), TPoint2D(far, 1.05)};
		EXPECT_LE(ex.splitAndMerge(pts, 0, 1).size(), 1u) << far;
		pts.assign(9, TPoint2D(far, far));
		EXPECT_LE(ex.splitAndMerge(pts, 0, 8).size(), 8u) << far;
	}
	// A zigzag splits down to pairs, one level per point: an explicit stack, not a 2*10^4-deep recursion,
	// shown on a thread with a 256 KiB stack (a recursion that deep needs megabytes; the split of this
	// worst case is quadratic, so the points are kept few).
	std::vector<TPoint2D> zigzag;
	for (int i = 0; i < 20000; i++) zigzag.emplace_back(0.01 * i, (i % 2) * 0.5);
	struct Job
	{
		const gridvector::VectorExtractor* ex;
		const std::vector<TPoint2D>* pts;
		size_t segments = 0;
	} job{&ex, &zigzag};
	pthread_attr_t attr;
	ASSERT_EQ(pthread_attr_init(&attr), 0);
	ASSERT_EQ(pthread_attr_setstacksize(&attr, 256 * 1024), 0);
	pthread_t thread;
	auto run = [](void* p) -> void* {
		auto* j = static_cast<Job*>(p);
		j->segments = j->ex->splitAndMerge(*j->pts, 0, j->pts->size() - 1).size();
		return nullptr;
	};
	ASSERT_EQ(pthread_create(&thread, &attr, run, &job), 0);
	pthread_join(thread, nullptr);
	pthread_attr_destroy(&attr);
	EXPECT_GT(job.segments, 1000u);
}
