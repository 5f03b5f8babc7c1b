// The false-static breakdown of a map against gv-sim's truth: static vector
// length off every true wall, attributed to the nearest dynamic truth (Sec. 4.1:
// what Eq. 14 kept static that is not; Sec. 5.4: doors seen in one or two states),
// and how each door was seen, pass by pass.
#pragma once

#include "eval/MapEval.h"

#include <string>
#include <vector>

namespace gridvector::eval
{
/** One pass of the laser by a door: a run of its leaf hits (truth_dynamic.txt)
 * with no gap longer than MapEvalOptions::doorPassGap; the leaf angles seen, relative to closed. */
struct DoorPass
{
	double t0 = 0, t1 = 0;  //!< first and last hit run [s]
	size_t runs = 0;  //!< hit runs (scans that hit the leaf with >= 2 beams)
	bool angled = false;  //!< some run showed a leaf state (showsLeafState) to give an angle
	double minDeg = 0, maxDeg = 0;  //!< leaf angles seen from closed [deg]
};

/** How one true door was seen. */
struct DoorObservation
{
	int swings = 0;  //!< swings during the run (truth_doors.txt)
	double openDeg = 0;  //!< its open angle from closed [deg]
	bool seenSwinging = false;  //!< the evaluator's test (doorsSeenSwinging)
	std::vector<DoorPass> passes;
	std::vector<sim::DoorSwingTruth> swingTimes;  //!< truth_dynamic.txt door_swing lines
	double falseStatic = 0;  //!< static length attributed to this door [m]
};

struct FalseStaticBreakdown
{
	double total = 0;  //!< static length farther than wallTolerance from every true wall [m]
	double oneStateDoors = 0;  //!< nearest dynamic truth: a door seen in one state only [m]
	double twoStateDoors = 0;  //!< ... a door seen in two states [m]
	double movedObject = 0;  //!< ... the moved object (either place, or its hits) [m]
	double people = 0;  //!< ... a person's hits [m]
	double other = 0;  //!< farther than dynamicTolerance from every dynamic place [m]
	std::vector<DoorObservation> doors;  //!< per true door (truth order)
	double timeOrigin = 0;  //!< formatText prints times from this [s] (e.g. the first truth pose's)
};

/** Each static sample point (every sampleStep) farther than wallTolerance from
 * every true wall goes to the nearest dynamic place within dynamicTolerance: a
 * door (its swept sector and leaf hits; one-state or two-state by
 * doorsSeenSwinging), the moved object (edges at both places, its hits) or a
 * person (hits); none within reach: "other". The door categories, object and
 * people sum to MapMetrics::ghostLength (same places, same tolerances). */
FalseStaticBreakdown falseStaticBreakdown(const std::vector<MapVector>& vectors, const sim::Truth& truth,
										  const MapEvalOptions& opt = {});

/** Per door: its passes (leaf hits no more than doorPassGap apart) and leaf angles. */
std::vector<DoorObservation> doorObservations(const sim::Truth& truth, const MapEvalOptions& opt = {});

std::string formatText(const FalseStaticBreakdown& b);
/** The totals, and per door false static and passes (gv-eval map --breakdown --json). */
nlohmann::ordered_json toJson(const FalseStaticBreakdown& b);

}  // namespace gridvector::eval
