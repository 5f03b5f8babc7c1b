// Sec. 3.2 + Sec. 4.1 in sequential mode: the per-scan vectors m_{i,t} = x_t (+) v_{i,t} with the full
// product of Eq. 8 kept up to date scan by scan, and the E-step (Eq. 14-15, Fig. 4) run on the vectors
// each scan changed, so every vector's state is known at once and is the batch E-step's.
#pragma once

#include "estep/EStep.h"
#include "map/ScanWipe.h"
#include "map/VectorIndex.h"
#include "map/WipeTriangle.h"

#include <gridvector/GridVectorConfig.h>
#include <gridvector/LocalScan.h>

#include <mrpt/math/TPose2D.h>

#include <cstdint>
#include <vector>

namespace gridvector
{
/** The batch E-step's map (EStep::run on GlobalMap::buildPerScan) built one scan at a time.
 *
 * insert(): the scan's vectors m_{i,t} in world coordinates; Eq. 8 both ways: the scan's wipe
 * triangles over the earlier per-scan vectors they reach, and the earlier scans' triangles over the
 * new vectors (found through an index of every triangle so far). Every cell gets the increments of
 * WipeProduct in its order (scan by scan ascending, the per-cell unit kBatchWipeCountsBeams), so after
 * the same scans at the same poses perScan() equals buildPerScan's output bit for bit, and the E-step's
 * verdicts equal the batch's. Fig. 4's split-and-merge (EStep::split) runs on a vector whose cells
 * changed when its state is next asked (stateOf, piecesOf, children: O(that vector)), its pieces cached;
 * so a query may write the cache, and queries from several threads need a lock. An earlier scan seeing through a place counts as a later one does:
 * a person standing where the robot saw the wall before is dynamic at once, as in the batch.
 *
 * Cost of a scan: the per-scan vectors and triangles that meet its triangles and vectors, i.e. those of
 * the passes through the robot's surroundings (as buildPerScan's per scan), not the map's size. Memory:
 * every keyframe's vectors and triangles (the map of the batch's E-step). */
class ClassifiedMap
{
   public:
	explicit ClassifiedMap(const GridVectorConfig& cfg = {});

	/** Inserts the scan observed from `pose`; returns how many vectors it changed (their state is
	 * Fig. 4's on their new cells from now on). */
	size_t insert(const mrpt::math::TPose2D& pose, const LocalScan& scan);

	/** The per-scan vectors so far, Eq. 8 over every scan inserted (ids: position + 1, as buildPerScan). */
	const std::vector<GridVector>& perScan() const { return vectors_; }
	size_t size() const { return vectors_.size(); }
	size_t scans() const { return scans_; }

	/** Eq. 14 for one per-scan vector as of now: Static or Dynamic when all its pieces (Fig. 4)
	 * agree, Unknown when it is part static and part dynamic or not in the map. */
	VectorState stateOf(const GridVector& v) const;
	/** Fig. 4's pieces of a per-scan vector by id (null: not in the map). */
	const std::vector<ProfilePiece>* piecesOf(uint64_t id) const;

	/** Every per-scan vector split into its children (Eq. 14) from the cached pieces: EStep::run's children. */
	std::vector<GridVector> children() const;

   private:
	/** Eq. 8 of the triangles tris_[cand] (one scan's or several, ascending) on vector m, scan by scan. */
	bool applyTriangles(GridVector& m, const std::vector<uint32_t>& cand);

	GridVectorConfig cfg_;
	EStep estep_;
	std::vector<GridVector> vectors_;  //!< m_{i,t}, scan by scan
	std::vector<WipeTriangle> tris_;  //!< per vector: its triangle from its scan's sensor
	std::vector<uint32_t> scanOf_;  //!< per vector: its scan's insertion number
	/** Fig. 4's pieces of a vector, split again first if its cells changed since. */
	const std::vector<ProfilePiece>& fresh(size_t slot) const;
	mutable std::vector<std::vector<ProfilePiece>> pieces_;  //!< per vector: Fig. 4's pieces (fresh())
	mutable std::vector<bool> stale_;  //!< per vector: cells changed since its pieces were made
	VectorIndex index_, triIndex_;  //!< vectors by band box, non-degenerate triangles by box
	size_t scans_ = 0;
	std::vector<ScanWipe::Mark> marks_;  //!< workspace
	std::vector<uint32_t> cand_;  //!< workspace
	std::vector<std::vector<uint32_t>> byVector_;  //!< workspace: per vector, the new scan's triangles reaching it
};

}  // namespace gridvector
