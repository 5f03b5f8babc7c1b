// .ini text that MRPT's reader would pass over silently: keys outside any section, unclosed headers.
#pragma once

#include <string>

namespace gridvector::io
{
/** Throws "path:LINE: ..." for a key before the first section header ("'k = v' is outside any
 * [section]") or a section header without its ']' (MRPT's reader drops such keys, or files them
 * under the previous section, without a word). Comments (';', '#', and MRPT's '//', as its shipped files
 * open with) and blank lines are fine. */
void requireIniLayout(const std::string& text, const std::string& path);
}  // namespace gridvector::io
