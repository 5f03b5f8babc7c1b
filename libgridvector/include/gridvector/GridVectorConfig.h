// gridvector: every tunable parameter of the system, with the paper's defaults.
//
// Each group is a plain struct with a visit() that lists its keys once; loading
// from MRPT .ini files, dumping, rejecting unknown keys and generating the
// parameter table in doc/parameters.md all walk that one list.
#pragma once

#include <mrpt/config/CConfigFileBase.h>

#include <cmath>
#include <iosfwd>
#include <string>

namespace gridvector
{
/** Sec. 3.1: split-and-merge line extraction (Borges & Aldon 2004). */
struct ExtractionOptions
{
	double minRange = 0.02;  //!< readings <= this are invalid [m]
	double maxRangeMargin = 0.01;  //!< readings >= maxRange - margin are "no hit" [m]
	double breakDistance = 0.20;  //!< absolute jump between neighbours that breaks a segment [m]
	double breakAngleDeg = 10.0;  //!< adaptive breakpoint: min incidence angle (Borges & Aldon) [deg]
	double splitThreshold = 0.04;  //!< max point-to-line distance before splitting [m]
	double mergeThreshold = 0.04;  //!< max residual for merging neighbouring segments [m]
	int minPoints = 5;  //!< minimum laser points per vector
	double minLength = 0.30;  //!< minimum vector length [m]
	double maxPointGap = 0.50;  //!< max gap between consecutive points of one vector [m]

	template <class V>
	void visit(V&& v)
	{
		v("min_range", minRange, "Readings at or below this range are invalid [m]");
		v("max_range_margin", maxRangeMargin, "Readings within this of the scanner's maxRange are 'no hit' [m]");
		v("break_distance", breakDistance, "Absolute range-jump threshold between neighbouring points [m]");
		v("break_angle_deg", breakAngleDeg, "Adaptive breakpoint: smallest incidence angle of a surface [deg]");
		v("split_threshold", splitThreshold, "Split a segment where a point lies further than this from its line [m]");
		v("merge_threshold", mergeThreshold, "Merge neighbouring collinear segments when the joint fit's max residual is below this [m]");
		v("min_points", minPoints, "Minimum laser points per vector");
		v("min_length", minLength, "Minimum vector length [m]");
		v("max_point_gap", maxPointGap, "Largest gap between consecutive points inside one vector; caps the adaptive breakpoint [m]");
	}
};

/** Sec. 3.1, Eq. 2: the slender grid carried by each vector. */
struct GridOptions
{
	double resolution = 0.10;  //!< cell size [m] (Table 1 compares with a 10 cm grid)
	int halfWidth = 1;  //!< cells on each side of the vector's own row
	double priorOccupy = 0.5;  //!< prior n_occupy (Sec. 3.1: 1/2)
	double priorVisit = 1.0;  //!< prior n_visit (Sec. 3.1: 1)

	template <class V>
	void visit(V&& v)
	{
		v("resolution", resolution, "Cell size of every vector's grid [m]");
		v("half_width", halfWidth, "Cells on each side of the vector's own row (width = 2*half_width+1)");
		v("prior_occupy", priorOccupy, "Prior n_occupy of a cell (paper: 1/2)");
		v("prior_visit", priorVisit, "Prior n_visit of a cell (paper: 1)");
	}
};

/** Sec. 3.2: global map update (Eq. 8 wipe triangles) and correspondence/merging. */
struct MapOptions
{
	double hitBand = 0.10;  //!< part c: cells within this of the new vector count as hits [m]
	double maxDirectionDiffDeg = 10.0;  //!< criterion 1: |psi_a - psi_b| [deg]
	double maxThetaDiffDeg = 10.0;  //!< criterion 2: |theta_a - theta_b| [deg]
	double maxRhoDiff = 0.15;  //!< criterion 2: |rho_a - rho_b| [m]
	double indexCellSize = 2.0;  //!< spatial index bucket size [m]
	bool mergeOnInsert = true;  //!< merge corresponding vectors (Algorithm 2) when inserting

