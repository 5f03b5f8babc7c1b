// Whole-file input, transparently gunzipped, with gzip integrity checking and size limits;
// regular files, pipes and FIFOs alike (nothing is read twice, nothing is sought).
#pragma once

#include "io/InputLimits.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace gridvector::io
{
/** CRC-32 (IEEE 802.3, as in gzip trailers), computed incrementally. */
class Crc32
{
   public:
	void update(const void* data, size_t len);
	uint32_t value() const { return ~state_; }

   private:
	uint32_t state_ = 0xFFFFFFFFu;
};

/** What readFileBytes accepts. */
struct ReadLimits
{
	size_t maxBytes = kMaxInputBytes;  //!< larger (after gunzip): "path: larger than N bytes (the limit)"
	/** Called once with the first bytes (up to 64 KiB, gunzipped) before the rest is read: it may throw
	 * (a file that cannot be what the caller reads) and returns the longest line to allow, 0 for none. */
	std::function<size_t(std::string_view head)> onHead;
};

/** Throws "path: cannot read (reason)" unless path is a file that can be opened for reading
 * (a directory: "it is a directory"; missing: "No such file or directory"). Does not block on a FIFO. */
void checkReadableFile(const std::string& path);
/** True if the file starts with the gzip magic bytes 1f 8b. */
bool isGzipFile(const std::string& path);

/** The file's content, gunzipped if it is gzip-compressed (by its magic bytes). A gzip file whose
 * trailer (CRC-32 and length) does not match the data is reported as
 * "path: truncated or corrupt gzip data (...)"; unreadable files as "path: cannot read (reason)";
 * more than limits.maxBytes as "path: larger than ..."; a line longer than onHead's limit as
 * "path:LINE: line longer than ...". A named FIFO that gets no writer within kFifoWriterWaitMs is
 * "path: cannot read (no writer opened the FIFO within 3 s)". Concatenated multi-member gzip files
 * are not supported (reported as corrupt). */
std::vector<char> readFileBytes(const std::string& path, bool* wasGzip = nullptr, const ReadLimits& limits = {});

}  // namespace gridvector::io
