#include "map/BeamWipe.h"

#include <algorithm>
#include <cmath>

namespace gridvector
{
using mrpt::math::TPoint2D;

// The beams of a scan that no vector of its extraction explains.
ScanBeams ScanBeams::of(const mrpt::obs::CObservation2DRangeScan& scan, const LocalScan& own, double minRange)
{
	ScanBeams out;
	const double sx = scan.sensorPose.x(), sy = scan.sensorPose.y(), yaw = scan.sensorPose.yaw();
	out.origin = TPoint2D(sx, sy);
	const size_t n = scan.getScanSize();
	for (size_t i = 0; i < n; ++i)
	{
		const double a0 = n > 1 ? -0.5 * scan.aperture + scan.aperture * double(i) / double(n - 1) : 0.0;
		const double a = yaw + (scan.rightToLeft ? a0 : -a0);
		const float r = scan.getScanRange(i);
		const bool ret = scan.getScanRangeValidity(i) && std::isfinite(r) && r > minRange && r < scan.maxRange;
		const double range = ret ? double(r) : double(scan.maxRange);
		const TPoint2D e(sx + range * std::cos(a), sy + range * std::sin(a));
		if (ret)
		{
			int row, col;
			const bool explained = std::any_of(own.vectors.begin(), own.vectors.end(),
											   [&](const GridVector& v) { return v.cellOf(e, row, col); });
			if (explained) continue;
		}
		out.ends.push_back(e);
		out.returned.push_back(ret ? 1 : 0);
	}
	return out;
}

// Eq. 8 extended: each unexplained beam credited to the cells of the map vectors it crosses.
BeamWipe::Stats BeamWipe::apply(const mrpt::math::TPose2D& x, const ScanBeams& beams, std::vector<GridVector>& map,
								const VectorIndex& index, int64_t ownScan)
{
	Stats st;
	const double c = std::cos(x.phi), s = std::sin(x.phi);
	auto toWorld = [&](const TPoint2D& p) { return TPoint2D(x.x + c * p.x - s * p.y, x.y + s * p.x + c * p.y); };
	const TPoint2D o = toWorld(beams.origin);
	std::vector<uint32_t> cand;
	for (size_t k = 0; k < beams.ends.size(); ++k)
	{
		const TPoint2D e = toWorld(beams.ends[k]);
		const bool ret = beams.returned[k] != 0;
		cand.clear();
		index.query({std::min(o.x, e.x), std::min(o.y, e.y), std::max(o.x, e.x), std::max(o.y, e.y)}, cand);
		st.candidates += cand.size();
		++st.beams;
		for (uint32_t slot : cand)
		{
			GridVector& m = map[slot];
			if (ownScan >= 0 && m.scanIndex == ownScan) continue;
			traverse(m, o, e, [&](int row, int col, bool last) {
				GridCell& cell = m.cell(row, col);
				cell.n_visit += 1.f;
				if (last && ret)
				{
					cell.n_occupy += 1.f;
					++st.cellsHit;
				}
				else
					++st.cellsVisited;
			});
		}
	}
	return st;
}

}  // namespace gridvector
