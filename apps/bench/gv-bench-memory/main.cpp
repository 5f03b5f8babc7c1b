// gv-bench-memory: where the bytes of a saved grid vector map go, and how much of its length is
// duplicate (Sec. 3.2: pieces of one wall left unmerged by Algorithm 2).
//
//   gv-bench-memory MAP.gvmap
//
// Also: Eq. 6 over the map and over its CompactMap round trip (the raster of [gridvector_occupancy]),
// and the totals Algorithm 2 conserves, before and after.
//
// Bytes: per-vector overhead (sizeof(GridVector)), cells (sizeof(GridCell)), rows of a vector
// without any evidence (every cell at the prior), cells without evidence.
// Duplicate length: vectors taken longest first; a column of a vector is duplicate when its centre
// lies on an earlier vector's grid (within one cell of its line, inside its length, directions
// within map.max_direction_diff_deg). Each duplicate column is charged to the pair it lies on:
// same state or not, and whether the Sec. 3.2 criteria hold for the pair (they do: the guard or the
// grouping left it; they do not: which criterion fails).
#include "common/ArgParser.h"
#include "io/ObjectFile.h"
#include "map/CompactMap.h"
#include "map/GlobalMap.h"
#include "map/Correspondence.h"
#include "map/MemoryAccounting.h"
#include "map/OccupancyConversion.h"
#include "map/VectorIndex.h"
#include <mrpt/maps/CGridVectorMap.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

using namespace gridvector;

