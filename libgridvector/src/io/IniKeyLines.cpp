#include "io/IniKeyLines.h"
#include "io/TextParsing.h"

#include <sstream>
#include <stdexcept>

namespace gridvector::io
{
void requireKeyValueLines(const std::string& text, const std::string& path)
{
	std::istringstream in(text);
	std::string line;
	for (size_t n = 1; std::getline(in, line); ++n)
	{
		const size_t b = line.find_first_not_of(" \t\r");
		if (b == std::string::npos || line[b] == ';' || line[b] == '#' || line[b] == '[' ||
			line.compare(b, 2, "//") == 0 || line.find('=', b) != std::string::npos)
			continue;
		size_t e = line.find_last_not_of(" \t\r");
		throw std::runtime_error(path + ":" + std::to_string(n) + ": '" +
								 printableToken(std::string_view(line).substr(b, e + 1 - b)) +
								 "' is not 'key = value' (MRPT would skip the line)");
	}
}
}  // namespace gridvector::io
