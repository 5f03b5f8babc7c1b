#include "io/TextParsing.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace gridvector::io
{
void parseError(const TextPos& pos, const std::string& msg) { throw std::runtime_error(pos.str() + ": " + msg); }

namespace
{
template <class T>
std::string shortestOf(T v)
{
	char buf[32];
	const auto r = std::to_chars(buf, buf + sizeof buf, v);
	return std::string(buf, r.ptr);
}
}  // namespace

std::string shortestText(double v) { return shortestOf(v); }
std::string shortestText(float v) { return shortestOf(v); }

std::string printableToken(std::string_view tok)
{
	constexpr size_t kMax = 40;
	static const char* hex = "0123456789abcdef";
	std::string out;
	for (size_t i = 0; i < tok.size() && i < kMax; ++i)
	{
		const auto c = static_cast<unsigned char>(tok[i]);
		if (c >= 0x20 && c < 0x7f)
			out += char(c);
		else
			out += std::string("\\x") + hex[c >> 4] + hex[c & 15];
	}
	if (tok.size() > kMax) out += "...";
	return out;
}

std::vector<std::string_view> splitTokens(std::string_view line)
{
	std::vector<std::string_view> out;
	size_t i = 0;
	const auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
	while (i < line.size())
	{
		while (i < line.size() && blank(line[i])) i++;
		size_t j = i;
		while (j < line.size() && !blank(line[j])) j++;
		if (j > i) out.push_back(line.substr(i, j - i));
		i = j;
	}
	return out;
}

double parseDouble(std::string_view tok, const TextPos& pos, const std::string& what)
{
	double fast = 0;  // the common case without allocating; strtod for the rest ("+1", hex, errors)
	const auto [end0, ec] = std::from_chars(tok.data(), tok.data() + tok.size(), fast);
	if (ec == std::errc() && end0 == tok.data() + tok.size() && std::isfinite(fast)) return fast;
	const std::string s(tok);
	char* end = nullptr;
	errno = 0;
	const double v = std::strtod(s.c_str(), &end);
	const bool hex = s.find_first_of("xX") != std::string::npos;
	if (s.empty() || hex || end != s.c_str() + s.size() || !std::isfinite(v) || errno == ERANGE)
		parseError(pos, what + " is '" + printableToken(s) + "' (not a finite number)");
	return v;
}

double parseBounded(std::string_view tok, const TextPos& pos, const std::string& what, double limit, const char* unit)
{
	const double v = parseDouble(tok, pos, what);
	if (std::abs(v) > limit)
		parseError(pos, what + " is " + printableToken(tok) + " (beyond +-" + shortestText(limit) + " " + unit + ")");
	return v;
}

long parseInt(std::string_view tok, const TextPos& pos, const std::string& what, long lo, long hi)
{
	const std::string s(tok);
	char* end = nullptr;
	errno = 0;
	const long v = std::strtol(s.c_str(), &end, 10);
	if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE)
		parseError(pos, what + " is '" + printableToken(s) + "' (not an integer)");
	if (v < lo || v > hi)
		parseError(pos, what + " is " + printableToken(s) + " (must be in " + std::to_string(lo) + ".." +
							std::to_string(hi) + ")");
	return v;
}

bool LineCursor::next(std::string_view& line)
{
	if (pos_ >= text_.size()) return false;
	size_t end = pos_;
	while (end < text_.size() && text_[end] != '\n') end++;
	size_t stop = end;
	if (stop > pos_ && text_[stop - 1] == '\r') stop--;
	line = std::string_view(text_.data() + pos_, stop - pos_);
	pos_ = end < text_.size() ? end + 1 : end;
	line_++;
	return true;
}

}  // namespace gridvector::io
