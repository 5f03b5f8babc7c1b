// Sec. 3.2: the global grid vector map M = {x_t (+) V_t}, merged (Eq. 4).
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>
#include "map/ScanWipe.h"
#include "extraction/VectorExtractor.h"
#include "map/VectorIndex.h"
#include "map/VectorMerger.h"

#include <mrpt/math/TPose2D.h>

#include <vector>

namespace gridvector
{
/** Output of GlobalMap::mergeAll(). */
struct MergeResult
{
	std::vector<GridVector> vectors;  //!< the merged map {m_j} (Eq. 4)
	/** sources[k]: ids of the input vectors that went into vectors[k]
	 * (ascending; one id when the input had no correspondent). This is the
	 * correspondence set M_cor of Eq. 25. */
	std::vector<std::vector<uint64_t>> sources;
};

/** The global map: vectors in world coordinates.
 *
 * Sequential mode (insertScan): the new scan's wipe triangles update the
 * vectors already in the map (Eq. 8, through the spatial index), then its
 * vectors are compounded with the pose (m = x (+) v) and inserted, each merged
 * with its correspondents by Algorithm 2 when map.merge_on_insert is set.
 * Cost per scan: O(vectors near the robot), independent of the map's size.
 * Merges go through mergeCascade (VectorMerger::mergeGreedy, the guard map.merge_holds_wall).
 *
 * Batch mode (buildPerScan + mergeAll): the full product of Eq. 8 over all
 * scans, then the merge of Eq. 4; used by the EM loop. */
class GlobalMap
{
   public:
	/** Eq. 8's unit in the sequential map (insertScan): a wipe increment counts the fan's beams
	 * through a cell, the unit of Algorithm 1's endpoint counts, so that scans seen through a place
	 * outweigh the hits it once took (a door seen open, a person walking past). */
	static constexpr bool kSequentialWipeCountsBeams = true;
	/** Eq. 8's unit in the batch product (buildPerScan, the maps the E-step classifies): 1 per cell
	 * and triangle, the paper's Fig. 2, against which the E-step's thresholds are set. */
	static constexpr bool kBatchWipeCountsBeams = false;

	explicit GlobalMap(const GridVectorConfig& cfg = {}, bool wipeCountsBeams = kSequentialWipeCountsBeams);

	void clear();
	bool empty() const { return vectors_.empty(); }
	size_t size() const { return vectors_.size(); }
	const std::vector<GridVector>& vectors() const { return vectors_; }
	const GridVectorConfig& config() const { return cfg_; }
	/** Also rebuilds the spatial index if its bucket size changed. */
	void setConfig(const GridVectorConfig& cfg);
	/** Changes with every modification (clear, setConfig, insertScan, wipe, insertVector,
	 * setVectors) and assignment, so one map object's successive states never share one; a copy
	 * starts with the original's (same content), a moved-from map gets a new one. What a cache of
	 * this object's state keys on. */
	uint64_t revision() const { return revision_.value(); }

	/** Insert V_t observed from robot pose x_t (sequential mode, see above).
	 * Vectors of the map whose scanIndex equals scan.scanIndex (>= 0) are not
	 * wiped by it, and the triangle of a new vector only adds part b (the
	 * beams passing) to the map vectors it is merged into: its endpoints reach
	 * them through its own Algorithm 1 counts, and counting them again as part
	 * c would weigh that scan's hits double. A map vector the new vector
	 * corresponds to but that does not absorb it (the guard refused the merge)
	 * gets the part c too, after the insertion, as with merging off.
	 * New vectors get fresh ids; merged vectors get a fresh id and scanIndex -1. */
	void insertScan(const mrpt::math::TPose2D& robotPose, const LocalScan& scan);

	/** Eq. 8 alone: the scan's triangles applied to the map (parts b and c; not to
	 * the vectors of the scan itself), nothing inserted. */
	ScanWipe::Stats wipe(const mrpt::math::TPose2D& robotPose, const LocalScan& scan);

	/** Insert one vector already in global coordinates (merged with its
	 * correspondents if map.merge_on_insert). Its id is replaced by a fresh one. */
	void insertVector(GridVector m);

	/** Replace the content (deserialisation, EM rebuilds); rebuilds the index. */
	void setVectors(std::vector<GridVector> v);

	/** Indices into vectors() of the map vectors corresponding to v (Sec. 3.2 criteria). */
	std::vector<size_t> correspondents(const GridVector& v) const;

	/** What the last insertScan() did. */
	struct InsertStats
	{
		ScanWipe::Stats wipe;
		size_t inserted = 0;  //!< new vectors of the scan
		size_t merges = 0;  //!< Algorithm 2 runs
		size_t absorbed = 0;  //!< map vectors merged away
		size_t refused = 0;  //!< correspondents kept apart by the guard (map.merge_holds_wall)
	};
	const InsertStats& lastInsertStats() const { return stats_; }
	const VectorIndex& index() const { return index_; }

