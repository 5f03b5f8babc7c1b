// Reading one serialized MRPT object from a file (gv-map-info, gv-bench-icp).
#include "io/ErrorText.h"
#include "io/FileBytes.h"
#include "io/ObjectFile.h"
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <stdexcept>

namespace gridvector::io
{
void readObjectFile(const std::string& path, mrpt::serialization::CSerializable& obj)
{
	if (!mrpt::system::fileExists(path)) throw std::runtime_error(path + ": no such file");
	// read (and gunzip, checking the gzip trailer's CRC) before MRPT sees a byte
	const std::vector<char> bytes = readFileBytes(path);
	mrpt::io::CMemoryStream mem;
	mem.assignMemoryNotOwn(bytes.data(), bytes.size());
	try
	{
		auto a = mrpt::serialization::archiveFrom(mem);
		a.ReadObject(&obj);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(path + ": not a valid " + obj.GetRuntimeClass()->className + " file (" +
								 gridvector::oneLineError(e) + ")");
	}
}

}  // namespace gridvector::io
