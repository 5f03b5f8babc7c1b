#include "io/ErrorText.h"

#include <cctype>
#include <sstream>

namespace gridvector
{
namespace
{
std::string trim(const std::string& s)
{
	size_t a = 0, b = s.size();
	while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
	while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
	return s.substr(a, b - a);
}

bool startsWith(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

// Length of the well-formed multi-byte UTF-8 sequence at s[i], 0 if there is none.
size_t utf8Length(const std::string& s, size_t i)
{
	const auto b = static_cast<unsigned char>(s[i]);
	const size_t n = b >= 0xc2 && b <= 0xdf ? 2 : b >= 0xe0 && b <= 0xef ? 3 : b >= 0xf0 && b <= 0xf4 ? 4 : 0;
	if (n == 0 || i + n > s.size()) return 0;
	for (size_t k = 1; k < n; ++k)
		if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return 0;
	return n;
}

// A backtrace frame: "[12] 0x..." or "[0 ] ...".
bool isFrame(const std::string& s)
{
	size_t i = 1;
	if (s.empty() || s[0] != '[') return false;
	while (i < s.size() && s[i] == ' ') ++i;
	const size_t digits = i;
	while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
	if (i == digits) return false;
	while (i < s.size() && s[i] == ' ') ++i;
	return i < s.size() && s[i] == ']';
}
}  // namespace

std::string oneLineError(const std::exception& e, size_t maxLen) { return oneLineError(std::string(e.what()), maxLen); }

// MRPT exceptions nest blocks of "Message:", "Location:", "Call stack backtrace:"
// and frame lines; keep only the message text, innermost (last) first.
std::string oneLineError(const std::string& text, size_t maxLen)
{
	std::istringstream in(text);
	std::string line, out, lastMessage;
	bool inStack = false;
	while (std::getline(in, line))
	{
		line = trim(line);
		if (line.empty() || startsWith(line, "====")) continue;
		if (startsWith(line, "Call stack backtrace"))
		{
			inStack = true;
			continue;
		}
		if (startsWith(line, "Location:"))
		{
			inStack = false;
			continue;
		}
		if (startsWith(line, "Message:"))
		{
			inStack = false;
			lastMessage = trim(line.substr(8));
			continue;
		}
		if (inStack || isFrame(line)) continue;
		if (!lastMessage.empty())
			lastMessage += ' ' + line;
		else
			out += (out.empty() ? "" : " ") + line;
	}
	std::string s;
	const std::string& text1 = lastMessage.empty() ? out : lastMessage;
	for (size_t i = 0; i < text1.size(); ++i)
	{
		const char c = text1[i];
		if (std::isspace(static_cast<unsigned char>(c)))
		{
			if (!s.empty() && s.back() != ' ') s += ' ';
		}
		else if (const size_t n = utf8Length(text1, i); n > 1)  // a UTF-8 file name passes whole
			s += text1.substr(i, n), i += n - 1;
		else  // bytes of a corrupt file quoted in the message: control and stray high bytes
			s += std::iscntrl(static_cast<unsigned char>(c)) || static_cast<unsigned char>(c) >= 0x80 ? '?' : c;
	}
	if (s.size() > maxLen) s = s.substr(0, maxLen - 3) + "...";
	return s.empty() ? "unknown error" : s;
}
}  // namespace gridvector
