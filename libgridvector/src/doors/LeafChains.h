// Beyond the paper: a door leaf that Fig. 4's split cut into a short dynamic piece and a collinear
// static piece (the part of an open leaf never seen through after the door closed stays static)
// is one door candidate.
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>

#include <utility>
#include <vector>

namespace gridvector::doors
{
/** The pieces of one leaf meet end to end within this: one grid cell, where Fig. 4's split
 * cuts [m]. */
constexpr double kLeafChainGap = 0.10;
/** ... and turn by at most this at the joint: one straight leaf, turned less than a corner
 * (doors.min_corner_angle_deg's default) [deg]. */
constexpr double kLeafChainMaxTurnDeg = 10.0;

/** The vectors with every leaf chain appended as one dynamic candidate: a dynamic piece shorter
 * than min_door_length and a static one no longer than max_door_length, end to end, together of
 * door length (two dynamic pieces are not: people's tracks). */
class LeafChains
{
   public:
	LeafChains(const std::vector<GridVector>& vectors, const DoorOptions& opts);

	/** The input vectors, then one candidate per chain. */
	const std::vector<GridVector>& vectors() const { return v_; }
	/** Indices into vectors() as indices into the input: a chain's are its two pieces
	 * (ascending, each once). */
	std::vector<size_t> pieces(const std::vector<size_t>& indices) const;

   private:
	std::vector<GridVector> v_;
	size_t n_;  //!< input vectors
	std::vector<std::pair<size_t, size_t>> parts_;  //!< per chain: its dynamic and static piece
};

}  // namespace gridvector::doors
