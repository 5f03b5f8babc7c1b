// gridvector: the grid vector map (Wang, Xiong, Chu 2011) as an MRPT metric map.
#pragma once

#include <gridvector/GridVector.h>
#include <gridvector/GridVectorConfig.h>
#include <gridvector/LocalScan.h>

#include <mrpt/config/CLoadableOptions.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/maps/CMetricMap.h>
#include <mrpt/obs/CObservation2DRangeScan.h>

#include <memory>
#include <vector>

namespace gridvector
{
class GlobalMap;  // the library's internals (libgridvector/src/map/GlobalMap.h)
}

namespace mrpt::maps
{
/** A map of grid vectors: directed line segments (open space on their left)
 * each carrying a slender occupancy grid (Sec. 3 of the paper).
 *
 * Inserting a CObservation2DRangeScan extracts its grid vectors (Sec. 3.1),
 * compounds them with the robot pose and updates the global map (Sec. 3.2:
 * wipe triangles, correspondence, Algorithm 2 merging).
 *
 * In a CMultiMetricMap .ini (short name `gridVectorMap`):
 * \code
 * [MappingApplication]
 * gridVectorMap_count = 1
 * ; optional, every key of gridvector::GridVectorConfig, grouped:
 * [MappingApplication_gridVectorMap_00_extraction]
 * split_threshold = 0.04
 * [MappingApplication_gridVectorMap_00_grid]
 * resolution = 0.10
 * [MappingApplication_gridVectorMap_00_likelihoodOpts]
 * sigma = 0.30
 * \endcode
 * or in MRPT's own section names, as for COccupancyGridMap2D: the grid group's keys in
 * `[..._creationOpts]` (next to MRPT's enableSaveAs3DObject, ...), the extraction and map
 * groups' in `[..._insertOpts]` (libgridvector/src/mrpt/MrptOptionSections.h).
 * Unknown keys in these sections are an error, not silently ignored.
 *
 * Threads: every const member (likelihood, matching, getAsOccupancyGrid,
 * asString, visualisation, save*) may run in any number of threads at once,
 * as long as no thread modifies the map meanwhile (insert, clear, setConfig,
 * deserialisation, globalMap() non-const): the standard library's contract.
 * A const call keeps its scratch to itself; the matching calls share the
 * vectors' static stretches, computed once per map state (each entry filled
 * once, under std::call_once). */
class CGridVectorMap : public CMetricMap
{
	DEFINE_SERIALIZABLE(CGridVectorMap, mrpt::maps)

   public:
	explicit CGridVectorMap(const gridvector::GridVectorConfig& cfg = {});
	CGridVectorMap(const CGridVectorMap& o);
	CGridVectorMap(CGridVectorMap&& o);
	CGridVectorMap& operator=(const CGridVectorMap& o);
	CGridVectorMap& operator=(CGridVectorMap&& o) noexcept;
	~CGridVectorMap() override;

	/** Parameters of computeObservationLikelihood(): MRPT's likelihood field over the vectors,
	 * each weighted by its wall row's occupancy. The defaults localise with MRPT's particle filter
	 * as MRPT's grid does with its test's options (tests/mrpt_generic_checks_test.cpp, MonteCarlo2D):
	 * sigma is the spread of a particle's points about the walls (its pose error as well as the
	 * range noise: MRPT's grid default LF_stdHit is 0.35), not the range noise alone; 0.05 and one
	 * beam in 2 made every scan so sharp that the filter kept a wrong pose 4.5 m off. */
	struct TLikelihoodOptions : public mrpt::config::CLoadableOptions
	{
		double sigma = 0.30;  //!< std. dev. of a point's distance to the nearest wall [m]
		double maxCorrDistance = 0.50;  //!< beyond this a point reads as this far from a wall [m]
		double zRandom = 0.05;  //!< weight of the uniform "random measurement" term
		int decimation = 10;  //!< use one beam out of this many
		void loadFromConfigFile(const mrpt::config::CConfigFileBase& source, const std::string& section) override;
		void dumpToTextStream(std::ostream& out) const override;
	} likelihoodOptions;

	// --- access ---
	/** The map's internals (the library's own code, its tests and apps). */
	const gridvector::GlobalMap& globalMap() const;
	gridvector::GlobalMap& globalMap();
	/** The map's vectors, world frame (state, p_static and the cells in each). */
	const std::vector<gridvector::GridVector>& vectors() const;
	const gridvector::GridVectorConfig& config() const;
	void setConfig(const gridvector::GridVectorConfig& cfg);
	size_t insertedScans() const { return insertedScans_; }

