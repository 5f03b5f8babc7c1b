// The public face of the online EM-SLAM (gridvector/OnlineEmSlam.h): online::OnlineEmSlam and an extractor.
#include <gridvector/OnlineEmSlam.h>

#include "doors/DoorDetector.h"
#include "extraction/VectorExtractor.h"
#include "online/OnlineEmSlam.h"

namespace gridvector
{
struct OnlineEmSlam::Impl
{
	explicit Impl(const GridVectorConfig& c) : cfg(c), extractor(cfg.extraction, cfg.grid), slam(cfg) {}
	GridVectorConfig cfg;
	VectorExtractor extractor;
	online::OnlineEmSlam slam;
};

struct OnlineEmSlam::Optimisation::Job
{
	online::OnlineEmSlam::Optimisation job;
};

OnlineEmSlam::Optimisation::Optimisation(std::unique_ptr<Job> job) : job_(std::move(job)) {}
OnlineEmSlam::Optimisation::Optimisation(Optimisation&&) noexcept = default;
OnlineEmSlam::Optimisation& OnlineEmSlam::Optimisation::operator=(Optimisation&&) noexcept = default;
OnlineEmSlam::Optimisation::~Optimisation() = default;

namespace
{
const GridVectorConfig& validated(const GridVectorConfig& cfg)
{
	cfg.validate();
	return cfg;
}
}  // namespace

OnlineEmSlam::OnlineEmSlam(const GridVectorConfig& cfg) : impl_(std::make_unique<Impl>(validated(cfg))) {}
OnlineEmSlam::~OnlineEmSlam() = default;

OnlineEmSlam::Step OnlineEmSlam::addScan(const mrpt::obs::CObservation2DRangeScan& scan,
										 const mrpt::math::TPose2D& odometry)
{
	LocalScan s = impl_->extractor.extract(scan);
	s.scanIndex = int64_t(impl_->slam.scans());
	s.timestamp = scan.timestamp == INVALID_TIMESTAMP ? 0.0 : mrpt::Clock::toDouble(scan.timestamp);
	return addScan(s, odometry);
}

OnlineEmSlam::Step OnlineEmSlam::addScan(const LocalScan& scan, const mrpt::math::TPose2D& odometry)
{
	const online::OnlineStep st = impl_->slam.addScan(scan, odometry);
	return {st.pose, st.registered, st.keyframe, st.loops, st.classified};
}

bool OnlineEmSlam::optimisationDue() const { return impl_->slam.optimisationDue(); }

void OnlineEmSlam::optimise() { impl_->slam.optimise(); }

OnlineEmSlam::Optimisation OnlineEmSlam::takeOptimisation()
{
	return Optimisation(std::make_unique<Optimisation::Job>(Optimisation::Job{impl_->slam.takeOptimisation()}));
}

void OnlineEmSlam::runOptimisation(Optimisation& job) { impl_->slam.runOptimisation(job.job_->job); }
void OnlineEmSlam::applyOptimisation(const Optimisation& job) { impl_->slam.applyOptimisation(job.job_->job); }
void OnlineEmSlam::finish() { impl_->slam.finish(); }

size_t OnlineEmSlam::scans() const { return impl_->slam.scans(); }
mrpt::math::TPose2D OnlineEmSlam::currentPose() const { return impl_->slam.currentPose(); }
std::vector<mrpt::math::TPose2D> OnlineEmSlam::trajectory() const { return impl_->slam.trajectory(); }
const std::vector<size_t>& OnlineEmSlam::keyframes() const { return impl_->slam.keyframes(); }

std::vector<GridVector> OnlineEmSlam::vectors() const { return impl_->slam.vectors(); }
std::vector<GridVector> OnlineEmSlam::staticMap() const { return impl_->slam.staticMap(); }
std::vector<GridVector> OnlineEmSlam::dynamicVectors() const { return impl_->slam.dynamicVectors(); }
std::vector<GridVector> OnlineEmSlam::finalMap() const { return impl_->slam.finalMap(); }

// Sec. 5.4: doors among the map's vectors.
std::vector<Door> OnlineEmSlam::doors(const std::vector<GridVector>& map) const
{
	return DoorDetector(impl_->cfg.doors).detect(map);
}

mrpt::maps::COccupancyGridMap2D OnlineEmSlam::occupancyGrid() const { return impl_->slam.occupancyGrid(); }

}  // namespace gridvector
