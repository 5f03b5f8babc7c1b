// Sec. 3.1: grid-vector extraction from a 2D range scan by split-and-merge.
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>
#include <gridvector/LocalScan.h>

#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cmath>
#include <vector>

namespace gridvector
{
/** A fitted run of points [first, last] of the ordered scan points. */
struct ScanSegment
{
	size_t first = 0, last = 0;  //!< inclusive indices into the point list
	Line2D line;  //!< least-squares fit (Eq. 3)
	double maxResidual = 0;  //!< largest |distance| of its points to the line
};

class VectorExtractor
{
   public:
	VectorExtractor(const ExtractionOptions& ext = {}, const GridOptions& grid = {});

	/** Extract v_{1,t}..v_{n,t} from a scan (sensorPose, aperture,
	 * rightToLeft and per-beam validity respected; NaN, inf, <= min_range and
	 * >= maxRange readings break segments). */
	LocalScan extract(const mrpt::obs::CObservation2DRangeScan& scan) const;

	/** Valid beam endpoints (robot frame), in scan order, and the index at
	 * which each contiguous run starts (runs break at invalid beams and at
	 * the adaptive breakpoint of Borges & Aldon 2004). */
	void scanToRuns(const mrpt::obs::CObservation2DRangeScan& scan, std::vector<mrpt::math::TPoint2D>& pts,
					std::vector<size_t>& runStarts) const;

	/** Every `stride`-th valid beam endpoint (robot frame): the points scanToRuns lists, at
	 * 0, stride, 2 stride, ..., without the others' transforms or the breakpoints (the likelihood's
	 * decimated points, once per particle). */
	void scanToPoints(const mrpt::obs::CObservation2DRangeScan& scan, std::vector<mrpt::math::TPoint2D>& pts,
					  size_t stride) const;

	/** Split-and-merge's point-to-line tolerances for a scanner of range std. dev. `rangeSigma` [m]. */
	struct FitTolerance
	{
		double split = 0, merge = 0;
	};
	/** split_threshold and merge_threshold, raised to break_noise_sigmas x rangeSigma where the scanner is
	 * noisier (its noise alone would split a straight wall, as the breakpoint's allowance already says), at
	 * most kMaxTolerance (ExtractionOptions::noiseAllowance). With the usual 0.01 m the keys hold unchanged.
	 * A negative or non-finite rangeSigma is unknown: none. */
	FitTolerance tolerance(double rangeSigma) const;
	/** A noise-raised tolerance stops here: the keys' own upper bound [m]. */
	static constexpr double kMaxTolerance = ExtractionOptions::kMaxNoiseAllowance;
	/** A scan's stdError as a range std. dev.: 0 (unknown) if negative or not finite. */
	static double rangeSigmaOf(double stdError) { return std::isfinite(stdError) && stdError > 0 ? stdError : 0.0; }

	/** Split-and-merge over one run of ordered points [first, last], for a scanner of range std. dev.
	 * `rangeSigma` (the scan's stdError; tolerance()). */
	std::vector<ScanSegment> splitAndMerge(const std::vector<mrpt::math::TPoint2D>& pts, size_t first, size_t last,
										   double rangeSigma = 0) const;

	/** Directed grid vector from a fitted segment: endpoints are the
	 * projections of the extreme points, open space (sensor) on the left,
	 * grid initialised by Algorithm 1 with the segment's points. */
	GridVector makeVector(const std::vector<mrpt::math::TPoint2D>& pts, const ScanSegment& seg,
						  const mrpt::math::TPoint2D& sensor) const;

	const ExtractionOptions& extractionOptions() const { return ext_; }
	const GridOptions& gridOptions() const { return grid_; }

   private:
	/** Whether beam i's reading is one scanToRuns keeps (finite, valid, inside the ranges). */
	bool validBeam(const mrpt::obs::CObservation2DRangeScan& scan, size_t i) const;

	void split(const std::vector<mrpt::math::TPoint2D>& pts, const PrefixMoments& pm, size_t i, size_t j,
			   double threshold, std::vector<ScanSegment>& out) const;
	/** LS fit of [i, j] from prefix moments; false if degenerate or, when
	 * maxResidual > 0, if the fit's residual provably exceeds it. */
	bool fitSegment(const std::vector<mrpt::math::TPoint2D>& pts, const PrefixMoments& pm, size_t i, size_t j,
					ScanSegment& seg, double maxResidual = 0) const;

	ExtractionOptions ext_;
	GridOptions grid_;
};

}  // namespace gridvector
