// Example: an MRPT program that uses the grid-vector map only through an .ini file, as MRPT's
// own apps do (CMultiMetricMap + gridVectorMap_count). It references no gridvector symbol:
// linking gridvector::gridvector is what registers the map type (the target keeps the library
// linked: see libgridvector/CMakeLists.txt, --no-as-needed).
#include <mrpt/config/CConfigFileMemory.h>
#include <mrpt/maps/CMultiMetricMap.h>

#include <iostream>

int main()
{
	mrpt::config::CConfigFileMemory ini(
		"[MappingApplication]\n"
		"gridVectorMap_count = 1\n"
		"[MappingApplication_gridVectorMap_00_grid]\n"
		"resolution = 0.05\n");
	mrpt::maps::TSetOfMetricMapInitializers init;
	init.loadFromConfigFile(ini, "MappingApplication");
	mrpt::maps::CMultiMetricMap map;
	map.setListOfMaps(init);
	std::cout << map.maps.size() << " map(s)";
	for (const auto& m : map.maps) std::cout << ": " << m->GetRuntimeClass()->className;
	std::cout << "\n";
	return map.maps.size() == 1 &&
				   std::string(map.maps[0]->GetRuntimeClass()->className) == "mrpt::maps::CGridVectorMap"
			   ? 0
			   : 1;
}
