// Sec. 3.2, Algorithm 2 repeated: a vector merged with its correspondents, then the merged vector with its own.
#pragma once

#include <gridvector/GridVector.h>
#include "map/VectorMerger.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace gridvector
{
/** One vector a cascade may merge: its key names it for as long as it is in the
 * pool (a map vector's id, a partial merge's position), and is how a refusal by
 * the guard is remembered. */
struct MergeCandidate
{
	uint64_t key = 0;
	const GridVector* vector = nullptr;
};

/** The vectors a cascade merges into: the global map (GlobalMap::insertVector)
 * or the partial merges of a group the guard refused (GlobalMap::mergeAll). */
struct MergePool
{
	/** v's correspondents (Sec. 3.2 criteria) in the order mergeGreedy tries them. */
	std::function<std::vector<MergeCandidate>(const GridVector& v)> correspondents;
	/** These candidates (of the last correspondents() call) went into the merge: they leave the pool. */
	std::function<void(const std::vector<MergeCandidate>& taken)> absorb;
};

/** What one cascade did. */
struct MergeCascadeStats
{
	size_t merges = 0;  //!< Algorithm 2 runs
	size_t absorbed = 0;  //!< pool vectors merged into the vector
	size_t refused = 0;  //!< correspondents kept apart by the guard (map.merge_holds_wall)
};

/** Beyond the paper (Algorithm 2 merges once): merges of one insertion at most, a bound on its
 * work, not a model choice (the value it had as the key map.merge_cascade_rounds). */
constexpr int kMergeCascadeRounds = 8;

/** Algorithm 2 with every correspondent the guard allows (VectorMerger::mergeGreedy),
 * repeated with the merged vector while it has correspondents in the pool: a merge
 * moves and lengthens the vector, so it may now correspond to vectors the first one
 * did not. At most `maxMerges` merges: a bound on the work of one insertion. A correspondent the guard refused is not
 * offered again. `v` becomes the last merge (unchanged if nothing merged; a merge has id 0, the caller numbers it). */
MergeCascadeStats mergeCascade(const VectorMerger& merger, GridVector& v, const MergePool& pool,
							   int maxMerges = kMergeCascadeRounds);

}  // namespace gridvector
