#include <gridvector/ErrorText.h>

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
		if (startsWith(line, "Call stack backtrace")) { inStack = true; continue; }
		if (startsWith(line, "Location:")) { inStack = false; continue; }
		if (startsWith(line, "Message:")) { inStack = false; lastMessage = trim(line.substr(8)); continue; }
		if (inStack || isFrame(line)) continue;
		if (!lastMessage.empty()) lastMessage += ' ' + line;
		else out += (out.empty() ? "" : " ") + line;
	}
	std::string s;
	for (char c : lastMessage.empty() ? out : lastMessage)
		if (std::isspace(static_cast<unsigned char>(c)))
		{
			if (!s.empty() && s.back() != ' ') s += ' ';
		}
		else s += std::iscntrl(static_cast<unsigned char>(c)) ? '?' : c;  // bytes of a corrupt file quoted in the message
	if (s.size() > maxLen) s = s.substr(0, maxLen - 3) + "...";
	return s.empty() ? "unknown error" : s;
}
}  // namespace gridvector
