#include "io/FileBytes.h"

#include <mrpt/io/CFileGZInputStream.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace gridvector::io
{
namespace
{
std::array<uint32_t, 256> makeCrcTable()
{
	std::array<uint32_t, 256> t{};
	for (uint32_t n = 0; n < 256; n++)
	{
		uint32_t c = n;
		for (int k = 0; k < 8; k++) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
		t[n] = c;
	}
	return t;
}

[[noreturn]] void cannotRead(const std::string& path, const std::string& why)
{
	throw std::runtime_error(path + ": cannot read (" + why + ")");
}

std::ifstream openOrThrow(const std::string& path)
{
	if (std::filesystem::is_directory(path)) cannotRead(path, "it is a directory");
	errno = 0;
	std::ifstream f(path, std::ios::binary);
	if (!f) cannotRead(path, errno ? std::strerror(errno) : "cannot open");
	return f;
}

uint32_t le32(const unsigned char* p)
{
	return uint32_t(p[0]) | uint32_t(p[1]) << 8 | uint32_t(p[2]) << 16 | uint32_t(p[3]) << 24;
}

/** The gzip trailer: CRC-32 and uncompressed length mod 2^32 (RFC 1952). */
std::pair<uint32_t, uint32_t> gzipTrailer(const std::string& path)
{
	std::ifstream f = openOrThrow(path);
	f.seekg(0, std::ios::end);
	const auto size = static_cast<long long>(f.tellg());
	if (size < 18) throw std::runtime_error(path + ": truncated or corrupt gzip data (file too short)");
	unsigned char b[8];
	f.seekg(size - 8);
	f.read(reinterpret_cast<char*>(b), 8);
	if (!f) cannotRead(path, "read error");
	return {le32(b), le32(b + 4)};
}

std::vector<char> readGzip(const std::string& path)
{
	const auto [crcExpected, sizeExpected] = gzipTrailer(path);
	mrpt::io::CFileGZInputStream in;
	std::string err;
	if (!in.open(path, err)) cannotRead(path, err);
	std::vector<char> out;
	Crc32 crc;
	std::vector<char> buf(1 << 16);
	for (;;)
	{
		const size_t n = in.Read(buf.data(), buf.size());
		if (n == 0) break;
		if (n > buf.size()) throw std::runtime_error(path + ": truncated or corrupt gzip data");
		crc.update(buf.data(), n);
		out.insert(out.end(), buf.begin(), buf.begin() + n);
	}
	if (crc.value() != crcExpected || uint32_t(out.size()) != sizeExpected)
		throw std::runtime_error(path + ": truncated or corrupt gzip data (CRC/length trailer mismatch)");
	return out;
}
}  // namespace

void Crc32::update(const void* data, size_t len)
{
	static const auto table = makeCrcTable();
	const auto* p = static_cast<const unsigned char*>(data);
	uint32_t c = state_;
	for (size_t i = 0; i < len; i++) c = table[(c ^ p[i]) & 0xFF] ^ (c >> 8);
	state_ = c;
}

void checkReadableFile(const std::string& path) { openOrThrow(path); }

bool isGzipFile(const std::string& path)
{
	std::ifstream f = openOrThrow(path);
	unsigned char m[2] = {0, 0};
	f.read(reinterpret_cast<char*>(m), 2);
	return f.gcount() == 2 && m[0] == 0x1f && m[1] == 0x8b;
}

std::vector<char> readFileBytes(const std::string& path, bool* wasGzip)
{
	const bool gz = isGzipFile(path);
	if (wasGzip) *wasGzip = gz;
	if (gz) return readGzip(path);
	std::ifstream f = openOrThrow(path);
	std::vector<char> out((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
	if (f.bad()) cannotRead(path, "read error");
	return out;
}

}  // namespace gridvector::io
