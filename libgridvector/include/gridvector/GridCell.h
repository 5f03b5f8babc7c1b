// Eq. 2: one cell of a grid vector's slender grid.
#pragma once

namespace gridvector
{
/** c = {(x_acc, y_acc), n_acc, (n_occupy, n_visit)} (Eq. 2).
 *
 * (x_acc, y_acc) accumulate beam endpoints expressed in the owning vector's
 * grid frame (u along the vector, w to its left) *relative to this cell's
 * lower corner*, so floats keep sub-millimetre precision over long runs and
 * the cell survives pose compounding untouched. */
struct GridCell
{
	float x_acc = 0.f;
	float y_acc = 0.f;
	float n_acc = 0.f;
	float n_occupy = 0.5f;
	float n_visit = 1.f;

	/** Counting model: p(occupied) = n_occupy / n_visit (Sec. 3.1); `prior`, the configured
	 * prior_occupy / prior_visit (GridVector::priorRatio()), for a cell with no counts (a cell of a
	 * merged grid that no part covered: Algorithm 2 moves counts, it adds no prior). */
	double occupancy(double prior) const { return n_visit > 0 ? double(n_occupy) / n_visit : prior; }
	bool hasPoints() const { return n_acc > 0; }
};

}  // namespace gridvector
