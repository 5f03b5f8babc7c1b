#include "io/ArchiveFile.h"
#include "io/AtomicFile.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/io/zip.h>

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace gridvector::io
{
namespace
{
/** The gzip file's bytes, decompressed; false if it cannot be read whole. */
bool readBack(const std::string& file, std::vector<uint8_t>& bytes)
{
	return mrpt::io::zip::decompress_gz_file(file, bytes);
}

void writeGzip(const std::string& tmp, const void* data, size_t n)
{
	mrpt::io::CFileGZOutputStream gz;
	if (!gz.open(tmp, 1)) throw std::runtime_error("cannot open");
	if (n > 0 && gz.Write(data, n) != n) throw std::runtime_error("write error (disk full?)");
	gz.close();  // gzclose's error is not reported: readBack finds what it lost
}
}  // namespace

void writeArchiveFile(const std::string& path, bool compress,
					  const std::function<void(mrpt::serialization::CArchive&)>& fill)
{
	mrpt::io::CMemoryStream mem;
	{
		auto ar = mrpt::serialization::archiveFrom(mem);
		fill(ar);
	}
	const auto* data = static_cast<const uint8_t*>(mem.getRawBufferData());
	const size_t n = size_t(mem.getTotalBytesCount());
	if (!compress)
	{
		AtomicFile file(path, AtomicFile::Mode::Binary);
		file.stream().write(reinterpret_cast<const char*>(data), std::streamsize(n));
		file.commit();  // checks the flush and the close
		return;
	}
	AtomicFile file(path, AtomicFile::Mode::External);
	try
	{
		writeGzip(file.tempPath(), data, n);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(path + ": cannot write (" + e.what() + ")");
	}
	std::vector<uint8_t> back;
	if (!readBack(file.tempPath(), back) || back.size() != n || (n > 0 && std::memcmp(back.data(), data, n) != 0))
		throw std::runtime_error(path + ": cannot write (the file came out incomplete: disk full?)");
	file.commit();
}
}  // namespace gridvector::io
