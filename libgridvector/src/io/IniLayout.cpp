#include "io/IniLayout.h"
#include "io/TextParsing.h"

#include <sstream>
#include <stdexcept>

namespace gridvector::io
{
void requireIniLayout(const std::string& text, const std::string& path)
{
	std::istringstream in(text);
	std::string line;
	bool inSection = false;
	for (size_t n = 1; std::getline(in, line); ++n)
	{
		const size_t b = line.find_first_not_of(" \t\r");
		if (b == std::string::npos || line[b] == ';' || line[b] == '#' || line.compare(b, 2, "//") == 0) continue;
		const auto where = path + ":" + std::to_string(n) + ": ";
		if (line[b] == '[')
		{
			if (line.find(']', b) == std::string::npos) throw std::runtime_error(where + "section header without ']'");
			inSection = true;
		}
		else if (!inSection)
			throw std::runtime_error(where + "'" + printableToken(std::string_view(line).substr(b)) +
									 "' is outside any [section]");  // a binary file's bytes as \xHH
	}
}
}  // namespace gridvector::io
