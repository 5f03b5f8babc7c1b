// Whole-file input, transparently gunzipped, with gzip integrity checking.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
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

/** Throws "path: cannot read (reason)" unless path is a file that can be opened for reading
 * (a directory: "it is a directory"; missing: "No such file or directory"). */
void checkReadableFile(const std::string& path);
/** True if the file starts with the gzip magic bytes 1f 8b. */
bool isGzipFile(const std::string& path);

/** The file's content, gunzipped if it is gzip-compressed. A gzip file whose
 * trailer (CRC-32 and length) does not match the data is reported as
 * "path: truncated or corrupt gzip data"; unreadable files as "path: cannot read (reason)".
 * Concatenated multi-member gzip files are not supported (reported as corrupt). */
std::vector<char> readFileBytes(const std::string& path, bool* wasGzip = nullptr);

}  // namespace gridvector::io
