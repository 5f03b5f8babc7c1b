// CGridVectorMap: serialization (versioned) and text/SVG representation.
#include "map/CompactMap.h"
#include "map/MapExport.h"
#include "io/ArchiveFile.h"
#include "io/AtomicFile.h"
#include "io/ObjectFile.h"
#include <mrpt/io/CFileGZOutputStream.h>
#include "mrpt/CGridVectorMapImpl.h"
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/serialization/CArchive.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

using namespace mrpt::maps;
using gridvector::GridCell;
using gridvector::GridVector;

IMPLEMENTS_SERIALIZABLE(CGridVectorMap, CMetricMap, mrpt::maps)

namespace
{
// Version 0 (frozen): the key count, then every config value in visit() order.
uint32_t countKeys(const gridvector::GridVectorConfig& cfg) { return uint32_t(cfg.namedValues().size()); }

gridvector::GridVectorConfig readConfigV0(mrpt::serialization::CArchive& in)
{
	gridvector::GridVectorConfig c;
	uint32_t nkeys = 0;
	in >> nkeys;
	const uint32_t expected = countKeys(c);
	if (nkeys != expected)
		throw std::runtime_error("CGridVectorMap: stored config has " + std::to_string(nkeys) +
								 " keys, this version expects " + std::to_string(expected) +
								 " (a version-0 .gvmap stores its config by position)");
	c.visitGroups([&](const char*, auto& g) {
		g.visit([&](const char*, auto& field, const char*, const gridvector::Range&) { in >> field; });
	});
	try
	{
		c.validate();
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(std::string("CGridVectorMap: stored config: ") + e.what());
	}
	return c;
}

// Version 1: (name, value) pairs, "group.key" as a uint8 length + bytes, the value as a double.
constexpr uint32_t kMaxStoredKeys = 4096;

void writeConfigV1(mrpt::serialization::CArchive& out, const gridvector::GridVectorConfig& cfg)
{
	const auto named = cfg.namedValues();
	out << uint32_t(named.size());
	for (const auto& [name, value] : named)
	{
		if (name.size() > 255) throw std::logic_error("CGridVectorMap: config key longer than 255 bytes: " + name);
		out << uint8_t(name.size());
		out.WriteBuffer(name.data(), name.size());
		out << value;
	}
}

// Keys of earlier versions that are gone: deleted, or named constants now. A map written with one
// loads; its value is not used (the map's vectors are what they were; new scans follow this version).
const std::set<std::string>& retiredKeys()
{
	static const std::set<std::string> keys = {// the 64 keys of 5eec48d that issue 20 retired
											   "doors.closed_leaf_hidden_ends",
											   "doors.closed_leaf_to_latch",
											   "doors.leaf_chain_gap",
											   "doors.leaf_chain_max_turn_deg",
											   "doors.max_tee_offset",
											   "doors.min_open_deg",
											   "doors.min_sweep_deg",
											   "estep.hysteresis",
											   "estep.rerun_rotation_deg",
											   "estep.rerun_translation",
											   "extraction.max_range_margin",
											   "map.index_cell_size",
											   "map.merge_cascade_rounds",
											   "map.merge_group_rounds",
											   "map.merge_regrid_tolerance",
											   "map.wipe_counts_beams",
											   "map.wipe_vectorless_beams",
											   "matcher.angle_rotation_seeds",
											   "matcher.convergence_rotation",
											   "matcher.convergence_translation",
											   "matcher.degenerate_projection",
											   "matcher.gate_shrink",
											   "matcher.max_iterations",
											   "matcher.robust_scale_gate_share",
											   "matcher.sigma_floor",
											   "mstep.changed_rotation",
											   "mstep.changed_translation",
											   "mstep.consistency_chain_var_phi",
											   "mstep.consistency_chain_var_xy",
											   "mstep.consistency_info_phi",
											   "mstep.consistency_info_xy",
											   "mstep.drop_distance_factor",
											   "mstep.drop_length_share",
											   "mstep.loop_corner_max_gap",
											   "mstep.loop_corner_min_angle_deg",
											   "mstep.loop_corner_min_length",
											   "mstep.loop_corner_turn_tolerance_deg",
											   "mstep.loop_distinct_deg",
											   "mstep.loop_duplicate_deg",
											   "mstep.loop_duplicate_distance",
											   "mstep.loop_score_gate_factor",
											   "mstep.loop_search_candidate_spacing",
											   "mstep.loop_search_distinct",
											   "mstep.loop_window_min_rotation_deg",
											   "mstep.loop_window_min_translation",
											   "mstep.moved_gate_share",
											   "mstep.recheck_gate_factor",
											   "mstep.reconsider_free_steps",
											   "mstep.register_min_incidence_deg",
											   "mstep.searched_near_deg",
											   "mstep.searched_near_distance",
											   "mstep.strong_min_correspondences",
											   "mstep.strong_min_degeneracy",
											   "mstep.strong_min_share",
											   "posegraph.correlated_group_gap",
											   "posegraph.use_mrpt_optimizer",
											   "posegraph.correlated_group_rho",
											   "posegraph.graduation_iterations",
											   "posegraph.graduation_percentile",
											   "posegraph.graduation_tolerance",
											   "posegraph.lm_initial_lambda",
											   "posegraph.lm_max_lambda",
											   "posegraph.lm_min_lambda",
											   "posegraph.tolerance"};
	return keys;
}

// Keys missing from the stream keep their defaults; a retired key is skipped; a key this version
// does not know is an error.
gridvector::GridVectorConfig readConfigV1(mrpt::serialization::CArchive& in)
{
	gridvector::GridVectorConfig c;
	uint32_t nkeys = 0;
	in >> nkeys;
	if (nkeys > kMaxStoredKeys)
		throw std::runtime_error("CGridVectorMap: corrupt config record (" + std::to_string(nkeys) + " keys)");
	for (uint32_t k = 0; k < nkeys; ++k)
	{
		uint8_t len = 0;
		in >> len;
		std::string name(len, '\0');
		in.ReadBuffer(name.data(), len);
		double value = 0;
		in >> value;
		for (char ch : name)
			if (!(std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '.'))
				throw std::runtime_error("CGridVectorMap: corrupt config record (key " + std::to_string(k) + ")");
		if (retiredKeys().count(name)) continue;
		bool known = false;
		try
		{
			known = c.setNamedValue(name, value);
		}
		catch (const std::invalid_argument& e)
		{
			throw std::runtime_error(std::string("CGridVectorMap: stored config: ") + e.what());
		}
		if (!known)
			throw std::runtime_error("CGridVectorMap: stored config key '" + name +
									 "' is unknown to this version of gridvector (map written by a newer version?)");
	}
	try
	{
		c.validate();
	}
	catch (const std::invalid_argument& e)
	{
		throw std::runtime_error(std::string("CGridVectorMap: stored config: ") + e.what());
	}
	return c;
}

/** Columns a stored grid may have beyond its length: Intel's and ACES's maps have at most 2. */
constexpr double kMaxExtraColumns = 4;

bool finite(const mrpt::math::TPoint2D& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

/** The stored likelihood options pass the checks of the .ini path (TLikelihoodOptions::loadFromConfigFile). */
void requireLikelihoodOptions(const CGridVectorMap::TLikelihoodOptions& o)
{
	const auto bad = [](const char* key, double v, const char* want) {
		throw std::runtime_error("CGridVectorMap: stored likelihood option " + std::string(key) + " = " +
								 std::to_string(v) + " (must be " + want + ")");
	};
	if (!(o.sigma > 0 && std::isfinite(o.sigma))) bad("sigma", o.sigma, "a number > 0");
	if (!(o.maxCorrDistance > 0 && std::isfinite(o.maxCorrDistance)))
		bad("maxCorrDistance", o.maxCorrDistance, "a number > 0");
	if (!(o.zRandom >= 0 && o.zRandom < 1)) bad("zRandom", o.zRandom, "a number in [0,1)");
	if (!(o.decimation >= 1 && o.decimation <= 1000000)) bad("decimation", o.decimation, "an integer in [1,1000000]");
}

/** Counts are non-negative and finite, the sums finite: what Algorithm 1 and 2 can produce. */
void requireCells(const std::vector<GridCell>& cells, uint64_t vector)
{
	for (const GridCell& c : cells)
	{
		const bool counts = c.n_acc >= 0 && c.n_occupy >= 0 && c.n_visit >= 0 && std::isfinite(c.n_acc) &&
							std::isfinite(c.n_occupy) && std::isfinite(c.n_visit);
		if (!counts || !std::isfinite(c.x_acc) || !std::isfinite(c.y_acc))
			throw std::runtime_error("CGridVectorMap: corrupt vector record " + std::to_string(vector) +
									 " (a cell with a negative or non-finite count)");
	}
}

/** A vector record's geometry: finite endpoints, a known state, a grid that covers its vector
 * (cols is ceil(length / resolution), up to kMaxExtraColumns more after merges: Algorithm 2). */
void requireRecord(const mrpt::math::TPoint2D& s, const mrpt::math::TPoint2D& e, int64_t cols, uint8_t state,
				   const gridvector::GridVectorConfig& cfg, uint64_t i)
{
	const double lengthInCells = std::hypot(e.x - s.x, e.y - s.y) / cfg.grid.resolution;
	const bool covers = cols + 1 >= lengthInCells && cols <= lengthInCells + kMaxExtraColumns;
	if (cols < 1 || cols > 10'000'000 || state > 2 || !finite(s) || !finite(e) || !(lengthInCells < 1e6) || !covers)
		throw std::runtime_error("CGridVectorMap: corrupt vector record " + std::to_string(i));
}

// The cells of one vector, read in chunks so that a corrupt column count fails at the end
// of the data instead of allocating what it claims.
std::vector<GridCell> readCells(mrpt::serialization::CArchive& in, size_t count)
{
	constexpr size_t kChunk = 1 << 16;
	std::vector<GridCell> cells;
	for (size_t done = 0; done < count;)
	{
		const size_t n = std::min(kChunk, count - done);
		cells.resize(done + n);
		in.ReadBuffer(cells.data() + done, n * sizeof(GridCell));
		done += n;
	}
	return cells;
}

}  // namespace

/** Version 2: the vectors as one CompactMap buffer (half-float counts, only the cells' evidence),
 * instead of version 1's doubles and 20-byte cells. */
uint8_t CGridVectorMap::serializeGetVersion() const { return 2; }

void CGridVectorMap::serializeTo(mrpt::serialization::CArchive& out) const
{
	writeConfigV1(out, impl_->map.config());
	out << likelihoodOptions.sigma << likelihoodOptions.maxCorrDistance << likelihoodOptions.zRandom
		<< int32_t(likelihoodOptions.decimation);
	const gridvector::CompactMap compact = gridvector::CompactMap::encode(impl_->map.vectors());
	out << uint64_t(insertedScans_) << uint64_t(compact.bytes().size());
	out.WriteBuffer(compact.bytes().data(), compact.bytes().size());
	out << genericMapParams;
}

namespace
{
/** Version 0/1 vector records: geometry and bookkeeping as doubles and integers, then the cells as stored. */
std::vector<GridVector> readVectorsV1(mrpt::serialization::CArchive& in, const gridvector::GridVectorConfig& cfg,
									  uint64_t n)
{
	std::vector<GridVector> vectors;
	vectors.reserve(size_t(std::min<uint64_t>(n, 1 << 16)));
	for (uint64_t i = 0; i < n; ++i)
	{
		mrpt::math::TPoint2D s, e;
		int32_t cols = 0;
		int64_t scanIndex = 0;
		uint8_t state = 0;
		double t = 0;
		uint64_t id = 0;
		uint32_t merged = 1;
		in >> s.x >> s.y >> e.x >> e.y >> cols >> scanIndex >> t >> id >> state >> merged;
		requireRecord(s, e, cols, state, cfg, i);
		std::vector<GridCell> cells = readCells(in, size_t(cfg.grid.halfWidth * 2 + 1) * size_t(cols));
		requireCells(cells, i);
		GridVector v = GridVector::fromParts(s, e, cfg.grid, cols, std::move(cells));
		v.scanIndex = scanIndex;
		v.timestamp = t;
		v.id = id;
		v.state = gridvector::VectorState(state);
		v.mergedCount = merged;
		vectors.push_back(std::move(v));
	}
	return vectors;
}

/** Most bytes a version-2 vector buffer may claim: 2^32, far beyond any map (and read in chunks). */
constexpr uint64_t kMaxCompactBytes = uint64_t(1) << 32;

/** Version 2: the CompactMap buffer, decoded, each vector checked as a version-1 record. */
std::vector<GridVector> readVectorsV2(mrpt::serialization::CArchive& in, const gridvector::GridVectorConfig& cfg)
{
	uint64_t size = 0;
	in >> size;
	if (size > kMaxCompactBytes) throw std::runtime_error("CGridVectorMap: corrupt vector buffer (" + std::to_string(size) + " bytes)");
	std::vector<uint8_t> bytes;
	constexpr size_t kChunk = 1 << 20;
	for (size_t done = 0; done < size;)
	{
		const size_t n = std::min<size_t>(kChunk, size_t(size) - done);
		bytes.resize(done + n);
		in.ReadBuffer(bytes.data() + done, n);
		done += n;
	}
	std::vector<GridVector> vectors;
	try
	{
		vectors = gridvector::CompactMap::fromBytes(std::move(bytes)).decode(cfg.grid);
	}
	catch (const std::runtime_error& e)
	{
		throw std::runtime_error(std::string("CGridVectorMap: corrupt vector buffer (") + e.what() + ")");
	}
	for (size_t i = 0; i < vectors.size(); ++i)
	{
		const GridVector& v = vectors[i];
		requireRecord(v.start(), v.end(), v.cols(), uint8_t(v.state), cfg, i);
		requireCells(v.cells(), i);
	}
	return vectors;
}
}  // namespace

// Versions 0 and 1 differ only in the config record; version 2 stores the vectors compactly.
void CGridVectorMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	if (version > 2) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	const gridvector::GridVectorConfig cfg = version == 0 ? readConfigV0(in) : readConfigV1(in);
	int32_t decimation = 1;
	in >> likelihoodOptions.sigma >> likelihoodOptions.maxCorrDistance >> likelihoodOptions.zRandom >> decimation;
	likelihoodOptions.decimation = decimation;
	requireLikelihoodOptions(likelihoodOptions);
	uint64_t scans = 0;
	in >> scans;
	std::vector<GridVector> vectors;
	if (version < 2)
	{
		uint64_t n = 0;
		in >> n;
		vectors = readVectorsV1(in, cfg, n);
	}
	else
		vectors = readVectorsV2(in, cfg);
	in >> genericMapParams;
	impl_->map.clear();
	setConfig(cfg);
	impl_->map.setVectors(std::move(vectors));
	insertedScans_ = size_t(scans);
}

void CGridVectorMap::saveToFile(const std::string& path) const
{
	gridvector::io::writeArchiveFile(path, true, [&](mrpt::serialization::CArchive& a) { a << *this; });
}

void CGridVectorMap::loadFromFile(const std::string& path)
{
	CGridVectorMap loaded;
	gridvector::io::readObjectFile(path, loaded);
	*this = std::move(loaded);
}

void CGridVectorMap::saveMetricMapRepresentationToFile(const std::string& prefix) const
{
	gridvector::MapExport::writeVectorsText(impl_->map.vectors(), prefix + "_vectors.txt");
	gridvector::MapExport::writeSvg(impl_->map.vectors(), prefix + "_vectors.svg");
	gridvector::MapExport::writePng(getAsOccupancyGrid(), prefix + "_occupancy.png");
}
