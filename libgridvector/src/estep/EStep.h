// Sec. 4.1, Eq. 14-15, Fig. 4: the expectation step — static/dynamic vectors.
#pragma once

#include "map/GlobalMap.h"
#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <cstdint>
#include <utility>
#include <vector>

namespace gridvector
{
/** A run of grid columns [first, last) with one state (Fig. 4). */
struct ProfilePiece
{
	int first = 0, last = 0;
	bool isStatic = true;
	int columns() const { return last - first; }
};

/** Output of one E-step over the per-scan vectors m_{i,t}. */
struct EStepResult
{
	/** The children, parent by parent (p(c|m) of Eq. 14 is their state). */
	std::vector<GridVector> children;
	/** M_chd of Eq. 25: children[childrenOf[k][..]] came from parents[k]. */
	std::vector<std::vector<uint32_t>> childrenOf;
	std::vector<ProfilePiece> pieces;  //!< per child: its columns of the parent and its state
	size_t staticCount = 0, dynamicCount = 0;
	double staticLength = 0, dynamicLength = 0;
};

/** Classifies each grid vector from its occupancy profile (Fig. 4): every
 * column at or above estep.static_threshold -> static, every column below ->
 * dynamic, mixed -> split at the threshold crossings and merged until no piece
 * is shorter than estep.min_piece_length. Children are sub-grids of the parent:
 * their cells (and so the posterior, Eq. 5) are the parent's, unchanged; they
 * keep the parent's scanIndex and timestamp and get id childId(parent.id, k). */
class EStep
{
   public:
	explicit EStep(const EStepOptions& opts = {}, const GridOptions& grid = {});

	/** Split-and-merge of a profile (Fig. 4). */
	static std::vector<ProfilePiece> pieces(const std::vector<double>& profile, double threshold, int minColumns);
	/** The occupancy profile along a vector (Fig. 4), one value per column. */
	std::vector<double> profile(const GridVector& v) const;
	/** The children of one vector; `piecesOut`: the column range of each child. */
	std::vector<GridVector> split(const GridVector& parent, std::vector<ProfilePiece>* piecesOut = nullptr) const;
	/** split()'s children for pieces already computed (split(parent, &ps) gave `ps`): no profile. */
	std::vector<GridVector> childrenFrom(const GridVector& parent, const std::vector<ProfilePiece>& ps) const;
	/** The E-step over all vectors, from the current map alone (Sec. 4.1). */
	EStepResult run(const std::vector<GridVector>& parents) const;

	/** Eq. 25: per parent of `now`, did its children M_chd differ from those of `before` (the
	 * last E-step, same parents in the same order)? A difference is any change in the number
	 * of children, their ids, their states (Eq. 14) or their column ranges (Fig. 4's split
	 * points), compared exactly on the integer columns: a split point moving by one column is
	 * a change at any grid resolution, a parent moved rigidly with the trajectory (its length
	 * off by float noise) is none. `before` null: against the state before the first E-step,
	 * where every vector is its own single static child. */
	static std::vector<bool> changedChildren(const EStepResult& now, const EStepResult* before);

	/** The final classification of the converged map's children: every
	 * static child is split again at estep.final_static_threshold (dynamic
	 * children stay dynamic). A static place must be occupied in nearly every
	 * observation (Eq. 6 near 1): a door closed most of the time or an object
	 * that stood still for half the run reads 0.5-0.85. With
	 * estep.final_relative_drop > 0 the threshold of a child is raised to its
	 * profile's median minus that drop: a door closed most of the time reads
	 * 0.8 inside a wall that reads 0.98. A child left whole keeps its id; the
	 * pieces of a split one get new ids above every id in `children` (not
	 * childId(child.id, k): a second generation could meet another parent's
	 * first). `parentIds`: per output vector, the id of the child it came from. */
	std::vector<GridVector> finalSplit(const std::vector<GridVector>& children,
									   std::vector<uint64_t>* parentIds = nullptr) const;

	/** Column runs of a merged vector that hold observations, split where
	 * at least `minGapColumns` consecutive columns have none (n_visit = 0 in
	 * every row: no per-scan vector covered them, e.g. a door opening between
	 * two merged wall pieces; Eq. 6 has an empty sum there). */
	static std::vector<ProfilePiece> observedRuns(const GridVector& v, int minGapColumns);

	/** The merged map (Eq. 4) without its unobserved stretches: each vector
	 * is cut into its observedRuns (gaps of at least estep.min_piece_length),
	 * each piece keeps the state of the vector and the sources (ids of
	 * `inputs`, the vectors given to mergeAll) whose centre projects into it. */
	MergeResult cutUnobserved(const MergeResult& merged, const std::vector<GridVector>& inputs) const;

	/** Children of v (Eq. 14) in which the stretches `dynamicSpans` ([from, to]
	 * in metres from v's start) are dynamic and the rest keeps v's state: a
	 * column is dynamic if its centre lies in a stretch. Used for a door's
	 * states (Sec. 5.4) lying on a static wall. One child: v itself. The
	 * first child keeps v's id; the others get id 0 (the caller numbers them). A static piece
	 * shorter than estep.min_piece_length left beside a stretch becomes dynamic too (Sec. 4.1). */
	std::vector<GridVector> splitSpans(const GridVector& v,
									   const std::vector<std::pair<double, double>>& dynamicSpans) const;

	/** Id of Eq. 14's child k of the vector with id `parentId`: parentId *
	 * 2^kChildBits + k, so the same piece of the same per-scan vector keeps its
	 * id from one E-step to the next (the M-step's Eq. 24-25 bookkeeping compares
	 * ids) and ids sort by (parent, piece). Throws std::overflow_error where that
	 * does not fit: k >= 2^kChildBits (a vector of more than 65536 pieces, 19.7 km
	 * at min_piece_length 0.3) or parentId >= 2^(64 - kChildBits). */
	static uint64_t childId(uint64_t parentId, size_t k);
	static uint64_t parentIdOf(uint64_t childId) { return childId >> kChildBits; }
	static constexpr int kChildBits = 16;

   private:
	/** split() without the ids (a single piece is the parent itself, id included). */
	std::vector<GridVector> pieceVectors(const GridVector& parent, std::vector<ProfilePiece>* piecesOut) const;
	/** One vector per piece (a single piece: the parent itself, id included). */
	std::vector<GridVector> vectorsOf(const GridVector& parent, const std::vector<ProfilePiece>& ps) const;
	/** splitSpans' runs of `staticCols` (1 static, 0 dynamic), a cut static run shorter than
	 * estep.min_piece_length turned dynamic (in `staticCols` too). */
	std::vector<ProfilePiece> joinShortStatic(const GridVector& v, std::vector<double>& staticCols) const;
	GridVector subVector(const GridVector& parent, const ProfilePiece& p) const;

	EStepOptions opts_;
	GridOptions grid_;
};

}  // namespace gridvector
