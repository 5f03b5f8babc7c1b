// Strict tokenising and number parsing for line-based text formats: every
// problem becomes "file:line: what is wrong".
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace gridvector::io
{
/** Where a token came from, for error messages ("file:line"). */
struct TextPos
{
	std::string file;
	size_t line = 0;
	std::string str() const { return file + ":" + std::to_string(line); }
};

/** Throws std::runtime_error("file:line: msg"). */
[[noreturn]] void parseError(const TextPos& pos, const std::string& msg);

/** A token as quoted in an error message: bytes outside printable ASCII as \xHH, at most 40 of them
 * (a binary file's "token" can be any length and hold terminal control sequences). */
std::string printableToken(std::string_view tok);

/** The shortest decimal text that reads back as the same value ("0.1", not 0.100000001). */
std::string shortestText(double v);
std::string shortestText(float v);

/** Splits at blanks (space, tab, CR). */
std::vector<std::string_view> splitTokens(std::string_view line);

/** The whole token as a finite decimal double, else "file:line: <what> is 'tok' (not a finite number)"
 * (hexadecimal floats such as 0x1p3 included: no log or .ini writes them). */
double parseDouble(std::string_view tok, const TextPos& pos, const std::string& what);
/** The same, also within [-limit, limit]: else "file:line: <what> is V (beyond +-limit <unit>)". */
double parseBounded(std::string_view tok, const TextPos& pos, const std::string& what, double limit, const char* unit);
/** The whole token as an integer in [lo, hi]. */
long parseInt(std::string_view tok, const TextPos& pos, const std::string& what, long lo, long hi);

/** Iterates the lines of a text buffer (LF or CRLF), numbering them from 1. */
class LineCursor
{
   public:
	explicit LineCursor(const std::vector<char>& text) : text_(text) {}
	bool next(std::string_view& line);
	size_t lineNumber() const { return line_; }
	double fractionDone() const { return text_.empty() ? 1.0 : double(pos_) / double(text_.size()); }

   private:
	const std::vector<char>& text_;
	size_t pos_ = 0;
	size_t line_ = 0;
};

}  // namespace gridvector::io
