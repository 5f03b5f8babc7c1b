// MRPT archives (rawlogs, simplemaps, .gvmap, .3Dscene) written atomically and checked to the
// last byte: MRPT's gzip stream ignores gzclose's error, so a full disk left a truncated file
// that was renamed over the target and reported as written.
#pragma once

#include <mrpt/serialization/CArchive.h>

#include <functional>
#include <string>

namespace gridvector::io
{
/** Serialises what fill() writes into memory, writes it to a temporary file next to `path`
 * (gzip-compressed unless compress is false), reads the file back and compares, then renames it
 * over `path`. Throws std::runtime_error("path: cannot write (reason)") on any failure (a
 * directory, no permission, a full disk, a file size limit), leaving `path` as it was. */
void writeArchiveFile(const std::string& path, bool compress,
					  const std::function<void(mrpt::serialization::CArchive&)>& fill);
}  // namespace gridvector::io
