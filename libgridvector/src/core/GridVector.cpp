#include <gridvector/GridVector.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gridvector
{
using mrpt::math::TPoint2D;

namespace
{
/** Most columns of one vector's grid: 10^7 cells of 0.01 m is a 100 km wall; more (or a NaN length) is
 * corrupt geometry, not a map. */
constexpr double kMaxColumns = 1e7;

int columnsFor(double length, double res)
{
	const double cols = std::ceil(length / res - 1e-9);
	if (!(cols <= kMaxColumns))  // also NaN
		throw std::invalid_argument("GridVector: a vector of " + std::to_string(length) + " m at a resolution of " +
									std::to_string(res) + " m has more than 10^7 cells (corrupt geometry?)");
	return std::max(1, int(cols));
}
}  // namespace

GridVector::GridVector(const TPoint2D& start, const TPoint2D& end, const GridOptions& grid)
	: start_(start),
	  end_(end),
	  res_(grid.resolution),
	  halfWidth_(grid.halfWidth),
	  priorOcc_(float(grid.priorOccupy)),
	  priorVisit_(float(grid.priorVisit))
{
	setGeometry(start, end, columnsFor(std::hypot(end.x - start.x, end.y - start.y), res_));
}

GridVector GridVector::fromParts(const TPoint2D& start, const TPoint2D& end, const GridOptions& grid, int cols,
								 std::vector<GridCell> cells)
{
	GridVector v;  // not GridVector(start, end, grid): that sizes a grid from the length before the cells are checked
	v.res_ = grid.resolution;
	v.halfWidth_ = grid.halfWidth;
	v.priorOcc_ = float(grid.priorOccupy);
	v.priorVisit_ = float(grid.priorVisit);
	if (cols < 1 || cells.size() != size_t(v.rows()) * size_t(cols))
		throw std::invalid_argument("GridVector::fromParts: cell count does not match the grid");
	v.start_ = start;
	v.end_ = end;
	v.updateDirection();
	v.cols_ = cols;
	v.cells_ = std::move(cells);
	return v;
}

// Eq. 2 cells at the counting model's prior (Sec. 3.1: n_occupy = 1/2, n_visit = 1), no point of Algorithm 1 yet.
void GridVector::setGeometry(const TPoint2D& s, const TPoint2D& e, int cols)
{
	start_ = s;
	end_ = e;
	updateDirection();
	cols_ = std::max(1, cols);
	GridCell prior;
	prior.n_occupy = priorOcc_;
	prior.n_visit = priorVisit_;
	cells_.assign(size_t(rows()) * cols_, prior);
}

// Sec. 3.1 (after Eq. 3): psi = atan2(y_e - y_s, x_e - x_s), (x_c, y_c) = (s + e) / 2, l = |e - s|.
double GridVector::psi() const { return std::atan2(end_.y - start_.y, end_.x - start_.x); }
TPoint2D GridVector::centre() const { return {(start_.x + end_.x) / 2, (start_.y + end_.y) / 2}; }
double GridVector::length() const { return len_; }
TPoint2D GridVector::direction() const { return dir_; }

void GridVector::updateDirection()
{
	len_ = std::hypot(end_.x - start_.x, end_.y - start_.y);
	dir_ = len_ > 0 ? TPoint2D((end_.x - start_.x) / len_, (end_.y - start_.y) / len_) : TPoint2D(1, 0);
}

TPoint2D GridVector::leftNormal() const
{
	const TPoint2D d = direction();
	return {-d.y, d.x};
}

// Eq. 3 through the centre, the normal theta = psi - pi/2 pointing to the right (the unobserved side, Fig. 1).
Line2D GridVector::line() const
{
	Line2D l;
	l.theta = mrpt::math::wrapToPi(psi() - M_PI / 2);
	const TPoint2D c = centre();
	l.rho = std::cos(l.theta) * c.x + std::sin(l.theta) * c.y;
	return l;
}

TPoint2D GridVector::toGridFrame(const TPoint2D& p) const
{
	const double dx = p.x - start_.x, dy = p.y - start_.y;
	return {dx * dir_.x + dy * dir_.y, dy * dir_.x - dx * dir_.y};
}

bool GridVector::cellOf(const TPoint2D& p, int& row, int& col) const
{
	const TPoint2D g = toGridFrame(p);
	double c = std::floor(g.x / res_);
	const double r = std::floor(g.y / res_ + 0.5) + halfWidth_;
	if (c == cols_ && g.x <= length() + 1e-9) c = cols_ - 1;  // the terminal point itself
	if (c == -1 && g.x >= -1e-9) c = 0;  // the start point, up to rounding
	if (!(c >= 0 && c < cols_ && r >= 0 && r < rows())) return false;  // NaN (a non-finite point) included
	col = int(c);
	row = int(r);
	return true;
}

TPoint2D GridVector::cellCentre(int row, int col) const
{
	const double u = (col + 0.5) * res_, w = (row - halfWidth_) * res_;
	const TPoint2D d = direction(), n = leftNormal();
	return {start_.x + u * d.x + w * n.x, start_.y + u * d.y + w * n.y};
}

// Eq. 2: (x_acc, y_acc) / n_acc, the gravity centre of the beam endpoints in the cell (its centre if none).
TPoint2D GridVector::cellMeanPoint(int row, int col) const
{
	const GridCell& c = cell(row, col);
	if (c.n_acc <= 0) return cellCentre(row, col);
	const double u = col * res_ + c.x_acc / c.n_acc;
	const double w = (row - halfWidth_ - 0.5) * res_ + c.y_acc / c.n_acc;
	const TPoint2D d = direction(), n = leftNormal();
	return {start_.x + u * d.x + w * n.x, start_.y + u * d.y + w * n.y};
}

// Algorithm 1: initialise the cell a beam endpoint drops in.
bool GridVector::addEndpoint(const TPoint2D& p)
{
	int row, col;
	if (!cellOf(p, row, col)) return false;
	const TPoint2D g = toGridFrame(p);
	GridCell& c = cell(row, col);
	c.x_acc += float(g.x - col * res_);
	c.y_acc += float(g.y - (row - halfWidth_ - 0.5) * res_);
	c.n_acc += 1;
	c.n_occupy += 1;
	c.n_visit += 1;
	return true;
}

// Fig. 4: probabilities summed across the width, normalised by the width.
std::vector<double> GridVector::occupancyProfile() const
{
	std::vector<double> prof(size_t(cols_), 0.0);
	for (int c = 0; c < cols_; ++c)
	{
		double s = 0;
		for (int r = 0; r < rows(); ++r) s += cell(r, c).occupancy(priorRatio());
		prof[size_t(c)] = s / rows();
	}
	return prof;
}

// p(c_i = 1) of Eq. 1's c_i (Sec. 3.1): the mean of the Fig. 4 profile.
double GridVector::pStatic() const
{
	const auto prof = occupancyProfile();
	double s = 0;
	for (double v : prof) s += v;
	return prof.empty() ? 0.5 : s / prof.size();
}

double GridVector::totalOccupy() const
{
	double s = 0;
	for (const auto& c : cells_) s += c.n_occupy;
	return s;
}

double GridVector::totalVisit() const
{
	double s = 0;
	for (const auto& c : cells_) s += c.n_visit;
	return s;
}

double GridVector::totalPoints() const
{
	double s = 0;
	for (const auto& c : cells_) s += c.n_acc;
	return s;
}

// m_{i,t} = x_t (+) v_{i,t}: the grid rides in the vector's own frame.
GridVector GridVector::compose(const mrpt::math::TPose2D& pose) const
{
	GridVector out = *this;
	const double c = std::cos(pose.phi), s = std::sin(pose.phi);
	auto tf = [&](const TPoint2D& p) { return TPoint2D(pose.x + c * p.x - s * p.y, pose.y + s * p.x + c * p.y); };
	out.start_ = tf(start_);
	out.end_ = tf(end_);
	out.updateDirection();
	return out;
}

}  // namespace gridvector
