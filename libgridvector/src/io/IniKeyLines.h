// .ini lines that are neither a key = value, a section header, a comment nor blank: MRPT's
// reader skips them without a word ("resolution 0.05" keeps the default resolution).
#pragma once

#include <string>

namespace gridvector::io
{
/** Throws "path:LINE: 'text' is not 'key = value'" for a line without '=' that is not blank, a
 * comment (';', '#', '//') or a [section] header. */
void requireKeyValueLines(const std::string& text, const std::string& path);
}  // namespace gridvector::io
