#include "map/TriangleBuckets.h"
#include "map/VectorIndex.h"
#include "map/WipeProduct.h"
#include "map/WipeTriangle.h"

#include <algorithm>
#include <stdexcept>

namespace gridvector
{
namespace
{
/** Every vector's triangle from its scan's sensor (degenerate ones kept, never indexed). */
std::vector<WipeTriangle> trianglesOf(const std::vector<mrpt::math::TPoint2D>& sensors,
									  const std::vector<size_t>& first, const std::vector<GridVector>& map,
									  const std::vector<double>& hitBands, bool countBeams)
{
	std::vector<WipeTriangle> tris;
	tris.reserve(map.size());
	for (size_t t = 0; t < sensors.size(); ++t)
		for (size_t i = first[t]; i < first[t + 1]; ++i)
		{
			const ScanWipe::Segment v = ScanWipe::segmentOf(map[i]);
			const double density = countBeams ? WipeTriangle::beamDensity(sensors[t], v.start, v.end, v.points) : 0.0;
			tris.emplace_back(sensors[t], v.start, v.end, hitBands[t], density);
		}
	return tris;
}
}  // namespace

// Eq. 8, all scans: each map vector m_{i,p} takes the triangles of every scan q != p, q ascending.
ScanWipe::Stats WipeProduct::apply(const std::vector<mrpt::math::TPoint2D>& sensors, const std::vector<size_t>& first,
								   std::vector<GridVector>& map) const
{
	return apply(sensors, first, map, std::vector<double>(sensors.size(), hitBand_));
}

ScanWipe::Stats WipeProduct::apply(const std::vector<mrpt::math::TPoint2D>& sensors, const std::vector<size_t>& first,
								   std::vector<GridVector>& map, const std::vector<double>& hitBands) const
{
	if (first.size() != sensors.size() + 1 || first.back() != map.size() || hitBands.size() != sensors.size())
		throw std::invalid_argument("WipeProduct: scan ranges do not cover the map");
	ScanWipe::Stats st;
	const std::vector<WipeTriangle> tris = trianglesOf(sensors, first, map, hitBands, beams_);
	std::vector<uint32_t> scanOf(map.size());
	TriangleBuckets index(cell_);
	for (size_t t = 0; t < sensors.size(); ++t)
		for (size_t i = first[t]; i < first[t + 1]; ++i)
		{
			scanOf[i] = uint32_t(t);
			if (tris[i].degenerate()) continue;
			++st.triangles;
			index.insert(uint32_t(i), tris[i]);
		}
	std::vector<uint32_t> cand;
	std::vector<ScanWipe::Mark> marks;
	for (size_t i = 0; i < map.size(); ++i)
	{
		GridVector& m = map[i];
		const Box2D box = Box2D::of(m);
		cand.clear();
		index.query(box, cand);  // ascending: scan by scan, in each vector by vector (ScanWipe's order)
		st.candidates += cand.size();
		cand.erase(std::remove_if(cand.begin(), cand.end(),
								  [&](uint32_t j) {
									  const WipeTriangle& t = tris[j];
									  return scanOf[j] == scanOf[i] ||  // Algorithm 1 counted the scan's own
											 !Box2D{t.minX(), t.minY(), t.maxX(), t.maxY()}.intersects(box) ||
											 t.misses(box.minX, box.minY, box.maxX, box.maxY);
								  }),
				   cand.end());
		for (size_t a = 0, b = 0; a < cand.size(); a = b)
		{
			while (b < cand.size() && scanOf[cand[b]] == scanOf[cand[a]]) ++b;
			if (b == a + 1)
			{
				st.vectorsTouched += ScanWipe::addAlone(tris[cand[a]], m, beams_, st);
				continue;
			}
			if (marks.size() < m.cells().size()) marks.resize(m.cells().size());  // zeroed again by add()
			ScanWipe::Span span;
			for (size_t k = a; k < b; ++k)
				ScanWipe::mark(
					tris[cand[k]], m, WipePart::Hit, beams_, [&] { return marks.data(); }, span);
			if (span.first < span.last) st.vectorsTouched += ScanWipe::add(marks.data(), span, m.cells(), beams_, st);
		}
	}
	return st;
}

}  // namespace gridvector
