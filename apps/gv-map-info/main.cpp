// gv-map-info: inspect a saved CGridVectorMap (.gvmap), or build one from an MRPT
// .simplemap (poses + observations, e.g. written by icp-slam or rbpf-slam).
//
//   gv-map-info MAP.gvmap [--save OUT.gvmap]      (--save rewrites it in the current format version)
//   gv-map-info --from-simplemap FILE.simplemap [--config FILE.ini] [--save OUT.gvmap]
#include <gridvector/ErrorText.h>
#include <gridvector/io/ArgParser.h>
#include <gridvector/io/AtomicFile.h>
#include <gridvector/io/FileBytes.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <iostream>
#include <stdexcept>
#include <string>

namespace
{
template <class T>
void readObject(const std::string& path, T& obj)
{
	if (!mrpt::system::fileExists(path)) throw std::runtime_error(path + ": no such file");
	gridvector::io::checkReadableFile(path);  // a directory opened and failed in MRPT as "unknown error"
	mrpt::io::CFileGZInputStream f;
	if (!f.open(path)) throw std::runtime_error(path + ": cannot open");
	try
	{
		auto a = mrpt::serialization::archiveFrom(f);
		a >> obj;
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(path + ": not a valid " + obj.GetRuntimeClass()->className + " file (" +
								 gridvector::oneLineError(e) + ")");
	}
}
}  // namespace

int main(int argc, char** argv)
{
	gridvector::io::ArgParser args(
		"gv-map-info", "MAP.gvmap [--save OUT.gvmap]\n       gv-map-info --from-simplemap FILE.simplemap [--config FILE.ini] [--save OUT.gvmap]");
	args.option("from-simplemap", "FILE", "build the map from an MRPT .simplemap (poses + observations)");
	args.option("config", "FILE.ini", "gridvector parameters for --from-simplemap ([gridvector_*] sections)");
	args.option("save", "OUT.gvmap", "write the map (in the current .gvmap format version), atomically");
	gridvector::io::ToolErrorStyle style;
	style.prefix = "gv-map-info: ";
	style.oneLine = true;
	return gridvector::io::runTool(
		args, argc, argv,
		[&] {
			const bool fromSimplemap = args.has("from-simplemap");
			args.requirePositional(fromSimplemap ? 0 : 1, fromSimplemap ? 0 : 1);
			if (args.has("config") && !fromSimplemap)
				args.fail("--config applies to --from-simplemap only (a .gvmap stores its own parameters)");
			if (args.has("save")) gridvector::io::checkWritableFile(args.get("save"));  // before the read
			mrpt::maps::CGridVectorMap map;
			if (fromSimplemap)
			{
				if (args.has("config"))
				{
					gridvector::GridVectorConfig cfg;
					cfg.loadFromFile(args.get("config"));
					map.setConfig(cfg);
				}
				mrpt::maps::CSimpleMap sm;
				readObject(args.get("from-simplemap"), sm);
				map.loadFromProbabilisticPosesAndObservations(sm);
			}
			else
				readObject(args.positional()[0], map);
			std::cout << map.asString() << "\n";
			if (args.has("save")) map.saveToFile(args.get("save"));
			return 0;
		},
		style);
}
