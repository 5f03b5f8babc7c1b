// The largest values the readers take from a file: every number that sizes an allocation, a
// loop or a geometry is checked against one of these where it is read (doc/io.md, "Limits").
#pragma once

#include <cstddef>

namespace gridvector::io
{
/** Largest input file (a log, a trajectory, a .gvmap), after gunzip: 1 GiB. Reading holds the whole
 * file in memory, so this bounds the reader's memory (about twice this while the buffer grows). */
constexpr size_t kMaxInputBytes = size_t(1) << 30;
/** Longest line of a text input (CARMEN log, trajectory): a 100000-beam FLASER line with remissions
 * is about 2 MB. */
constexpr size_t kMaxLineBytes = size_t(4) << 20;
/** Largest .ini file: MRPT's own shipped configs are under 40 KB. */
constexpr size_t kMaxConfigBytes = size_t(1) << 20;
/** A named FIFO given as an input must get a writer within this time (open() would block forever) [ms]. */
constexpr int kFifoWriterWaitMs = 3000;

/** Most beams in one scan: 100000 (a 0.01 deg scanner over 360 deg is 36000). */
constexpr size_t kMaxBeams = 100000;
/** Longest max range a 2D scanner may declare; readings beyond it are invalid beams anyway [m]. */
constexpr double kMaxRangeLimit = 1000.0;
/** Farthest a laser may sit from the robot's origin (robots are a few metres across) [m]. */
constexpr double kMaxSensorOffset = 10.0;
/** Largest |x|, |y| of a robot pose: Earth-sized, so UTM coordinates fit [m]. */
constexpr double kMaxCoordinate = 1e7;
/** Largest |angle| read: a start angle, a yaw, a heading, before wrapping [rad]. */
constexpr double kMaxAngle = 1000.0;
/** Widest aperture of one scan: a full turn plus a float's rounding [rad]. */
constexpr double kMaxApertureRad = 6.2832;
/** Longest string in a rawlog object (a sensor label) [bytes]. */
constexpr size_t kMaxRawlogString = 4096;
/** Most objects in one sensory frame or action collection. */
constexpr size_t kMaxRawlogChildren = 10000;

}  // namespace gridvector::io