	/** Sensor position in the world: x_t (+) sensorOrigin (apex of the wipe triangles). */
	static mrpt::math::TPoint2D sensorPosition(const mrpt::math::TPose2D& robotPose, const LocalScan& scan);

	/** Batch Eq. 4 + Eq. 8: all m_{i,t} = x_t (+) v_{i,t}, unmerged, each updated
	 * by the wipe triangles of every *other* scan (earlier and later: the full
	 * product of Eq. 8; a scan's own vectors are counted by Algorithm 1).
	 * Output order: scan by scan, vector by vector; id = position + 1;
	 * scanIndex = scans[t].scanIndex if >= 0, else t; timestamp of the scan.
	 * Throws std::invalid_argument if poses.size() != scans.size().
	 * Eq. 8 through WipeProduct (vector by vector, the same sums as ScanWipe
	 * scan by scan). Cost: O(sum over scans of the vectors near each pose),
	 * which grows with the square of the passes through a place. */
	static std::vector<GridVector> buildPerScan(const std::vector<mrpt::math::TPose2D>& poses,
												const std::vector<LocalScan>& scans, const GridVectorConfig& cfg);

	/** Eq. 4 "merge": groups corresponding vectors (Sec. 3.2 criteria, grown
	 * greedily from the longest vectors, each group's geometry re-estimated as
	 * it grows, so chains along one wall join) and merges each group once by
	 * Algorithm 2 (VectorMerger). A vector without correspondent is copied
	 * unchanged (id and scanIndex kept); merged vectors get ids above the
	 * largest input id and scanIndex -1. Output ordered by each group's first
	 * input position. Inputs must have distinct ids.
	 * A group whose merge the guard refuses (map.merge_holds_wall: a curved
	 * wall) is merged member by member instead, longest first, each into the
	 * partial merges it corresponds to while they hold its wall, as the
	 * sequential insertion does; it then yields several vectors.
	 * groupRounds: a group absorbs the groups its grown span corresponds to at most this often
	 * (beyond the paper; kMergeGroupRounds). */
	static MergeResult mergeAll(const std::vector<GridVector>& vectors, const GridVectorConfig& cfg,
								int groupRounds = kMergeGroupRounds);
	/** mergeAll's bound on a group's growth rounds: a bound on the work of one group, not a
	 * model choice (the value it had as the key map.merge_group_rounds). */
	static constexpr int kMergeGroupRounds = 16;

   private:
	/** What wipeHolding() held back: per new vector of the scan, its segment and
	 * the ids of the map vectors that got part b of its triangle only. */
	struct HeldBack
	{
		mrpt::math::TPoint2D sensor;
		int64_t scanIndex = -1;
		double hitBand = 0;  //!< the scan's (ScanWipe::hitBandFor)
		std::vector<ScanWipe::Segment> segs;
		std::vector<std::vector<uint64_t>> targets;  //!< per segment, ascending
		std::vector<std::pair<uint64_t, Box2D>> boxes;  //!< every target once, with its box
	};
	/** Eq. 8; with `holdBack` (merge_on_insert) part b only from a new vector to the
	 * map vectors it corresponds to, recorded in `held`. */
	ScanWipe::Stats wipeHolding(const mrpt::math::TPose2D& robotPose, const LocalScan& scan, bool holdBack,
								HeldBack& held);
	/** After the insertion: the held-back parts c for the targets still in the map
	 * under their id (a merge gives a fresh id: such a vector absorbed nothing). */
	void completeRefused(HeldBack& held);
	void insertVectors(const mrpt::math::TPose2D& robotPose, const LocalScan& scan);
	void addSlot(GridVector m);
	void removeSlots(std::vector<size_t> slots);
	void rebuildIndex();

	/** A fresh revision for a modification. */
	void modified() { revision_.bump(); }

	/** The state counter: bumped by assignment (and in a move's source) as by a modification,
	 * so GlobalMap's defaulted copy and move keep revision()'s promise. */
	class Revision
	{
	   public:
		Revision() = default;
		Revision(const Revision& o) : value_(o.value_) {}
		Revision(Revision&& o) noexcept : value_(o.value_) { o.bump(); }
		Revision& operator=(const Revision&)
		{
			bump();
			return *this;
		}
		Revision& operator=(Revision&& o) noexcept
		{
			bump(), o.bump();
			return *this;
		}
		void bump() { ++value_; }
		uint64_t value() const { return value_; }

	   private:
		uint64_t value_ = 0;
	};

	GridVectorConfig cfg_;
	bool wipeCountsBeams_;  //!< Eq. 8's unit (kSequentialWipeCountsBeams unless a test sets it)
	std::vector<GridVector> vectors_;
	Revision revision_;
	uint64_t nextId_ = 1;
	VectorIndex index_;
	ScanWipe wiper_;
	VectorMerger merger_;
	InsertStats stats_;
};

}  // namespace gridvector
