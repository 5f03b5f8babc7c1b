// Map quality against gv-sim's truth: static precision and recall, ghost
// length, dynamic detection and door recall (Sec. 4.1 static/dynamic vectors,
// Sec. 5.4 door detection).
#pragma once

#include <mrpt/math/TPose2D.h>

#include "sim/TruthFiles.h"

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace gridvector::eval
{
/** One line of a vectors file: "x1 y1 x2 y2 p_static [static|dynamic]". */
struct MapVector
{
	sim::Segment seg;
	double pStatic = 1;
	bool isStatic = true;  //!< the label column, else p_static >= 0.5
};

/** Reads a vectors file; malformed lines throw "file:line: what is wrong". */
std::vector<MapVector> readVectors(const std::string& path);

/** Moves vectors / door hinges by the rigid transform T: p -> R(T.phi) p + (T.x, T.y)
 * (e.g. alignmentTransform() of the estimated trajectory onto the truth). */
std::vector<MapVector> transformVectors(const std::vector<MapVector>& v, const mrpt::math::TPose2D& T);
std::vector<sim::DoorTruth> transformDoors(const std::vector<sim::DoorTruth>& d, const mrpt::math::TPose2D& T);

struct MapEvalOptions
{
	double wallTolerance = 0.10;  //!< a vector point "on a wall" is within this of it [m]
	double dynamicTolerance = 0.10;  //!< ... on a dynamic hit / object / door sweep [m]
	double doorTolerance = 0.30;  //!< a detected hinge matches a true one within this [m]
	/** A swinging door counts as observed swinging when the laser hit its leaf
	 * (runs of at least doorMinRunLength and doorMinRunBeams) at angles this far apart [deg]. */
	double doorMinStateDiffDeg = 10.0;
	double doorMinRunLength = 0.30;  //!< [m]
	/** A run shows a leaf state only with this many beams: two points fit any
	 * line, a third checks it (no line extractor accepts fewer; gv-em-slam's min_points is 3). */
	int doorMinRunBeams = 3;
	double sampleStep = 0.01;  //!< length integrals are sampled this finely [m]
	double doorPassGap = 2.0;  //!< --breakdown: a door's leaf hits further apart in time than this are two passes [s]
};

struct MapMetrics
{
	double staticLength = 0, dynamicLength = 0;  //!< total vector length per class [m]
	double staticOnWalls = 0;  //!< static length within tolerance of a true static wall [m]
	double staticPrecision = 0;  //!< staticOnWalls / staticLength
	double seenWallLength = 0;  //!< true wall length seen by static beams [m]
	double seenCovered = 0;  //!< ... of it within tolerance of a static vector [m]
	double staticRecall = 0;  //!< seenCovered / seenWallLength
	double ghostLength = 0;  //!< static length off the walls, on dynamic objects / moved object / door sweeps [m]
	double ghostShare = 0;  //!< ghostLength / staticLength
	/** A second, separately labelled ghost figure: the same, but a door whose
	 * leaf the laser saw in one state only (not in two states, see
	 * observedSwingingDoors) is no dynamic place (Sec. 5.4: "if a door never
	 * changes its state, it will be regarded as part of the static
	 * environment"): its sector and leaf hits are left out. ghostLength is unchanged. */
	double ghostLengthSeenSwinging = 0;
	double ghostShareSeenSwinging = 0;  //!< ghostLengthSeenSwinging / staticLength
	/** The precision by the same reading: static length on true walls or on the places
	 * of doors seen in one state only (and no other dynamic place), over staticLength. */
	double staticPrecisionSeenSwinging = 0;
	double dynamicHitLength = 0;  //!< total length of runs of dynamic hits (truth_dynamic.txt) [m]
	double dynamicHitDetected = 0;  //!< ... of it within tolerance of a dynamic vector [m]
	double dynamicDetection = 0;  //!< dynamicHitDetected / dynamicHitLength
	double dynamicOnWalls = 0;  //!< dynamic vector length lying on true static walls [m]
	bool doorsEvaluated = false;
	size_t movingDoors = 0;  //!< true doors that swung during the run
	size_t doorsFound = 0;  //!< ... with a detected hinge within doorTolerance
	size_t detectedDoors = 0, detectedCorrect = 0;
	double doorRecall = 0, doorPrecision = 0;
	/** Sec. 5.4 can only find doors whose motion is in the data ("if a door never
	 * changes its state, it will be regarded as part of the static environment"):
	 * the swinging doors whose leaf the laser saw in two states, and how many of
	 * them were found. */
	size_t observedSwingingDoors = 0, observedDoorsFound = 0;
	double doorRecallObserved = 0;
};

/** Sample points every `step` along a length (at least 1): the count lengths are integrated with.
 * Throws std::invalid_argument above 1e8 (1,000 km at 1 cm: no building's map; the count would
 * overflow int, and sample for hours) or for a length or step that is not finite and positive. */
int sampleCount(double length, double step);

/** Does this truth hit run show a door leaf's state: at least doorMinRunLength long, of at least doorMinRunBeams beams?
 */
bool showsLeafState(const sim::HitRun& h, const MapEvalOptions& opt);
/** Per true door: was its leaf seen in two states, i.e. truth hit runs
 * (truth_dynamic.txt, `hit door`) showing a state (showsLeafState) whose leaf
 * angles differ by doorMinStateDiffDeg or more? */
std::vector<bool> doorsSeenSwinging(const sim::Truth& truth, const MapEvalOptions& opt = {});
/** The leaf angle of a door's hit run from its closed angle [rad] (the run's end
 * farther from the hinge). */
double leafAngle(const sim::HitRun& h, const sim::DoorTruth& d);
/** A door's swept sector as leaves every 3 deg from closed to open. */
std::vector<sim::Segment> doorSweep(const sim::DoorTruth& d);

/** detectedDoors may be null (door recall not evaluated). */
MapMetrics evaluateMap(const std::vector<MapVector>& vectors, const sim::Truth& truth,
					   const std::vector<sim::DoorTruth>* detectedDoors, const MapEvalOptions& opt = {});

std::string formatText(const MapMetrics& m);
nlohmann::ordered_json toJson(
	const MapMetrics& m);  //!< gv-eval map --json (keys in this order; a non-finite figure is null when dumped)

}  // namespace gridvector::eval
