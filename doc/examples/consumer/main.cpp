// Loads a CGridVectorMap saved by gridvector (map.gvmap) through MRPT's own
// serialization, then inserts one more scan into it, as a robot would.
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <iostream>

int main(int argc, char** argv)
{
	if (argc != 2)
	{
		std::cerr << "usage: gv-consumer MAP.gvmap\n";
		return 2;
	}
	mrpt::io::CFileGZInputStream f;
	if (!f.open(argv[1]))
	{
		std::cerr << argv[1] << ": cannot open\n";
		return 1;
	}
	// Read polymorphically: MRPT's class registry knows CGridVectorMap.
	auto obj = mrpt::serialization::archiveFrom(f).ReadObject();
	auto map = std::dynamic_pointer_cast<mrpt::maps::CGridVectorMap>(obj);
	if (!map)
	{
		std::cerr << argv[1] << ": not a CGridVectorMap\n";
		return 1;
	}
	std::cout << map->asString() << "\n";
	// A scan of a wall 2 m ahead, inserted at the origin.
	mrpt::obs::CObservation2DRangeScan scan;
	scan.aperture = float(M_PI);
	scan.resizeScan(181);
	for (size_t i = 0; i < 181; ++i)
	{
		const double a = -M_PI / 2 + M_PI * double(i) / 180.0;
		const bool hit = std::abs(a) < 1.0;
		scan.setScanRange(i, hit ? float(2.0 / std::cos(a)) : 0.f);
		scan.setScanRangeValidity(i, hit);
	}
	const size_t before = map->vectors().size();
	map->insertObservation(scan);
	std::cout << "vectors before/after inserting one scan: " << before << " " << map->vectors().size() << "\n";
	return map->vectors().empty() ? 1 : 0;
}
