#include "io/JsonFile.h"
#include "io/AtomicFile.h"

#include <nlohmann/json.hpp>

namespace gridvector::io
{
std::string jsonText(const nlohmann::ordered_json& j)
{
	return j.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

void writeJsonFile(const std::string& path, const nlohmann::ordered_json& j)
{
	const std::string text = jsonText(j);
	writeFileAtomically(path, [&](std::ostream& o) { o << text; });
}

}  // namespace gridvector::io
