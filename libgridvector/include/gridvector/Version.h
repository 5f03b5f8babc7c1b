// The version of the library, of the source it was built from, and of MRPT (every tool's --version).
#pragma once

#include <string>

namespace gridvector
{
/** The project version of CMakeLists.txt's project(), e.g. "0.1.0". */
std::string version();
/** `git describe --tags --always --dirty` of the source, refreshed at every build; "unknown" outside git. */
std::string gitDescription();
/** The MRPT version the library was compiled against, e.g. "2.5.8". */
std::string mrptVersion();
/** "PROGRAM (gridvector 0.1.0, git DESCRIPTION, MRPT 2.5.8)", the line every tool's --version prints. */
std::string versionLine(const std::string& program);
}  // namespace gridvector
