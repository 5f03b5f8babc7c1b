// "1 scan", "2 scans": a count with its noun in the right number, for messages and summaries.
#pragma once

#include <cstddef>
#include <string>

namespace gridvector::io
{
/** n followed by `singular` when n == 1, else by `plural` (default: singular + "s"). */
std::string counted(size_t n, const std::string& singular, const std::string& plural = "");
/** "does"/"do", "is"/"are", "has"/"have": `one` when n == 1, else `many`. */
inline const char* agree(size_t n, const char* one, const char* many) { return n == 1 ? one : many; }
}  // namespace gridvector::io
