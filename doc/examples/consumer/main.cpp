// Loads a CGridVectorMap saved by gridvector (map.gvmap) through MRPT's own
// serialization, inserts one more scan into it, as a robot would, and localises
// that scan against the map with MRPT's ICP.
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/maps/CSimplePointsMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/poses/CPosePDF.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/slam/CICP.h>

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

	// ICP against the map (its static vectors): the scan as a points map, aligned from a guess
	// 10 cm / 2 deg off. The grid-vector map is the reference (m1); icpClassic only (MRPT 2.5's
	// icpLevenbergMarquardt needs a CPointsMap there). One wall fixes x and the heading, not the
	// position along it.
	mrpt::maps::CSimplePointsMap points;
	points.loadFromRangeScan(scan);
	mrpt::slam::CICP icp;
	icp.options.ICP_algorithm = mrpt::slam::icpClassic;
	mrpt::slam::CICP::TReturnInfo info;
	const auto pdf = icp.Align(map.get(), &points, mrpt::poses::CPose2D(0.1, 0.0, 2.0 * M_PI / 180), info);
	std::cout << "ICP: pose " << pdf->getMeanVal().asString() << ", goodness " << info.goodness << "\n";
	return map->vectors().empty() ? 1 : 0;
}
