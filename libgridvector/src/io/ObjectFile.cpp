// Reading one serialized MRPT object from a file (gv-map-info, gv-bench-icp).
#include "io/ErrorText.h"
#include "io/FileBytes.h"
#include "io/ObjectFile.h"
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <stdexcept>

namespace gridvector::io
{
void readObjectFile(const std::string& path, mrpt::serialization::CSerializable& obj)
{
	if (!mrpt::system::fileExists(path)) throw std::runtime_error(path + ": no such file");
	checkReadableFile(path);  // a directory opened and failed in MRPT as "unknown error"
	mrpt::io::CFileGZInputStream f;
	if (!f.open(path)) throw std::runtime_error(path + ": cannot open");
	try
	{
		auto a = mrpt::serialization::archiveFrom(f);
		a.ReadObject(&obj);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(path + ": not a valid " + obj.GetRuntimeClass()->className + " file (" +
								 gridvector::oneLineError(e) + ")");
	}
}

}  // namespace gridvector::io
