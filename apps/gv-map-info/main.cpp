// gv-map-info: inspect a saved CGridVectorMap (.gvmap), or build one from an MRPT
// .simplemap (poses + observations, e.g. written by icp-slam or rbpf-slam).
//
//   gv-map-info MAP.gvmap [--save OUT.gvmap]      (--save rewrites it in the current format version)
//   gv-map-info --from-simplemap FILE.simplemap [--config FILE.ini] [--save OUT.gvmap]
#include "common/ArgParser.h"
#include "io/AtomicFile.h"
#include "io/ObjectFile.h"
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/CSimpleMap.h>

#include <iostream>
#include <stdexcept>
#include <string>

int main(int argc, char** argv)
{
	gridvector::io::ArgParser args("gv-map-info",
								   "MAP.gvmap [--save OUT.gvmap]\n       gv-map-info --from-simplemap FILE.simplemap "
								   "[--config FILE.ini] [--save OUT.gvmap]");
	args.option("from-simplemap", "FILE", "build the map from an MRPT .simplemap (poses + observations)",
				"none: read MAP.gvmap");
	args.option("config", "FILE.ini", "gridvector parameters for --from-simplemap ([gridvector_*] sections)",
				"the library's defaults (gv-config --ini)");
	args.option("save", "OUT.gvmap", "write the map (in the current .gvmap format version), atomically",
				"none: print only");
	return gridvector::io::runTool(args, argc, argv, [&] {
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
			gridvector::io::readObjectFile(args.get("from-simplemap"), sm);
			map.loadFromProbabilisticPosesAndObservations(sm);
		}
		else
			gridvector::io::readObjectFile(args.positional()[0], map);
		std::cout << map.asString() << "\n";
		if (args.has("save")) map.saveToFile(args.get("save"));
		return 0;
	});
}
