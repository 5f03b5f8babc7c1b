// CGridVectorMap: serialization (versioned) and text/SVG representation.
#include <gridvector/MapExport.h>
#include <gridvector/io/AtomicFile.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/serialization/CArchive.h>

#include <stdexcept>

using namespace mrpt::maps;
using gridvector::GridCell;
using gridvector::GridVector;

IMPLEMENTS_SERIALIZABLE(CGridVectorMap, CMetricMap, mrpt::maps)

namespace
{
// Config values are written in visit() order; the format version pins that order.
void writeConfig(mrpt::serialization::CArchive& out, const gridvector::GridVectorConfig& cfg)
{
	auto c = cfg;
	c.visitGroups([&](const char*, auto& g) {
		g.visit([&](const char*, auto& field, const char*) { out << field; });
	});
}

uint32_t countKeys(const gridvector::GridVectorConfig& cfg)
{
	auto c = cfg;
	uint32_t n = 0;
	c.visitGroups([&](const char*, auto& g) { g.visit([&](const char*, auto&, const char*) { ++n; }); });
	return n;
}
gridvector::GridVectorConfig readConfig(mrpt::serialization::CArchive& in)
{
	gridvector::GridVectorConfig c;
	uint32_t nkeys = 0;
	in >> nkeys;
	const uint32_t expected = countKeys(c);
	if (nkeys != expected)
		throw std::runtime_error("CGridVectorMap: stored config has " + std::to_string(nkeys) +
								 " keys, this version expects " + std::to_string(expected));
	c.visitGroups([&](const char*, auto& g) {
		g.visit([&](const char*, auto& field, const char*) { in >> field; });
	});
	return c;
}

}  // namespace

uint8_t CGridVectorMap::serializeGetVersion() const { return 0; }

void CGridVectorMap::serializeTo(mrpt::serialization::CArchive& out) const
{
	out << countKeys(map_.config());
	writeConfig(out, map_.config());
	out << likelihoodOptions.sigma << likelihoodOptions.maxCorrDistance << likelihoodOptions.zRandom
		<< int32_t(likelihoodOptions.decimation);
	out << uint64_t(insertedScans_) << uint64_t(map_.size());
	for (const auto& v : map_.vectors())
	{
		out << v.start().x << v.start().y << v.end().x << v.end().y;
		out << int32_t(v.cols()) << int64_t(v.scanIndex) << v.timestamp << v.id << uint8_t(v.state)
			<< v.mergedCount;
		out.WriteBuffer(v.cells().data(), v.cells().size() * sizeof(GridCell));
	}
	out << genericMapParams;
}

void CGridVectorMap::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	if (version != 0) MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	const gridvector::GridVectorConfig cfg = readConfig(in);
	int32_t decimation = 1;
	in >> likelihoodOptions.sigma >> likelihoodOptions.maxCorrDistance >> likelihoodOptions.zRandom >>
		decimation;
	likelihoodOptions.decimation = decimation;
	uint64_t scans = 0, n = 0;
	in >> scans >> n;
	std::vector<GridVector> vectors;
	vectors.reserve(size_t(n));
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
		if (cols < 1 || cols > 10'000'000 || state > 2)
			throw std::runtime_error("CGridVectorMap: corrupt vector record " + std::to_string(i));
		std::vector<GridCell> cells(size_t(cfg.grid.halfWidth * 2 + 1) * size_t(cols));
		in.ReadBuffer(cells.data(), cells.size() * sizeof(GridCell));
		GridVector v = GridVector::fromParts(s, e, cfg.grid, cols, std::move(cells));
		v.scanIndex = scanIndex;
		v.timestamp = t;
		v.id = id;
		v.state = gridvector::VectorState(state);
		v.mergedCount = merged;
		vectors.push_back(std::move(v));
	}
	in >> genericMapParams;
	setConfig(cfg);
	map_.setVectors(std::move(vectors));
	insertedScans_ = size_t(scans);
}

void CGridVectorMap::saveToFile(const std::string& path) const
{
	gridvector::io::AtomicFile f(path, gridvector::io::AtomicFile::Mode::External);
	{
		mrpt::io::CFileGZOutputStream gz;
		if (!gz.open(f.tempPath())) throw std::runtime_error(path + ": cannot write");
		auto a = mrpt::serialization::archiveFrom(gz);
		a << *this;
	}
	f.commit();
}

void CGridVectorMap::saveMetricMapRepresentationToFile(const std::string& prefix) const
{
	gridvector::MapExport::writeVectorsText(map_.vectors(), prefix + "_vectors.txt");
	gridvector::MapExport::writeSvg(map_.vectors(), prefix + "_vectors.svg");
	gridvector::MapExport::writePng(getAsOccupancyGrid(), prefix + "_occupancy.png");
}
