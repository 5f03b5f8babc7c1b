#include "io/FileBytes.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/stat.h>
#include <unistd.h>
#include <zlib.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <filesystem>
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

/** Bytes handed to onHead before the rest is read. */
constexpr size_t kHeadBytes = size_t(64) << 10;
constexpr size_t kChunk = size_t(64) << 10;

[[noreturn]] void cannotRead(const std::string& path, const std::string& why)
{
	throw std::runtime_error(path + ": cannot read (" + why + ")");
}

[[noreturn]] void corruptGzip(const std::string& path, const std::string& why)
{
	throw std::runtime_error(path + ": truncated or corrupt gzip data (" + why + ")");
}

/** A file, pipe or FIFO opened for reading without blocking in open(): a named FIFO waits at most
 * kFifoWriterWaitMs for a writer (a blocking open would wait forever), then reads block as usual. */
class InputFile
{
   public:
	explicit InputFile(const std::string& path) : path_(path)
	{
		std::error_code ec;
		if (std::filesystem::is_directory(path, ec)) cannotRead(path, "it is a directory");
		fd_ = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
		if (fd_ < 0) cannotRead(path, std::strerror(errno));
		try
		{
			struct stat st = {};
			if (::lstat(path.c_str(), &st) == 0 && S_ISFIFO(st.st_mode)) waitForWriter();
			const int flags = ::fcntl(fd_, F_GETFL);
			if (flags < 0 || ::fcntl(fd_, F_SETFL, flags & ~O_NONBLOCK) < 0) cannotRead(path, std::strerror(errno));
		}
		catch (...)
		{
			::close(fd_);
			throw;
		}
	}
	~InputFile() { ::close(fd_); }
	InputFile(const InputFile&) = delete;
	InputFile& operator=(const InputFile&) = delete;

	/** Up to n bytes; 0 at the end of the file. */
	size_t read(char* buf, size_t n)
	{
		for (;;)
		{
			const ssize_t r = ::read(fd_, buf, n);
			if (r >= 0) return size_t(r);
			if (errno != EINTR) cannotRead(path_, std::strerror(errno));
		}
	}

	/** Fills buf as far as the file goes (a pipe hands out what its writer wrote so far). */
	size_t readFull(char* buf, size_t n)
	{
		size_t got = 0;
		while (got < n)
		{
			const size_t r = read(buf + got, n - got);
			if (r == 0) break;
			got += r;
		}
		return got;
	}

   private:
	void waitForWriter()
	{
		pollfd p{fd_, POLLIN, 0};
		int r = 0;
		do r = ::poll(&p, 1, kFifoWriterWaitMs);
		while (r < 0 && errno == EINTR);
		if (r < 0) cannotRead(path_, std::strerror(errno));
		if (r == 0)
			cannotRead(path_, "a FIFO that no writer opened within " + std::to_string(kFifoWriterWaitMs / 1000) + " s");
	}

	std::string path_;
	int fd_ = -1;
};

/** The bytes read so far, with the size and line limits applied as they arrive. */
class Sink
{
   public:
	Sink(const std::string& path, const ReadLimits& limits) : path_(path), limits_(limits) {}

	void append(const char* p, size_t n)
	{
		if (n > limits_.maxBytes - out_.size())
			throw std::runtime_error(path_ + ": larger than " + std::to_string(limits_.maxBytes) +
									 " bytes (the input limit" + (gzip_ ? ", after gunzip)" : ")"));
		out_.insert(out_.end(), p, p + n);
		if (!headDone_ && out_.size() >= kHeadBytes) deliverHead();
		if (headDone_) checkLines();
	}
	std::vector<char> finish()
	{
		if (!headDone_) deliverHead();
		checkLines();
		return std::move(out_);
	}
	void setGzip(bool gz) { gzip_ = gz; }

