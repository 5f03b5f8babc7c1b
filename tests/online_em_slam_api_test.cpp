// gridvector/OnlineEmSlam.h, the installed API of the online EM-SLAM: laser scans in, the same results as
// the implementation the tools use, the optimisation on a background thread as a robot would run it.
#include <gridvector/OnlineEmSlam.h>

#include "online/OnlineEmSlam.h"
#include "extraction/VectorExtractor.h"
#include "room_loop.h"

#include <gtest/gtest.h>
#include <mrpt/poses/CPose2D.h>

#include <future>
#include <optional>
#include <stdexcept>

using gridvector::GridVectorConfig;
using mrpt::math::TPose2D;
using mrpt::poses::CPose2D;

namespace
{
double worstError(const std::vector<TPose2D>& est, const std::vector<TPose2D>& truth)
{
	double worst = 0;
	for (size_t k = 0; k < est.size(); ++k)
	{
		const CPose2D e = CPose2D(est[k]) - CPose2D(est[0]), t = CPose2D(truth[k]) - CPose2D(truth[0]);
		worst = std::max(worst, e.distanceTo(t));
	}
	return worst;
}
}  // namespace

// The public class runs the implementation: scan for scan the same poses as online::OnlineEmSlam fed the
// same extracted vectors, and the same final trajectory.
TEST(OnlineEmSlamApi, SameResultsAsTheImplementation)
{
	const gvtest::RoomLoop d;
	gridvector::OnlineEmSlam api;
	const GridVectorConfig cfg;
	gridvector::online::OnlineEmSlam core(cfg);
	const gridvector::VectorExtractor ex(cfg.extraction, cfg.grid);
	size_t keyframes = 0;
	for (size_t t = 0; t < d.truth.size(); ++t)
	{
		const auto scan = gvtest::castScan(d.truth[t], gvtest::clutteredRoom());
		const auto a = api.addScan(scan, d.odometry[t]);
		gridvector::LocalScan s = ex.extract(scan);
		s.scanIndex = int64_t(t);
		const auto b = core.addScan(s, d.odometry[t]);
		ASSERT_EQ(a.pose, b.pose) << t;
		ASSERT_EQ(a.keyframe, b.keyframe) << t;
		keyframes += a.keyframe;
		ASSERT_EQ(api.optimisationDue(), core.optimisationDue());
		if (api.optimisationDue())
		{
			api.optimise();
			auto job = core.takeOptimisation();
			core.runOptimisation(job);
			core.applyOptimisation(job);
		}
	}
	api.finish();
	core.finish();
	EXPECT_EQ(api.trajectory(), core.trajectory());
	EXPECT_EQ(api.keyframes().size(), keyframes);
	EXPECT_LT(worstError(api.trajectory(), d.truth), 0.05);
	EXPECT_GT(worstError(d.odometry, d.truth), 0.5);
}

// As on a robot: Eq. 22 on another thread while scans keep coming; the result as accurate, every query
// answered, the room's walls static and no door in it.
TEST(OnlineEmSlamApi, OptimisationOnABackgroundThread)
{
	const gvtest::RoomLoop d;
	gridvector::OnlineEmSlam slam;
	std::future<void> running;
	std::optional<gridvector::OnlineEmSlam::Optimisation> job;
	size_t keyframes = 0;
	for (size_t t = 0; t < d.truth.size(); ++t)
	{
		const auto st = slam.addScan(gvtest::castScan(d.truth[t], gvtest::clutteredRoom()), d.odometry[t]);
		keyframes += st.keyframe;
		EXPECT_EQ(slam.currentPose(), st.pose);
		if (running.valid() && running.wait_for(std::chrono::seconds(0)) == std::future_status::ready)
		{
			running.get();
			slam.applyOptimisation(*job);
		}
		if (!running.valid() && slam.optimisationDue())
		{
			job.emplace(slam.takeOptimisation());
			running = std::async(std::launch::async, [&] { slam.runOptimisation(*job); });
		}
	}
	if (running.valid()) running.get(), slam.applyOptimisation(*job);
	slam.finish();
	EXPECT_EQ(slam.scans(), d.truth.size());
	EXPECT_EQ(slam.keyframes().size(), keyframes);
	EXPECT_LT(worstError(slam.trajectory(), d.truth), 0.05);
	double staticLength = 0;
	for (const auto& v : slam.staticMap()) staticLength += v.length();
	EXPECT_GT(staticLength, 20.0);
	EXPECT_EQ(slam.vectors().size(), slam.staticMap().size() + slam.dynamicVectors().size());
	EXPECT_TRUE(slam.doors(slam.finalMap()).empty());
	EXPECT_GT(slam.occupancyGrid().getSizeX(), 10u);
}

TEST(OnlineEmSlamApi, InvalidConfigurationIsRefused)
{
	GridVectorConfig cfg;
	cfg.mstep.keyframeDistance = -1;
	EXPECT_THROW(gridvector::OnlineEmSlam{cfg}, std::invalid_argument);
}