	/** Eq. 6: the map as an MRPT occupancy grid, with the options of the
	 * `[..._occupancy]` group (resolution, margin, sample points, pooling). */
	mrpt::maps::COccupancyGridMap2D getAsOccupancyGrid() const;
	/** Extract the grid vectors of a scan in the robot frame (Sec. 3.1). */
	gridvector::LocalScan extractLocal(const mrpt::obs::CObservation2DRangeScan& scan) const;

	// --- CMetricMap ---
	bool isEmpty() const override;
	/** Writes `<prefix>_vectors.txt` (x1 y1 x2 y2 p_static per line),
	 * `<prefix>_vectors.svg` and the Eq. 6 grid as `<prefix>_occupancy.png`. */
	void saveMetricMapRepresentationToFile(const std::string& prefix) const override;
	/** Writes the serialized map, gzip-compressed (a `.gvmap`), atomically;
	 * throws std::runtime_error("path: cannot write ..."). */
	void saveToFile(const std::string& path) const;
	/** Replaces this map by the one saveToFile() wrote at `path` (gzip-compressed or not): its
	 * configuration, likelihood options, vectors and scan count. Throws std::runtime_error
	 * ("path: no such file", "path: not a valid mrpt::maps::CGridVectorMap file (why)", ...) and
	 * leaves this map unchanged on any error. */
	void loadFromFile(const std::string& path);
	std::string asString() const override;
	/** Vectors as line segments coloured by p_static (blue static .. red dynamic). */
	void getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const override;

	// --- CMetricMap matching: the map as the reference ("this", m1) of mrpt::slam::CICP (icpClassic) ---
	/** Each point of `otherMap` (a CPointsMap; std::invalid_argument otherwise), moved by
	 * otherMapPose, is paired with the nearest of the fixed places every half cell along the map's
	 * static stretches (gridvector::StaticFootPoints: vectors not classified dynamic, their columns whose Fig. 4
	 * profile is at least matching.static_threshold, 0 by default: all) closer than
	 * params.maxDistForCorrespondence + params.maxAngularDistForCorrespondence x its distance to
	 * params.angularDistPivotPoint. Pairs: `global` = that point on the vector's line (z = the
	 * point's z), globalIdx = the vector's index in vectors(); `local` = the point in the other
	 * map's own frame, localIdx its index; errorSquareAfterTransformation = the squared distance.
	 * onlyKeepTheClosest = false: one pair per vector within the gate. onlyUniqueRobust: one pair
	 * per (vector, grid column), the closest. Points offset, offset + decimation, ... are used.
	 * extraResults: sumSqrDist = the sum over the points with a correspondence of the closest
	 * squared distance (as COccupancyGridMap2D and the header's contract; CPointsMap gives the
	 * mean); correspondencesRatio = those points / the points used. */
	void determineMatching2D(const mrpt::maps::CMetricMap* otherMap, const mrpt::poses::CPose2D& otherMapPose,
							 mrpt::tfest::TMatchingPairList& correspondences, const TMatchingParams& params,
							 TMatchingExtraResults& extraResults) const override;
	/** The share of the other map's points (a CPointsMap), moved by the 3D pose and projected on
	 * the plane, within params.maxDistForCorr of a static stretch. */
	float compute3DMatchingRatio(const mrpt::maps::CMetricMap* otherMap, const mrpt::poses::CPose3D& otherMapPose,
								 const TMatchingRatioParams& params) const override;
	/** Squared distance from (x0, y0) to the nearest point of a static stretch, no gate
	 * (float max if the map has none). */
	float squareDistanceToClosestCorrespondence(float x0, float y0) const override;

	MAP_DEFINITION_START(CGridVectorMap)
	gridvector::GridVectorConfig config;  //!< all mapping parameters
	TLikelihoodOptions likelihoodOpts;
	MAP_DEFINITION_END(CGridVectorMap)

   private:
	void internal_clear() override;
	bool internal_insertObservation(const mrpt::obs::CObservation& obs,
									const std::optional<const mrpt::poses::CPose3D>& robotPose) override;
	double internal_computeObservationLikelihood(const mrpt::obs::CObservation& obs,
												 const mrpt::poses::CPose3D& takenFrom) const override;
	bool internal_canComputeObservationLikelihood(const mrpt::obs::CObservation& obs) const override;

	/** The global map, the extractor and the matching calls' static stretches (kept while the
	 * map does not change: GlobalMap::revision()); libgridvector/src/mrpt/CGridVectorMapImpl.h. */
	struct Impl;
	std::unique_ptr<Impl> impl_;
	size_t insertedScans_ = 0;
};

}  // namespace mrpt::maps