   private:
	void deliverHead()
	{
		headDone_ = true;
		if (limits_.onHead) maxLine_ = limits_.onHead(std::string_view(out_.data(), std::min(out_.size(), kHeadBytes)));
	}
	void checkLines()
	{
		if (maxLine_ == 0) return void(checked_ = out_.size());
		for (; checked_ < out_.size(); ++checked_)
		{
			if (out_[checked_] == '\n')
			{
				line_++, lineLength_ = 0;
				continue;
			}
			if (++lineLength_ > maxLine_)
				throw std::runtime_error(path_ + ":" + std::to_string(line_) + ": line longer than " +
										 std::to_string(maxLine_) + " bytes (the limit)");
		}
	}

	const std::string& path_;
	const ReadLimits& limits_;
	std::vector<char> out_;
	bool headDone_ = false, gzip_ = false;
	size_t maxLine_ = 0, checked_ = 0, line_ = 1, lineLength_ = 0;
};

bool gzipMagic(const char* p, size_t n)
{
	return n >= 2 && static_cast<unsigned char>(p[0]) == 0x1f && static_cast<unsigned char>(p[1]) == 0x8b;
}

/** RFC 1952 through zlib, which checks the trailer's CRC-32 and length itself. */
void gunzip(InputFile& in, std::vector<char> raw, size_t n, Sink& sink, const std::string& path)
{
	z_stream z = {};
	if (inflateInit2(&z, 16 + MAX_WBITS) != Z_OK) corruptGzip(path, "zlib cannot start");
	struct End
	{
		z_stream* z;
		~End() { inflateEnd(z); }
	} end{&z};
	std::vector<char> buf(kChunk);
	bool ended = false;
	while (n > 0 && !ended)
	{
		z.next_in = reinterpret_cast<Bytef*>(raw.data());
		z.avail_in = uInt(n);
		do  // also while the output buffer came back full: zlib may hold more output for no more input
		{
			z.next_out = reinterpret_cast<Bytef*>(buf.data());
			z.avail_out = uInt(buf.size());
			const int r = inflate(&z, Z_NO_FLUSH);
			if (r == Z_DATA_ERROR && z.msg && std::strstr(z.msg, "check"))
				corruptGzip(path, "CRC/length trailer mismatch");  // "incorrect data check" / "length check"
			if (r != Z_OK && r != Z_STREAM_END && r != Z_BUF_ERROR) corruptGzip(path, z.msg ? z.msg : "zlib error");
			sink.append(buf.data(), buf.size() - z.avail_out);
			ended = r == Z_STREAM_END;
			if (r == Z_BUF_ERROR && z.avail_out != 0) break;  // wants more input
		} while ((z.avail_in > 0 || z.avail_out == 0) && !ended);
		if (ended && z.avail_in > 0)
			corruptGzip(path, "data after the gzip stream; concatenated members are not supported");
		if (!ended) n = in.read(raw.data(), raw.size());
	}
	if (!ended) corruptGzip(path, "CRC/length trailer mismatch");  // the file ends before the trailer
	if (in.read(raw.data(), raw.size()) > 0)
		corruptGzip(path, "data after the gzip stream; concatenated members are not supported");
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

void checkReadableFile(const std::string& path) { InputFile f(path); }

bool isGzipFile(const std::string& path)
{
	InputFile f(path);
	char m[2] = {0, 0};
	return gzipMagic(m, f.readFull(m, 2));
}

std::vector<char> readFileBytes(const std::string& path, bool* wasGzip, const ReadLimits& limits)
{
	InputFile in(path);
	std::vector<char> raw(kChunk);
	const size_t n = in.readFull(raw.data(), raw.size());  // one read: a pipe's bytes are not read twice
	const bool gz = gzipMagic(raw.data(), n);
	if (wasGzip) *wasGzip = gz;
	Sink sink(path, limits);
	sink.setGzip(gz);
	if (gz)
		gunzip(in, std::move(raw), n, sink, path);
	else
		for (size_t k = n; k > 0; k = in.read(raw.data(), raw.size())) sink.append(raw.data(), k);
	return sink.finish();
}

}  // namespace gridvector::io
