#include "io/ArchiveFile.h"
#include "io/RawlogWriter.h"

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/maps/CSimpleMap.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/poses/CPose3DPDFGaussian.h>
#include <mrpt/poses/CPose2D.h>
#include <mrpt/serialization/CArchive.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace gridvector::io
{
namespace
{
using namespace mrpt::obs;
using mrpt::poses::CPose2D;

void writeObservations(mrpt::serialization::CArchive& ar, const ScanRecord& r)
{
	if (r.hasOdometry)
	{
		auto o = CObservationOdometry::Create();
		o->sensorLabel = "ODOMETRY";
		o->timestamp = mrpt::Clock::fromDouble(r.timestamp);
		o->odometry = CPose2D(r.odometry);
		ar << *o;
	}
	ar << *r.scan;
}

void writeFrame(mrpt::serialization::CArchive& ar, const ScanRecord& r, const CPose2D& increment)
{
	CActionCollection acts;
	CActionRobotMovement2D mov;
	mov.timestamp = mrpt::Clock::fromDouble(r.timestamp);
	mov.computeFromOdometry(increment, CActionRobotMovement2D::TMotionModelOptions());
	acts.insert(mov);
	CSensoryFrame sf;
	sf.insert(r.scan);
	ar << acts << sf;
}
}  // namespace

void writeRawlog(const std::string& path, const LogData& log, const RawlogWriteOptions& opt)
{
	writeArchiveFile(path, opt.compress, [&](mrpt::serialization::CArchive& ar) {
		CPose2D prev;
		bool havePrev = false;
		for (const ScanRecord& r : log.scans)
		{
			if (!r.scan) throw std::runtime_error(path + ": cannot write (scan record without a scan)");
			if (opt.format == RawlogFormat::Observations)
				writeObservations(ar, r);
			else
			{
				const CPose2D odo(r.odometry);
				writeFrame(ar, r, havePrev && r.hasOdometry ? odo - prev : CPose2D());
				if (r.hasOdometry) prev = odo, havePrev = true;
			}
		}
	});
}

namespace
{
mrpt::maps::CSimpleMap simplemapOf(const LogData& log, const std::vector<std::optional<mrpt::math::TPose2D>>& poses)
{
	if (poses.size() != log.scans.size())
		throw std::invalid_argument("writeSimplemap: " + std::to_string(poses.size()) + " poses for " +
									std::to_string(log.scans.size()) + " scans");
	mrpt::maps::CSimpleMap sm;
	for (size_t i = 0; i < log.scans.size(); ++i)
	{
		if (!poses[i]) continue;
		if (!log.scans[i].scan) throw std::invalid_argument("writeSimplemap: scan record without a scan");
		const auto& p = *poses[i];
		auto pose = mrpt::poses::CPose3DPDFGaussian::Create();
		pose->mean = mrpt::poses::CPose3D(p.x, p.y, 0, p.phi, 0, 0);  // covariance zero: the pose is given
		auto sf = CSensoryFrame::Create();
		sf->insert(log.scans[i].scan);
		sm.insert(pose, sf);
	}
	if (sm.empty()) throw std::invalid_argument("writeSimplemap: no scan has a pose");
	return sm;
}
}  // namespace

size_t writeSimplemap(const std::string& path, const LogData& log,
					  const std::vector<std::optional<mrpt::math::TPose2D>>& poses)
{
	const mrpt::maps::CSimpleMap sm = simplemapOf(log, poses);
	writeArchiveFile(path, true, [&](mrpt::serialization::CArchive& ar) { ar << sm; });
	return sm.size();
}

}  // namespace gridvector::io
