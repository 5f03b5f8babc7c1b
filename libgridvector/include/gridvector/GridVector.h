// Sec. 3.1, Eq. 1, Fig. 1: a directed segment (open space on its left) with a slender grid.
#pragma once

#include <gridvector/GridCell.h>
#include <gridvector/GridVectorConfig.h>
#include <gridvector/LineFit.h>

#include <mrpt/math/TPoint2D.h>
#include <mrpt/math/TPose2D.h>

#include <cstdint>
#include <vector>

namespace gridvector
{
enum class VectorState : uint8_t
{
	Unknown = 0,
	Static = 1,  //!< c_i = 1
	Dynamic = 2  //!< c_i = 0
};

/** v_{i,t} = [(x_s, y_s), (x_e, y_e)], g_i, c_i, t  (Eq. 1).
 *
 * The grid lives in the vector's own frame: origin at the start point, u axis
 * along the vector, w axis to its left (towards open space). Columns
 * 0..cols()-1 cover u in [k*res, (k+1)*res); rows 0..2h cover
 * w in [(r-h-1/2)*res, (r-h+1/2)*res), so row h is centred on the segment.
 * Pose compounding (m = x (+) v) therefore moves only the endpoints. */
class GridVector
{
   public:
	GridVector() = default;
	/** A vector from start to end with a prior-initialised grid. */
	GridVector(const mrpt::math::TPoint2D& start, const mrpt::math::TPoint2D& end, const GridOptions& grid);

	/** Rebuild a vector from stored parts (deserialisation). Throws
	 * std::invalid_argument if cells.size() != (2*halfWidth+1)*cols. */
	static GridVector fromParts(const mrpt::math::TPoint2D& start, const mrpt::math::TPoint2D& end,
								const GridOptions& grid, int cols, std::vector<GridCell> cells);

	// --- geometry (Sec. 3.1) ---
	const mrpt::math::TPoint2D& start() const { return start_; }
	const mrpt::math::TPoint2D& end() const { return end_; }
	double psi() const;  //!< direction atan2(ye - ys, xe - xs)
	mrpt::math::TPoint2D centre() const;  //!< (x_c, y_c)
	double length() const;  //!< l
	/** Eq. 3 line with the normal pointing to the right of the vector
	 * (away from open space): theta = psi - pi/2, rho signed. */
	Line2D line() const;
	mrpt::math::TPoint2D direction() const;  //!< unit vector along
	mrpt::math::TPoint2D leftNormal() const;  //!< unit vector to the open side

	// --- grid (Eq. 2) ---
	double resolution() const { return res_; }
	int halfWidth() const { return halfWidth_; }
	int rows() const { return 2 * halfWidth_ + 1; }
	int cols() const { return cols_; }
	const std::vector<GridCell>& cells() const { return cells_; }
	std::vector<GridCell>& cells() { return cells_; }
	GridCell& cell(int row, int col) { return cells_[size_t(row) * cols_ + col]; }
	const GridCell& cell(int row, int col) const { return cells_[size_t(row) * cols_ + col]; }
	/** Grid frame (u, w) of a point in the vector's coordinates. */
	mrpt::math::TPoint2D toGridFrame(const mrpt::math::TPoint2D& p) const;
	/** Cell containing point p; false if p is outside the grid. */
	bool cellOf(const mrpt::math::TPoint2D& p, int& row, int& col) const;
	mrpt::math::TPoint2D cellCentre(int row, int col) const;  //!< in the vector's frame
	/** Gravity centre (x_acc, y_acc)/n_acc of a cell in the vector's frame. */
	mrpt::math::TPoint2D cellMeanPoint(int row, int col) const;

	/** The counting model's prior (Sec. 3.1: 1/2 over 1), as the grid was made with. */
	float priorOccupy() const { return priorOcc_; }
	float priorVisit() const { return priorVisit_; }
	/** prior_occupy / prior_visit: what a cell with no counts reads (GridCell::occupancy). */
	double priorRatio() const { return double(priorOcc_) / double(priorVisit_); }

	/** Algorithm 1: add a beam endpoint (vector's frame). False if outside. */
	bool addEndpoint(const mrpt::math::TPoint2D& p);

	// --- probabilities ---
	/** Fig. 4: occupancy profile along the vector, one value per column:
	 * the mean over the width of the cells' n_occupy / n_visit (priorRatio() where a cell has no counts). */
	std::vector<double> occupancyProfile() const;
	/** p(c_i = 1): the mean of the occupancy profile. */
	double pStatic() const;
	/** Totals over all cells (conserved by merging). */
	double totalOccupy() const;
	double totalVisit() const;
	double totalPoints() const;

	// --- pose compounding m = x (+) v (Sec. 3.2) ---
	GridVector compose(const mrpt::math::TPose2D& pose) const;
	/** Same geometry with a new grid and new endpoints (used by Algorithm 2/E-step). */
	void setGeometry(const mrpt::math::TPoint2D& s, const mrpt::math::TPoint2D& e, int cols);

	// --- bookkeeping ---
	int64_t scanIndex = -1;  //!< t: scan (pose) the vector came from, -1 once merged
	double timestamp = 0;  //!< seconds
	uint64_t id = 0;  //!< unique within a map
	VectorState state = VectorState::Unknown;  //!< c_i
	uint32_t mergedCount = 1;  //!< how many per-scan vectors this one stands for

   private:
	void updateDirection();
	mrpt::math::TPoint2D start_{0, 0}, end_{0, 0};
	mrpt::math::TPoint2D dir_{1, 0};  //!< unit vector start -> end (cached: hot path)
	double len_ = 0;  //!< cached length
	double res_ = 0.1;
	int halfWidth_ = 1;
	int cols_ = 0;
	std::vector<GridCell> cells_;
	float priorOcc_ = 0.5f, priorVisit_ = 1.f;
};

}  // namespace gridvector
