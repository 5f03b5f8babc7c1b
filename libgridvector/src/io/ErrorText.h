// One-line error messages for the command-line tools.
#pragma once

#include <exception>
#include <string>

namespace gridvector
{
/** The essence of an exception's text on one line: for MRPT's multi-line
 * exceptions the innermost "Message:" text, newlines folded, at most
 * `maxLen` characters. */
std::string oneLineError(const std::exception& e, size_t maxLen = 240);
std::string oneLineError(const std::string& text, size_t maxLen = 240);
}  // namespace gridvector
