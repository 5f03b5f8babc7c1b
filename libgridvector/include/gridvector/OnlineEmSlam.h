// Sec. 6's future work, the "sequential mode": EM-SLAM scan by scan on a robot. The implementation behind
// `gv-em-slam --online` and the graphslam-engine deciders CGridVectorNRD / CGridVectorERD.
#pragma once

#include <gridvector/Door.h>
#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>
#include <gridvector/LocalScan.h>

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/math/TPose2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <cstddef>
#include <memory>
#include <vector>

namespace gridvector
{
/** Online EM-SLAM: one laser scan and its odometry at a time.
 *
 * Per scan: its grid vectors (Sec. 3.1), its pose now (registered against the last keyframe from the
 * odometry guess, Sec. 4.2). Per keyframe (mstep.keyframe_distance / keyframe_rotation_deg): its
 * sequential, overlap (Sec. 4.3) and loop edges, checked for consistency; the scan merged into the map
 * (Eq. 4, 8) and the E-step (Eq. 14-15) on the vectors it touched, so every vector's state is known at
 * once. A loop edge makes Eq. 22 over the whole graph due: the one step whose cost grows with the map.
 * It runs outside addScan, either here (optimise()) or on a background thread (takeOptimisation,
 * runOptimisation there, applyOptimisation here); the map is then re-anchored to the corrected poses a
 * few keyframes per scan. addScan's cost is that of the robot's surroundings.
 *
 * Not thread-safe, except that runOptimisation() may run on one other thread while this one calls
 * addScan() and the queries. Every parameter is a GridVectorConfig key (doc/parameters.md). */
class OnlineEmSlam
{
   public:
	/** What one addScan did. */
	struct Step
	{
		mrpt::math::TPose2D pose;  //!< the scan's pose as known now
		bool registered = false;  //!< it came from a registration (else from the odometry alone)
		bool keyframe = false;  //!< the scan became a node of the pose graph and went into the map
		size_t loops = 0;  //!< loop edges it added (after the consistency check)
		size_t classified = 0;  //!< map vectors the E-step re-classified
	};

	/** A copy of the pose graph for Eq. 22 (takeOptimisation), solved by runOptimisation. Move-only. */
	class Optimisation
	{
	   public:
		Optimisation(Optimisation&&) noexcept;
		Optimisation& operator=(Optimisation&&) noexcept;
		~Optimisation();
		struct Job;

	   private:
		friend class OnlineEmSlam;
		explicit Optimisation(std::unique_ptr<Job> job);
		std::unique_ptr<Job> job_;
	};

	/** Throws std::invalid_argument if `cfg` fails GridVectorConfig::validate(). */
	explicit OnlineEmSlam(const GridVectorConfig& cfg = {});
	~OnlineEmSlam();
	OnlineEmSlam(const OnlineEmSlam&) = delete;
	OnlineEmSlam& operator=(const OnlineEmSlam&) = delete;

	/** One scan, taken at dead-reckoning pose `odometry` (any frame: the first scan's fixes the map's). */
	Step addScan(const mrpt::obs::CObservation2DRangeScan& scan, const mrpt::math::TPose2D& odometry);
	/** The same with the scan's vectors already extracted (VectorExtractor's output, robot frame). */
	Step addScan(const LocalScan& scan, const mrpt::math::TPose2D& odometry);

	/** Has a loop edge made Eq. 22 due? */
	bool optimisationDue() const;
	/** Eq. 22 now, on this thread: takeOptimisation, runOptimisation, applyOptimisation. */
	void optimise();
	/** The graph as it is now (no longer due). */
	Optimisation takeOptimisation();
	/** The solve; may run on another thread while addScan() runs. One at a time, applied in order. */
	void runOptimisation(Optimisation& job);
	/** The solved poses into the trajectory (keyframes added since follow the last of them), the map
	 * re-anchored if they moved. */
	void applyOptimisation(const Optimisation& job);
	/** End of the run: Eq. 22, a closing edge search over the whole trajectory, Eq. 22 again, and the map
	 * re-anchored at once. */
	void finish();

	size_t scans() const;
	mrpt::math::TPose2D currentPose() const;
	/** Every scan's pose at the current estimate. */
	std::vector<mrpt::math::TPose2D> trajectory() const;
	/** The scan index of every keyframe. */
	const std::vector<size_t>& keyframes() const;

	/** The live map's vectors split by state (Eq. 14, as of the last scan that touched each): static ones,
	 * then dynamic ones, ids 1..n. O(map): call when needed, not per scan. */
	std::vector<GridVector> vectors() const;
	std::vector<GridVector> staticMap() const;
	std::vector<GridVector> dynamicVectors() const;
	/** The batch's final map at the current trajectory (Eq. 8 over the keyframes, Eq. 14-15, Eq. 4 per
	 * state): for the end of a run. */
	std::vector<GridVector> finalMap() const;
	/** Sec. 5.4 on `map` (vectors() or finalMap()): Door::wall and Door::leaves index into it. */
	std::vector<Door> doors(const std::vector<GridVector>& map) const;
	/** The live static map as an occupancy grid (Eq. 6, occupancy.* keys). */
	mrpt::maps::COccupancyGridMap2D occupancyGrid() const;

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};

}  // namespace gridvector
