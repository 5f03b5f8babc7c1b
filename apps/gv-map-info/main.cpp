// gv-map-info: inspect a saved CGridVectorMap (.gvmap), or build one from an MRPT
// .simplemap (poses + observations, e.g. written by icp-slam or rbpf-slam).
//
//   gv-map-info MAP.gvmap
//   gv-map-info --from-simplemap FILE.simplemap [--config FILE.ini] [--save OUT.gvmap]
#include <gridvector/ErrorText.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>

#include <cstdio>
#include <iostream>
#include <string>

namespace
{
[[noreturn]] void fail(const std::string& msg)
{
	std::cerr << "gv-map-info: " << msg << "\n";
	std::exit(1);
}

void usage()
{
	std::cout << "usage: gv-map-info MAP.gvmap\n"
				 "       gv-map-info --from-simplemap FILE.simplemap [--config FILE.ini] [--save OUT.gvmap]\n";
}

template <class T>
void readObject(const std::string& path, T& obj)
{
	if (!mrpt::system::fileExists(path)) fail(path + ": no such file");
	mrpt::io::CFileGZInputStream f;
	if (!f.open(path)) fail(path + ": cannot open");
	try
	{
		auto a = mrpt::serialization::archiveFrom(f);
		a >> obj;
	}
	catch (const std::exception& e)
	{
		fail(path + ": not a valid " + obj.GetRuntimeClass()->className + " file (" +
			 gridvector::oneLineError(e) + ")");
	}
}

}  // namespace

int main(int argc, char** argv)
{
	std::string input, simplemap, config, save;
	for (int i = 1; i < argc; ++i)
	{
		const std::string a = argv[i];
		auto next = [&]() -> std::string {
			if (i + 1 >= argc) fail("option " + a + " needs a value");
			return argv[++i];
		};
		if (a == "--from-simplemap") simplemap = next();
		else if (a == "--config") config = next();
		else if (a == "--save") save = next();
		else if (a == "-h" || a == "--help") return usage(), 0;
		else if (!a.empty() && a[0] == '-') fail("unknown option " + a);
		else input = a;
	}
	if (input.empty() == simplemap.empty()) return usage(), 2;
	mrpt::maps::CGridVectorMap map;
	try
	{
		if (!config.empty())
		{
			gridvector::GridVectorConfig cfg;
			cfg.loadFromFile(config);
			map.setConfig(cfg);
		}
		if (!simplemap.empty())
		{
			mrpt::maps::CSimpleMap sm;
			readObject(simplemap, sm);
			map.loadFromProbabilisticPosesAndObservations(sm);
		}
		else
			readObject(input, map);
	}
	catch (const std::exception& e)
	{
		fail(gridvector::oneLineError(e));
	}
	std::cout << map.asString() << "\n";
	if (!save.empty())
	{
		try
		{
			map.saveToFile(save);
		}
		catch (const std::exception& e)
		{
			fail(gridvector::oneLineError(e));
		}
	}
	return 0;
}
