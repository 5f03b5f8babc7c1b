// A rawlog entry walked in its raw bytes before MRPT deserialises it: MRPT's deserialisers size
// their buffers from counts in the stream (a 2D scan's beam count, a sensory frame's observation
// count, a string's length, a motion model's particle count) and trust them.
#pragma once

#include <cstddef>
#include <stdexcept>

namespace gridvector::io
{
enum class EntryCheck
{
	Checked,  //!< every object of the entry is one the reader uses, and every length fits the bytes left
	Unchecked  //!< the entry holds an object of another class (an image, a 3D scan, ...): MRPT reads it as it is
};

/** The entry's fields run past the end of the bytes (a truncated file). */
struct TruncatedEntry : std::runtime_error
{
	TruncatedEntry() : std::runtime_error("truncated or corrupt rawlog (this entry reads past the end of the file)") {}
};

/** Walks the serialised object at bytes[0, size) (MRPT >= 0.5.5 framing: class name, version, payload,
 * end flag 0x88) for the classes the rawlog reader uses: CSensoryFrame, CActionCollection,
 * CObservation2DRangeScan, CObservationOdometry, CActionRobotMovement2D and their CPose2D, CPose3D,
 * CPosePDFGaussian(Inf) and CMatrixF parts. Throws std::runtime_error("what is wrong") for a count,
 * length or enum beyond io/InputLimits.h or the bytes left, or a missing end flag; TruncatedEntry
 * for a field that is not there. */
EntryCheck precheckRawlogEntry(const unsigned char* bytes, size_t size);

}  // namespace gridvector::io
