// Sec. 3.2, Algorithm 2: merging corresponding grid vectors.
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>
#include <gridvector/LineFit.h>

#include <vector>

namespace gridvector
{
/** Algorithm 2. The parts are summed into a temporary grid in global
 * coordinates (aligned with the part holding most points, large enough for
 * all parts): counts added, accumulators (x_acc, y_acc) transformed to global
 * coordinates and added (lines 1-11). The line is fitted by least squares on
 * the temporary cells' gravity centres (x_acc, y_acc)/n_acc, each weighted by
 * its n_occupy/n_visit, so rarely occupied (dynamic) cells hardly pull it
 * (lines 12-18). The endpoints are the extreme projections on the fitted line
 * of the parts' endpoints and of the occupied cells (line 19), and the new
 * grid is formed along the new vector (line 20).
 *
 * Every cell's counts are added, with or without points: the pseudo-code's
 * indentation puts lines 9-10 (n_occupy, n_visit) inside "if n_acc > 0", but
 * the text adds up "the parameters from its corresponding cells" and says the
 * merged grids "hold the same occupancy probability", which the free cells in
 * front of a wall (no endpoint, many passes) would lose otherwise.
 *
 * Posterior kept (Eq. 6): every cell's counts go into the new grid, so the
 * totals of n_occupy, n_visit and n_acc are conserved exactly. Across the
 * vector a cell's counts go to the row whose band contains its centre (no
 * smearing of a wall row into the free row in front of it, however often a
 * vector is re-merged); along the vector they are split between the two
 * columns its extent overlaps, in proportion to the overlap. Where the parts'
 * grids coincide with the new grid (same line, columns on the same lattice)
 * every cell maps onto one cell and Eq. 6 is unchanged at every point; in
 * general it is unchanged for every cell-sized average along the vector.
 * The new grid has the columns of the new length, one more if a part's cells
 * reach beyond the new end (a last column overhangs its vector's end); counts
 * of cells that still fall outside it (parts at an angle, overhanging prior
 * cells) go to the nearest border cell, so a grid never outgrows its vector
 * however often it is merged. The gravity centre of each cell's points moves
 * to the new cell containing it, at its exact position.
 *
 * Line 20 on the reference's lattice (kRegridTolerance): when the
 * new vector starts within the tolerance of the reference part's start and its
 * line stays within the tolerance of the reference's axis over its length,
 * the new grid is the reference's grid (extended at the end): the
 * reference's cells are kept as they are, only the other parts are moved into
 * it. Merging a short new view into a long wall then costs O(the new view)
 * for the moved cells plus a copy of the wall, instead of a resampling of the
 * whole wall, and the wall's counts are not smeared along it by repeated
 * sub-millimetre refits. The fit itself (lines 12-18) always uses every cell.
 *
 * Merging N parts at once equals N-1 pairwise merges of Algorithm 2 with one
 * fit and one resampling instead of N-1 of each.
 *
 * Guard (map.merge_holds_wall, beyond the paper; tryMerge, mergeGreedy): the
 * criteria of Sec. 3.2 compare two vectors, so pieces of a curved or bent
 * wall (each within 10 deg / 0.15 m of the previous merge) chain into one long
 * chord: on the corrected Intel log the corridor walls are arcs with up to
 * 0.5 m sagitta over 12 m, and the chords end 5-7 deg off the wall at their
 * ends. Such a merge moves the wall out of the new grid (its counts are
 * clamped into the border rows, away from where they were observed), which
 * is what "merging must not change the posterior" forbids. The guard
 * measures, in every column of the temporary grid, the occupancy-weighted
 * mean offset of the parts' points (the gravity centres of lines 1-11, with
 * the weights n_occupy/n_visit of the fit) from the fitted line, and refuses
 * the merge when one lies outside the new grid's band, (h + 1/2) res. */
class VectorMerger
{
   public:
	/** Algorithm 2 line 20 keeps the reference's grid when the new vector lies within this of it:
	 * a numerical tolerance (half a centimetre, far below any cell), not a model choice [m]. */
	static constexpr double kRegridTolerance = 0.005;

	/** regridTolerance: kRegridTolerance; 0 always builds a new grid on the fitted line (line 19). */
	explicit VectorMerger(const GridVectorConfig& cfg = {}, double regridTolerance = kRegridTolerance);

	GridVector merge(const GridVector& a, const GridVector& b) const;
	/** Merge any number (>= 1) of corresponding vectors of the same grid
	 * resolution; throws std::invalid_argument otherwise. The result has
	 * scanIndex -1, the latest timestamp, mergedCount the sum, state Unknown
	 * and id 0 (the caller numbers it). */
	GridVector merge(const std::vector<const GridVector*>& parts) const;

	/** merge(parts) if the new grid holds the parts' wall (see the guard
	 * above; always when map.merge_holds_wall is false), else false and `out`
	 * untouched. */
	bool tryMerge(const std::vector<const GridVector*>& parts, GridVector& out) const;

	/** `base` merged with as many of `candidates` as the guard allows: all of
	 * them if possible (one merge), else one by one in the given order, each
	 * kept if the merge still holds the wall. Returns the positions in
	 * `candidates` merged (ascending; empty: nothing merged, `out` untouched). */
	std::vector<size_t> mergeGreedy(const GridVector& base, const std::vector<const GridVector*>& candidates,
									GridVector& out) const;

	/** The guard's measure: the largest |occupancy-weighted mean offset| of a
	 * temporary-grid column's points from the fitted line [m]. */
	double wallOffset(const std::vector<const GridVector*>& parts) const;

	/** Algorithm 2 lines 1-18 only: the weighted least-squares line of the
	 * parts' temporary grid (normal to the right of the merged direction, as
	 * GridVector::line()). weighted=false gives the plain fit, for comparison. */
	Line2D fitLine(const std::vector<const GridVector*>& parts, bool weighted = true) const;

	const GridVectorConfig& config() const { return cfg_; }

   private:
	GridVectorConfig cfg_;
	double regridTolerance_ = kRegridTolerance;
};

}  // namespace gridvector
