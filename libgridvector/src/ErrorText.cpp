#include <gridvector/ErrorText.h>

#include <cctype>

namespace gridvector
{
std::string oneLineError(const std::exception& e, size_t maxLen) { return oneLineError(std::string(e.what()), maxLen); }

std::string oneLineError(const std::string& text, size_t maxLen)
{
	// MRPT nests "Message: ..." blocks; the last one is the root cause.
	std::string s = text;
	const auto pos = s.rfind("Message:");
	if (pos != std::string::npos) s = s.substr(pos + 8);
	const auto stack = s.find("==== MRPT exception");
	if (stack != std::string::npos) s = s.substr(0, stack);
	std::string out;
	bool space = false;
	for (char c : s)
	{
		if (std::isspace(static_cast<unsigned char>(c))) space = !out.empty();
		else
		{
			if (space) out += ' ';
			out += c;
			space = false;
		}
	}
	if (out.size() > maxLen) out = out.substr(0, maxLen - 3) + "...";
	return out.empty() ? "unknown error" : out;
}
}  // namespace gridvector
