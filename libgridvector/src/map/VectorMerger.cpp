#include "map/VectorMerger.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridvector
{
using mrpt::math::TPoint2D;

namespace
{
int columnsFor(double length, double res) { return std::max(1, int(std::ceil(length / res - 1e-9))); }

/** Frame of a directed segment: origin, unit direction d, left normal n. */
struct SegFrame
{
	TPoint2D o, d, n;
	static SegFrame of(const TPoint2D& o, const TPoint2D& d) { return {o, d, {-d.y, d.x}}; }
	void toLocal(double x, double y, double& u, double& w) const
	{
		const double dx = x - o.x, dy = y - o.y;
		u = dx * d.x + dy * d.y;
		w = dx * n.x + dy * n.y;
	}
	TPoint2D toGlobal(double u, double w) const { return {o.x + u * d.x + w * n.x, o.y + u * d.y + w * n.y}; }
};

/** Cells of a grid laid in a SegFrame: column k covers u in
 * [uLo + k res, uLo + (k+1) res), row j is centred on w = (rowMin + j) res. */
struct Lattice
{
	SegFrame f;
	double res = 0.1, uLo = 0;
	int rowMin = 0, rows = 1, cols = 1;

	int rowOf(double w) const { return std::clamp(int(std::lround(w / res)) - rowMin, 0, rows - 1); }
	int colOf(double u) const { return std::clamp(int(std::floor((u - uLo) / res)), 0, cols - 1); }
	/** Counts of a cell of width res centred at (u, w): whole to the row
	 * containing w, split along u between the (at most two) columns its
	 * extent overlaps; outside the lattice they go to the border. */
	template <class F>
	void spread(double u, double w, F&& add) const
	{
		const int r = rowOf(w);
		const double x = (u - uLo) / res - 0.5;  // the cell covers columns [x, x+1)
		const double k = std::floor(x);
		double frac = x - k;
		if (frac < 1e-6) frac = 0;  // aligned lattices: no leakage from rounding
		if (frac > 1 - 1e-6) frac = 1;
		const int k0 = std::clamp(int(k), 0, cols - 1), k1 = std::clamp(int(k) + 1, 0, cols - 1);
		if (frac < 1) add(r, k0, 1 - frac);
		if (frac > 0) add(r, k1, frac);
	}
};

/** Calls f(row, col, cell, centre u/w in lat's frame) for every cell of v. */
template <class F>
void forCellsIn(const GridVector& v, const Lattice& lat, F&& f)
{
	const SegFrame src = SegFrame::of(v.start(), v.direction());
	const double res = v.resolution();
	for (int r = 0; r < v.rows(); ++r)
		for (int c = 0; c < v.cols(); ++c)
		{
			const TPoint2D g = src.toGlobal((c + 0.5) * res, (r - v.halfWidth()) * res);
			double u, w;
			lat.f.toLocal(g.x, g.y, u, w);
			f(r, c, v.cell(r, c), u, w);
		}
}

/** Algorithm 2, temporary grid cell: counts, and accumulators in global coordinates. */
struct TempCell
{
	double occ = 0, visit = 0, n = 0, sx = 0, sy = 0;
};

struct TempGrid
{
	Lattice lat;
	std::vector<TempCell> cells;
	TempCell& at(int r, int c) { return cells[size_t(r) * lat.cols + c]; }
};

const GridVector& referenceOf(const std::vector<const GridVector*>& parts)
{
	const GridVector* best = parts.front();
	double bestPts = -1, bestLen = -1;
	for (const GridVector* p : parts)
	{
		const double pts = p->totalPoints(), len = p->length();
		if (pts > bestPts || (pts == bestPts && len > bestLen)) best = p, bestPts = pts, bestLen = len;
	}
	return *best;
}

void checkParts(const std::vector<const GridVector*>& parts)
{
	if (parts.empty()) throw std::invalid_argument("VectorMerger: nothing to merge");
	for (const GridVector* p : parts)
		if (!p || std::abs(p->resolution() - parts.front()->resolution()) > 1e-12)
			throw std::invalid_argument("VectorMerger: parts must share the grid resolution");
}

// Algorithm 2 lines 1-11: the temporary grid, aligned with the reference part, covering all parts.
// The reference's own cells lie on the temporary lattice: they are copied, not transformed.
TempGrid buildTempGrid(const std::vector<const GridVector*>& parts)
{
	const GridVector& ref = referenceOf(parts);
	TempGrid t;
	t.lat.f = SegFrame::of(ref.start(), ref.direction());
	t.lat.res = ref.resolution();
	const double res = t.lat.res;
	// the reference's cell centres: u in [res/2, (cols-1/2) res], w in [-h res, h res]
	double umin = 0.5 * res, umax = (ref.cols() - 0.5) * res;
	double wmin = -ref.halfWidth() * res, wmax = ref.halfWidth() * res;
	for (const GridVector* p : parts)
		if (p != &ref)
			forCellsIn(*p, t.lat, [&](int, int, const GridCell&, double u, double w) {
				umin = std::min(umin, u), umax = std::max(umax, u);
				wmin = std::min(wmin, w), wmax = std::max(wmax, w);
			});
	const int k0 = int(std::floor(umin / res)), k1 = int(std::floor(umax / res));
	t.lat.uLo = k0 * res;
	t.lat.cols = k1 - k0 + 1;
	t.lat.rowMin = int(std::lround(wmin / res));
	t.lat.rows = int(std::lround(wmax / res)) - t.lat.rowMin + 1;
	t.cells.assign(size_t(t.lat.rows) * t.lat.cols, TempCell{});
	const int h = ref.halfWidth();
	for (int r = 0; r < ref.rows(); ++r)
		for (int c = 0; c < ref.cols(); ++c)
		{
			const GridCell& cell = ref.cell(r, c);
			TempCell& tc = t.at(r - h - t.lat.rowMin, c - k0);
			tc.occ += cell.n_occupy;
			tc.visit += cell.n_visit;
			if (cell.n_acc <= 0) continue;
			// line 5: the gravity centre in global coordinates
			const double u = c * res + cell.x_acc / cell.n_acc, w = (r - h - 0.5) * res + cell.y_acc / cell.n_acc;
			const TPoint2D g = t.lat.f.toGlobal(u, w);
			TempCell& pc = t.at(t.lat.rowOf(w), t.lat.colOf(u));
			pc.n += cell.n_acc;
			pc.sx += cell.n_acc * g.x;
			pc.sy += cell.n_acc * g.y;
		}
	for (const GridVector* p : parts)
		if (p != &ref)
			forCellsIn(*p, t.lat, [&](int r, int c, const GridCell& cell, double u, double w) {
				t.lat.spread(u, w, [&](int tr, int tc, double f) {
					t.at(tr, tc).occ += f * cell.n_occupy;
					t.at(tr, tc).visit += f * cell.n_visit;
				});
				if (cell.n_acc <= 0) return;
				const TPoint2D g = p->cellMeanPoint(r, c);  // line 5: to global coordinates
				double gu, gw;
				t.lat.f.toLocal(g.x, g.y, gu, gw);
				TempCell& tc = t.at(t.lat.rowOf(gw), t.lat.colOf(gu));
				tc.n += cell.n_acc;
				tc.sx += cell.n_acc * g.x;
				tc.sy += cell.n_acc * g.y;
			});
	return t;
}

// Algorithm 2 lines 12-18: E_fit = sum ((x_acc cos + y_acc sin)/n_acc - rho)^2 n_occupy/n_visit.
Line2D fitTemp(const TempGrid& t, const GridVector& ref, bool weighted)
{
	LineMoments m;
	for (const TempCell& c : t.cells)
		if (c.n > 0 && c.visit > 0) m.add(c.sx / c.n, c.sy / c.n, weighted ? c.occ / c.visit : 1.0);
	Line2D l;
	if (!m.fit(l)) return ref.line();
	// orient like the parts: direction (-sin theta, cos theta) along ref's direction
	const TPoint2D d = ref.direction();
	if (-std::sin(l.theta) * d.x + std::cos(l.theta) * d.y < 0)
	{
		l.theta = mrpt::math::wrapToPi(l.theta + M_PI);
		l.rho = -l.rho;
	}
	return l;
}

// Guard: per column of the temporary grid, the mean offset of its points from the fitted line
// (weights n_occupy/n_visit, as the fit of lines 12-18); the largest |mean| over the columns.
double maxColumnOffset(const TempGrid& t, const Line2D& line)
{
	double worst = 0;
	for (int c = 0; c < t.lat.cols; ++c)
	{
		double sw = 0, swd = 0;
		for (int r = 0; r < t.lat.rows; ++r)
		{
			const TempCell& tc = t.cells[size_t(r) * t.lat.cols + c];
			if (tc.n <= 0 || tc.visit <= 0) continue;
			const double w = tc.occ / tc.visit;
			sw += w;
			swd += w * line.distance(TPoint2D(tc.sx / tc.n, tc.sy / tc.n));
		}
		if (sw > 0) worst = std::max(worst, std::abs(swd / sw));
	}
	return worst;
}

int maxHalfWidth(const std::vector<const GridVector*>& parts)
{
	int h = 0;
	for (const GridVector* p : parts) h = std::max(h, p->halfWidth());
	return h;
}

GridVector mergeFitted(const GridVectorConfig& cfg, double regridTolerance, const std::vector<const GridVector*>& parts,
					   const TempGrid& temp, const Line2D& line);

/** Line 20 on the reference's own lattice: the new vector (s, e) lies within
 * `tol` of the reference's axis and starts within `tol` of its start, so the
 * new grid is the reference's grid (extended at the end if needed) and only
 * the other parts are moved into it. Returns false if (s, e) is further out. */
bool onReferenceLattice(const GridVector& ref, const TPoint2D& s, const TPoint2D& e, double tol, double& len)
{
	if (tol <= 0) return false;
	const SegFrame f = SegFrame::of(ref.start(), ref.direction());
	double us, ws, ue, we;
	f.toLocal(s.x, s.y, us, ws);
	f.toLocal(e.x, e.y, ue, we);
	len = std::max(ue, ref.length());
	return std::abs(us) <= tol && std::abs(ws) <= tol && std::abs(we) <= tol && ue >= ref.length() - tol;
}

/** Every part's counts and points moved into `out`, whose lattice is `lat`
 * (`same`: a part already on that lattice, copied cell by cell). */
void resample(const std::vector<const GridVector*>& parts, const Lattice& lat, const GridVector* same, GridVector& out)
{
	const double res = lat.res;
	const int h = out.halfWidth();
	for (const GridVector* p : parts)
	{
		if (p == same)
		{
			for (int r = 0; r < p->rows(); ++r)
				for (int c = 0; c < p->cols(); ++c)
				{
					const GridCell& src = p->cell(r, c);
					GridCell& dst = out.cell(r - p->halfWidth() + h, c);
					dst.n_occupy += src.n_occupy, dst.n_visit += src.n_visit;
					dst.x_acc += src.x_acc, dst.y_acc += src.y_acc, dst.n_acc += src.n_acc;
				}
			continue;
		}
		forCellsIn(*p, lat, [&](int r, int c, const GridCell& cell, double u, double w) {
			lat.spread(u, w, [&](int nr, int nc, double f) {
				out.cell(nr, nc).n_occupy += float(f * cell.n_occupy);
				out.cell(nr, nc).n_visit += float(f * cell.n_visit);
			});
			if (cell.n_acc <= 0) return;
			const TPoint2D g = p->cellMeanPoint(r, c);
			double gu, gw;
			lat.f.toLocal(g.x, g.y, gu, gw);
			const int nr = lat.rowOf(gw), nc = lat.colOf(gu);
			GridCell& dst = out.cell(nr, nc);  // accumulators relative to the cell's lower corner
			dst.x_acc += float(cell.n_acc * (gu - nc * res));
			dst.y_acc += float(cell.n_acc * (gw - (nr - h - 0.5) * res));
			dst.n_acc += cell.n_acc;
		});
	}
}
}  // namespace

VectorMerger::VectorMerger(const GridVectorConfig& cfg, double regridTolerance)
	: cfg_(cfg), regridTolerance_(regridTolerance)
{}

// Algorithm 2 on two grid vectors.
GridVector VectorMerger::merge(const GridVector& a, const GridVector& b) const
{
	return merge(std::vector<const GridVector*>{&a, &b});
}

// Algorithm 2 lines 1-18: the occupancy-weighted least-squares line of the parts.
Line2D VectorMerger::fitLine(const std::vector<const GridVector*>& parts, bool weighted) const
{
	checkParts(parts);
	return fitTemp(buildTempGrid(parts), referenceOf(parts), weighted);
}

double VectorMerger::wallOffset(const std::vector<const GridVector*>& parts) const
{
	checkParts(parts);
	const TempGrid temp = buildTempGrid(parts);
	return maxColumnOffset(temp, fitTemp(temp, referenceOf(parts), true));
}

// Algorithm 2.
GridVector VectorMerger::merge(const std::vector<const GridVector*>& parts) const
{
	checkParts(parts);
	if (parts.size() == 1) return *parts.front();
	const TempGrid temp = buildTempGrid(parts);
	return mergeFitted(cfg_, regridTolerance_, parts, temp, fitTemp(temp, referenceOf(parts), true));
}

// Algorithm 2, refused when the fitted line leaves the parts' wall (map.merge_holds_wall).
bool VectorMerger::tryMerge(const std::vector<const GridVector*>& parts, GridVector& out) const
{
	checkParts(parts);
	if (parts.size() == 1)
	{
		out = *parts.front();
		return true;
	}
	const TempGrid temp = buildTempGrid(parts);
	const Line2D line = fitTemp(temp, referenceOf(parts), true);
	if (cfg_.map.mergeHoldsWall &&
		maxColumnOffset(temp, line) > (maxHalfWidth(parts) + 0.5) * parts.front()->resolution())
		return false;
	out = mergeFitted(cfg_, regridTolerance_, parts, temp, line);
	return true;
}

std::vector<size_t> VectorMerger::mergeGreedy(const GridVector& base, const std::vector<const GridVector*>& candidates,
											  GridVector& out) const
{
	std::vector<const GridVector*> parts{&base};
	parts.insert(parts.end(), candidates.begin(), candidates.end());
	std::vector<size_t> taken;
	if (candidates.empty()) return taken;
	if (tryMerge(parts, out))  // the common case: everything holds
	{
		for (size_t k = 0; k < candidates.size(); ++k) taken.push_back(k);
		return taken;
	}
	parts.resize(1);
	GridVector trial;
	for (size_t k = 0; k < candidates.size(); ++k)
	{
		parts.push_back(candidates[k]);
		if (tryMerge(parts, trial))
		{
			taken.push_back(k);
			out = std::move(trial);
		}
		else
			parts.pop_back();
	}
	return taken;
}

// Algorithm 2, lines 19-20, after the temporary grid (lines 1-11) and the fit (lines 12-18).
namespace
{
GridVector mergeFitted(const GridVectorConfig& cfg, double regridTolerance, const std::vector<const GridVector*>& parts,
					   const TempGrid& temp, const Line2D& line)
{
	const GridVector& ref = referenceOf(parts);

	// line 19: endpoints from the fitted line, the parts' ends and the occupied cells
	const TPoint2D dir(-std::sin(line.theta), std::cos(line.theta));
	const TPoint2D p0 = line.project(ref.start());
	double tmin = 1e300, tmax = -1e300;
	auto extend = [&](double x, double y) {
		const double t = (x - p0.x) * dir.x + (y - p0.y) * dir.y;
		tmin = std::min(tmin, t), tmax = std::max(tmax, t);
	};
	for (const GridVector* p : parts)
	{
		extend(p->start().x, p->start().y);
		extend(p->end().x, p->end().y);
	}
	for (const TempCell& c : temp.cells)
		if (c.n > 0) extend(c.sx / c.n, c.sy / c.n);
	TPoint2D s(p0.x + tmin * dir.x, p0.y + tmin * dir.y), e(p0.x + tmax * dir.x, p0.y + tmax * dir.y);

	// line 20: the new grid, every part's counts and points moved into it
	GridOptions go = cfg.grid;
	go.resolution = ref.resolution();
	go.halfWidth = maxHalfWidth(parts);
	double refLen = 0;
	const bool keep = go.halfWidth == ref.halfWidth() && onReferenceLattice(ref, s, e, regridTolerance, refLen) &&
					  ref.cols() <= columnsFor(refLen, go.resolution) + 1;
	if (keep)  // the same grid up to the tolerance: the reference's start and axis
	{
		s = ref.start();
		e = TPoint2D(s.x + refLen * ref.direction().x, s.y + refLen * ref.direction().y);
	}
	GridVector out(s, e, go);
	Lattice lat;
	lat.f = keep ? SegFrame::of(s, ref.direction()) : SegFrame::of(s, out.direction());
	// columns: the new length, one more if a part's cells reach beyond the end
	// (a part's last column overhangs its end; never more, or the grids of
	// vectors merged again and again would grow without bound)
	double uMax = keep ? (ref.cols() - 0.5) * go.resolution : 0;
	for (const GridVector* p : parts)
		if (!keep || p != &ref)
			forCellsIn(*p, lat, [&](int, int, const GridCell&, double u, double) { uMax = std::max(uMax, u); });
	const int needCols = std::min(int(std::ceil((uMax + 0.5 * go.resolution) / go.resolution - 1e-6)), out.cols() + 1);
	if (needCols > out.cols()) out.setGeometry(s, e, needCols);
	for (auto& c : out.cells()) c = GridCell{0.f, 0.f, 0.f, 0.f, 0.f};
	lat.res = go.resolution;
	lat.rowMin = -go.halfWidth;
	lat.rows = out.rows();
	lat.cols = out.cols();
	resample(parts, lat, keep ? &ref : nullptr, out);

	out.scanIndex = -1;
	out.id = 0;
	out.state = VectorState::Unknown;
	out.mergedCount = 0;
	out.timestamp = 0;
	for (const GridVector* p : parts)
	{
		out.mergedCount += p->mergedCount;
		out.timestamp = std::max(out.timestamp, p->timestamp);
	}
	return out;
}

}  // namespace

}  // namespace gridvector