namespace
{
void analyse(const std::vector<GridVector>& vs, const GridVectorConfig& cfg)
{
		const MapOptions& opt = cfg.map;
		const double prior = cfg.grid.priorOccupy / cfg.grid.priorVisit;

		size_t cells = 0, cellsNoEvidence = 0, cellsPoints = 0, rows = 0, rowsNoEvidence = 0, cols = 0;
		double len = 0, lenStatic = 0;
		for (const GridVector& v : vs)
		{
			len += v.length();
			if (v.state == VectorState::Static) lenStatic += v.length();
			cols += size_t(v.cols());
			cells += v.cells().size();
			for (int r = 0; r < v.rows(); ++r)
			{
				bool any = false;
				for (int c = 0; c < v.cols(); ++c)
				{
					const GridCell& g = v.cell(r, c);
					const bool ev = g.n_acc > 0 || std::abs(g.occupancy(prior) - prior) > 1e-6;
					any |= ev;
					cellsNoEvidence += !ev;
					cellsPoints += g.n_acc > 0;
				}
				++rows;
				rowsNoEvidence += !any;
			}
		}
		// CompactMap's bytes by part: per cell kind (2 bits) and values (half floats: 2 B), points (n_acc varint, 2 B centre)
		size_t kPrior = 0, kObserved = 0, kPoints = 0, pointBytes = 0;
		for (const GridVector& v : vs)
			for (const GridCell& g : v.cells())
			{
				if (g.n_acc > 0)
				{
					++kPoints;
					pointBytes += 2 + (g.n_acc < 128 ? 1 : g.n_acc < 16384 ? 2 : 3);
				}
				else if (g.n_occupy == 0 && g.n_visit == 0)
					continue;
				else if (std::abs(g.n_occupy - prior * g.n_visit) <= 1e-6 * g.n_visit)
					++kPrior;
				else
					++kObserved;
			}
		const size_t valueBytes = 2 * kPrior + 4 * (kObserved + kPoints) + pointBytes;
		const size_t compactBytes = CompactMap::encode(vs).bytes().size();
		std::printf("compact: %zu B = kinds %zu + counts %zu (prior %zu, observed %zu, with points %zu cells) + points %zu + "
					"per-vector %zu (%.1f B/vector)\n",
					compactBytes, (cells * 2 + 7) / 8, valueBytes - pointBytes, kPrior, kObserved, kPoints, pointBytes,
					compactBytes - (cells * 2 + 7) / 8 - valueBytes,
					double(compactBytes - (cells * 2 + 7) / 8 - valueBytes) / std::max<size_t>(vs.size(), 1));
		std::printf("vectors %zu, length %.1f m (static %.1f), columns %zu, cells %zu\n", vs.size(), len, lenStatic,
					cols, cells);
		std::printf("bytes: overhead %zu (%zu B/vector), cells %zu (%zu B/cell)\n", vs.size() * sizeof(GridVector),
					sizeof(GridVector), cells * sizeof(GridCell), sizeof(GridCell));
		std::printf("cells without evidence %zu (%.1f %%), with points %zu (%.1f %%); rows without evidence %zu of %zu\n",
					cellsNoEvidence, 100.0 * cellsNoEvidence / std::max<size_t>(cells, 1), cellsPoints,
					100.0 * cellsPoints / std::max<size_t>(cells, 1), rowsNoEvidence, rows);

		for (const double cells : {1.0, 2.0})
		{
		// duplicate length: within `cells` cells of the other's line
		std::vector<uint32_t> order(vs.size());
		std::iota(order.begin(), order.end(), 0u);
		std::stable_sort(order.begin(), order.end(), [&](uint32_t a, uint32_t b) { return vs[a].length() > vs[b].length(); });
		VectorIndex index(VectorIndex::kCellSize);
		const double cosMax = std::cos(opt.maxDirectionDiffDeg * M_PI / 180);
		double dup = 0, dupSame = 0, dupOther = 0, dupCorr = 0, failPsi = 0, failRho = 0, failCentre = 0;
		std::vector<uint32_t> cand;
		size_t piled = 0;
		for (uint32_t i : order)
		{
			const GridVector& v = vs[i];
			const double res = v.resolution();
			bool anyDup = false;
			for (int c = 0; c < v.cols(); ++c)
			{
				const double u = std::min((c + 0.5) * res, v.length());
				const mrpt::math::TPoint2D p(v.start().x + u * v.direction().x, v.start().y + u * v.direction().y);
				cand.clear();
				index.query(Box2D{p.x - res, p.y - res, p.x + res, p.y + res}, cand);
				for (uint32_t j : cand)
				{
					const GridVector& o = vs[j];
					const double cosPsi = v.direction().x * o.direction().x + v.direction().y * o.direction().y;
					if (cosPsi < cosMax) continue;
					const double du = (p.x - o.start().x) * o.direction().x + (p.y - o.start().y) * o.direction().y;
					const double dw = (p.x - o.start().x) * o.leftNormal().x + (p.y - o.start().y) * o.leftNormal().y;
					if (du < 0 || du > o.length() || std::abs(dw) > cells * res) continue;
					const double step = std::min(res, v.length() - c * res);
					dup += step;
					anyDup = true;
					(o.state == v.state ? dupSame : dupOther) += step;
					if (o.state == v.state)
					{
						const CorrespondenceTest t = testCorrespondence(v, o, opt);
						if (t.match)
							dupCorr += step;
						else if (t.dPsi > opt.maxDirectionDiffDeg * M_PI / 180 || t.dTheta > opt.maxThetaDiffDeg * M_PI / 180)
							failPsi += step;
						else if (t.dRho > opt.maxRhoDiff)
							failRho += step;
						else
							failCentre += step;
					}
					break;
				}
			}
			piled += anyDup;
			index.insert(i, Box2D::of(v));
		}
		std::printf("duplicate length (within %.0f cell(s)) %.1f m of %.1f (%.1f %%); %zu vectors lie partly on another\n", cells, dup, len,
					100 * dup / std::max(len, 1e-9), piled);
		std::printf("  on a vector of the other state %.1f m; of the same state %.1f m: criteria hold %.1f m (guard or "
					"grouping left them), fail on direction %.1f, on rho %.1f, on centre distance %.1f\n",
					dupOther, dupSame, dupCorr, failPsi, failRho, failCentre);
		}
		const MemoryReport mem = MemoryAccounting::account(vs, 0.1);
		std::printf("bytes: grid %zu, working form %zu (ratio %.3f), compact %zu (ratio %.3f, %.2f B/column)\n", mem.bytesGrid,
					mem.bytesWorkingForm, mem.ratioBytesWorkingForm, mem.bytesGridVector, mem.ratioBytes,
					double(mem.bytesGridVector) / std::max<size_t>(mem.columns, 1));
}

/** Eq. 6 of two maps over the same raster: mean |p_a - p_b| over the cells known in either, and the share
 * of them differing by more than 0.01. */
void compareOccupancy(const std::vector<GridVector>& a, const std::vector<GridVector>& b, const GridVectorConfig& cfg)
{
	const OccupancyRaster ra = OccupancyConversion::rasterise(a, cfg.occupancy, cfg.grid);
	double xmin, ymin, xmax, ymax;
	OccupancyConversion::bounds(a, xmin, ymin, xmax, ymax);
	const OccupancyRaster rb = OccupancyConversion::rasterise(b, ra.xMin, ra.yMin, ra.resolution, ra.nx, ra.ny,
															  cfg.occupancy.samplesPerAxis, cfg.occupancy.maxPooling, cfg.grid);
	double sum = 0;
	size_t known = 0, off = 0, flip = 0;
	for (int iy = 0; iy < ra.ny; ++iy)
		for (int ix = 0; ix < ra.nx; ++ix)
		{
			if (!ra.known(ix, iy) && !rb.known(ix, iy)) continue;
			const double d = std::abs(ra.probability(ix, iy) - rb.probability(ix, iy));
			++known, sum += d, off += d > 0.01;
			flip += (ra.probability(ix, iy) > 0.5) != (rb.probability(ix, iy) > 0.5);
		}
	std::printf("Eq. 6 raster: %zu known cells, mean |dp| %.5f, %.2f %% differ by > 0.01, %.2f %% change side of 0.5\n", known,
				sum / std::max<size_t>(known, 1), 100.0 * off / std::max<size_t>(known, 1),
				100.0 * flip / std::max<size_t>(known, 1));
}

void totals(const char* what, const std::vector<GridVector>& vs)
{
	double o = 0, v = 0, n = 0;
	for (const GridVector& g : vs) o += g.totalOccupy(), v += g.totalVisit(), n += g.totalPoints();
	std::printf("%s totals: n_occupy %.3f, n_visit %.3f, n_acc %.3f\n", what, o, v, n);
}
}  // namespace

int main(int argc, char** argv)
{
	io::ArgParser args("gv-bench-memory", "MAP.gvmap");
	return io::runTool(args, argc, argv, [&] {
		args.requirePositional(1, 1);
		mrpt::maps::CGridVectorMap map;
		io::readObjectFile(args.positional()[0], map);
		const GridVectorConfig& cfg = map.globalMap().config();
		analyse(map.vectors(), cfg);
		totals("map", map.vectors());
		const std::vector<GridVector> back = CompactMap::encode(map.vectors()).decode(cfg.grid);
		std::printf("compact round trip: ");
		compareOccupancy(map.vectors(), back, cfg);
		totals("round trip", back);
		return 0;
	});
}
