// The tools' JSON outputs (report.json, memory.json): built with nlohmann::ordered_json (keys in
// insertion order), written as dump(2) gives them ("key": value, two-space indent), atomically.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace gridvector::io
{
/** j.dump(2) and a newline. JSON has no NaN or infinity: a non-finite number is written as null
 * (nlohmann's dump); a string that is not valid UTF-8 (a Latin-1 file name) has its bad bytes
 * replaced by U+FFFD rather than failing the run. */
std::string jsonText(const nlohmann::ordered_json& j);

/** jsonText(j) written atomically (writeFileAtomically); throws "path: cannot write (...)". */
void writeJsonFile(const std::string& path, const nlohmann::ordered_json& j);

}  // namespace gridvector::io
