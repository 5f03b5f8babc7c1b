#include "io/Counted.h"

namespace gridvector::io
{
std::string counted(size_t n, const std::string& singular, const std::string& plural)
{
	return std::to_string(n) + " " + (n == 1 ? singular : plural.empty() ? singular + "s" : plural);
}
}  // namespace gridvector::io
