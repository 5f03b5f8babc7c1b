// Sec. 5.3: "the dynamic doors can be detected gradually in the EM procedure and excluded from
// data associations" — doors (Sec. 5.4) on the map of each E-step, their states kept out of the
// M-step's registrations.
#pragma once

#include "doors/DoorDetector.h"
#include "estep/EStep.h"
#include "map/GlobalMap.h"
#include <gridvector/GridVectorConfig.h>

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace gridvector
{
/** The map of a set of E-step children as the final map is made: split at
 * estep.final_static_threshold (EStep::finalSplit), static and dynamic merged
 * separately (Eq. 4) without their unobserved stretches (EStep::cutUnobserved). */
struct SplitMap
{
	std::vector<GridVector> perScan;  //!< EStep::finalSplit's output: what was merged
	MergeResult staticMap, dynamicMap;
	/** staticMap's then dynamicMap's vectors, state set, ids as merged (not renumbered). */
	std::vector<GridVector> vectors;
	/** Per id of a vector given to the merges (finalSplit's output): the child it came from. */
	std::map<uint64_t, uint64_t> childOf;

	static SplitMap of(const std::vector<GridVector>& children, const EStep& estep, const GridVectorConfig& cfg);
	/** The same, `children` released once split (the final map's peak holds the map once less). */
	static SplitMap of(std::vector<GridVector>&& children, const EStep& estep, const GridVectorConfig& cfg);

   private:
	static SplitMap fromSplit(std::vector<GridVector> split, const std::vector<uint64_t>& parentIds, const EStep& estep,
							  const GridVectorConfig& cfg);
};

/** What one detection kept out. */
struct DoorExclusionFigures
{
	size_t doors = 0;  //!< doors known so far (accumulated over the iterations)
	size_t found = 0;  //!< doors detected on this E-step's map
	size_t excluded = 0;  //!< static children kept out whole (door leaves)
	size_t cut = 0;  //!< static children of which a stretch was kept out (a wall across a door state)
	double seconds = 0;  //!< the map, the detection and the exclusion
};

/** Doors detected after each E-step and accumulated across iterations; each static
 * child that is a door state is kept out of the static children the M-step
 * registers: whole where the child went into a door's leaf, its stretch along a
 * door state otherwise (DoorDetector::stateSpans, cut by EStep::splitSpans). */
class DoorExclusion
{
   public:
	DoorExclusion(const GridVectorConfig& cfg, const EStep& estep);

	/** Detects doors on the map of `children` (global, the E-step's output) and
	 * returns the static children the M-step may register (door states removed or
	 * cut, the rest unchanged). A child found to be a door state stays out as it was
	 * decided then ("gradually": the exclusion only grows). Eq. 25: per scan, the ids
	 * of the children newly kept out are appended to `changedIds`. */
	std::vector<GridVector> apply(const std::vector<GridVector>& children,
								  std::vector<std::vector<uint64_t>>& changedIds, DoorExclusionFigures& fig);

	/** Doors known so far: every door of the last detection, and each door of an
	 * earlier one whose hinge no later door lies within doors.max_vertex_distance of. */
	const std::vector<Door>& doors() const { return doors_; }

	/** Id of the j-th (j >= 1) further static piece of a child cut at door states: the
	 * child's id with j in its top 8 bits. Throws std::overflow_error where that does not fit. */
	static uint64_t pieceId(uint64_t childId, size_t j);

   private:
	void accumulate(const std::vector<Door>& found);
	std::vector<uint64_t> leafChildren(const SplitMap& map, const std::vector<Door>& found) const;
	/** What was decided for a child the first time it was found to be a door state. */
	struct Decision
	{
		bool leaf = false;  //!< it went whole into a door's leaf: out whole
		std::vector<std::pair<double, double>> spans;  //!< else: the stretches along door states [m from its start]
	};
	std::vector<GridVector> keptPieces(const GridVector& child, const Decision& d) const;

	const GridVectorConfig& cfg_;
	const EStep& estep_;
	DoorDetector detector_;
	std::vector<Door> doors_;
	/** Per id of a child found to be a door state (at any call so far): what is kept out. */
	std::map<uint64_t, Decision> decided_;
};

}  // namespace gridvector