	template <class V>
	void visit(V&& v)
	{
		v("hit_band", hitBand, "Eq. 8 part c: cells within this distance of the new vector get n_occupy and n_visit [m]");
		v("max_direction_diff_deg", maxDirectionDiffDeg, "Correspondence criterion 1: max difference of directions psi [deg]");
		v("max_theta_diff_deg", maxThetaDiffDeg, "Correspondence criterion 2: max difference of line normals theta [deg]");
		v("max_rho_diff", maxRhoDiff, "Correspondence criterion 2: max difference of line distances rho [m]");
		v("index_cell_size", indexCellSize, "Bucket size of the spatial index over vectors [m]");
		v("merge_on_insert", mergeOnInsert, "Merge corresponding vectors (Algorithm 2) as scans are inserted");
	}
};

/** Sec. 4.1, Eq. 14-15, Fig. 4: static/dynamic split of each vector. */
struct EStepOptions
{
	double staticThreshold = 0.40;  //!< profile value at or above which a piece is static
	double minPieceLength = 0.30;  //!< smallest sub-vector kept by the split-and-merge [m]

	template <class V>
	void visit(V&& v)
	{
		v("static_threshold", staticThreshold, "Occupancy-profile threshold: above is static, below dynamic");
		v("min_piece_length", minPieceLength, "Smallest static/dynamic sub-vector; shorter pieces merge into neighbours [m]");
	}
};

/** Sec. 4.2-4.3: vector-matching registration, pose graph, EM loop. */
struct MStepOptions
{
	int maxIterations = 10;  //!< EM iterations at most (stops earlier when no constraint changes)
	int sequentialWindow = 5;  //!< register each scan against this many predecessors
	double overlapDistance = 8.0;  //!< candidate edge when poses are closer than this [m]
	int minMatchedVectors = 3;  //!< a registration needs at least this many matched vectors
	int matcherMaxIterations = 20;  //!< iterations of the vector matcher
	double robustKernelWidth = 1.0;  //!< pose-graph robust kernel (chi) width

	template <class V>
	void visit(V&& v)
	{
		v("max_iterations", maxIterations, "EM iterations at most");
		v("sequential_window", sequentialWindow, "Register each scan against this many predecessors");
		v("overlap_distance", overlapDistance, "Poses closer than this are candidates for an edge [m]");
		v("min_matched_vectors", minMatchedVectors, "Minimum matched vectors for a registration");
		v("matcher_max_iterations", matcherMaxIterations, "Iterations of the vector matcher");
		v("robust_kernel_width", robustKernelWidth, "Width of the pose-graph robust kernel");
	}
};

/** Sec. 5.4: door detection from static/dynamic corners. */
struct DoorOptions
{
	double maxVertexDistance = 0.25;  //!< corners' vertices closer than this share a hinge [m]
	double maxLengthDiff = 0.15;  //!< dynamic vectors of equal length within this [m]
	double minDoorLength = 0.6;  //!< door leaf length range [m]
	double maxDoorLength = 1.4;

	template <class V>
	void visit(V&& v)
	{
		v("max_vertex_distance", maxVertexDistance, "Corners whose vertices are closer than this share a hinge [m]");
		v("max_length_diff", maxLengthDiff, "Dynamic vectors whose lengths differ by less than this are one door [m]");
		v("min_door_length", minDoorLength, "Shortest door leaf [m]");
		v("max_door_length", maxDoorLength, "Longest door leaf [m]");
	}
};

/** All parameters of gridvector. Sections in an .ini file are named
 * `<prefix>_<group>`: e.g. [gridvector_extraction], [gridvector_grid]. */
struct GridVectorConfig
{
	ExtractionOptions extraction;
	GridOptions grid;
	MapOptions map;
	EStepOptions estep;
	MStepOptions mstep;
	DoorOptions doors;

	template <class V>
	void visitGroups(V&& v)
	{
		v("extraction", extraction);
		v("grid", grid);
		v("map", map);
		v("estep", estep);
		v("mstep", mstep);
		v("doors", doors);
	}

	/** Reads every `<prefix>_<group>` section present. Throws std::runtime_error
	 * naming `sourceName` and the key if a section holds a key this version
	 * does not know (a typo must not silently fall back to a default). */
	void loadFromConfigFile(
		const mrpt::config::CConfigFileBase& cfg, const std::string& prefix = "gridvector",
		const std::string& sourceName = "config");
	/** Loads an .ini file; throws std::runtime_error("FILE: problem"). */
	void loadFromFile(const std::string& iniPath, const std::string& prefix = "gridvector");
	/** Writes all sections as a valid .ini file. */
	void dumpAsIni(std::ostream& out, const std::string& prefix = "gridvector") const;
	/** Markdown table of every parameter (section, key, default, meaning). */
	static std::string parameterTableMarkdown(const std::string& prefix = "gridvector");
	/** Throws std::invalid_argument if a value is out of its valid range. */
	void validate() const;
};

}  // namespace gridvector
