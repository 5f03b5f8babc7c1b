// Reading one serialized MRPT object (a .gvmap, a .simplemap) from a file, gzip or not.
#pragma once

#include <mrpt/serialization/CSerializable.h>

#include <string>

namespace gridvector::io
{
/** Reads `obj` (its class's serialization) from the file at path, gunzipped if compressed.
 * Throws std::runtime_error "path: no such file", "path: cannot open" or
 * "path: not a valid <class> file (<why>)". */
void readObjectFile(const std::string& path, mrpt::serialization::CSerializable& obj);

}  // namespace gridvector::io
