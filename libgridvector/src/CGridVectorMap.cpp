// CGridVectorMap: map definition (registry), construction, clear, description.
#include <gridvector/OccupancyConversion.h>
#include <mrpt/config/CConfigFileBase.h>
#include <mrpt/maps/CGridVectorMap.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <sstream>

using namespace mrpt::maps;

MAP_DEFINITION_REGISTER("mrpt::maps::CGridVectorMap,gridVectorMap", mrpt::maps::CGridVectorMap)

CGridVectorMap::TMapDefinition::TMapDefinition() = default;

void CGridVectorMap::TMapDefinition::loadFromConfigFile_map_specific(
	const mrpt::config::CConfigFileBase& source, const std::string& sectionNamePrefix)
{
	// [<prefix>_extraction], [<prefix>_grid], ... : see GridVectorConfig; [<prefix>_creationOpts]
	// is MRPT's (TMapGenericParams, read by TMetricMapInitializer), [<prefix>_likelihoodOpts] below.
	try
	{
		config.loadFromConfigFile(source, sectionNamePrefix, "CGridVectorMap config", {"creationOpts", "likelihoodOpts"});
		likelihoodOpts.loadFromConfigFile(source, sectionNamePrefix + "_likelihoodOpts");
	}
	catch (const std::exception& e)
	{
		// MRPT's apps print an exception as "Location: <text up to the first ']'>" and "Message: <the
		// rest>" (its own are "file:line: [function] message"); a message holding "[section]" came
		// out cut in two, so give it that shape.
		throw std::runtime_error(std::string("[CGridVectorMap::TMapDefinition] ") + e.what());
	}
}

void CGridVectorMap::TMapDefinition::dumpToTextStream_map_specific(std::ostream& out) const
{
	config.dumpAsIni(out, "<prefix>");
	likelihoodOpts.dumpToTextStream(out);
}

mrpt::maps::CMetricMap* CGridVectorMap::internal_CreateFromMapDefinition(
	const mrpt::maps::TMetricMapInitializer& _def)
{
	const auto& def = dynamic_cast<const CGridVectorMap::TMapDefinition&>(_def);
	auto* obj = new CGridVectorMap(def.config);
	obj->likelihoodOptions = def.likelihoodOpts;
	return obj;
}

CGridVectorMap::CGridVectorMap(const gridvector::GridVectorConfig& cfg)
	: map_(cfg), extractor_(cfg.extraction, cfg.grid)
{
}

// Eq. 6: every cell of an MRPT grid from the vectors' counts.
COccupancyGridMap2D CGridVectorMap::getAsOccupancyGrid() const
{
	return gridvector::OccupancyConversion::toOccupancyGrid(map_.vectors(), map_.config().occupancy,
														   map_.config().grid);
}

void CGridVectorMap::setConfig(const gridvector::GridVectorConfig& cfg)
{
	cfg.validate();
	const auto& old = map_.config().grid;
	if (!map_.empty() && (cfg.grid.resolution != old.resolution || cfg.grid.halfWidth != old.halfWidth))
		throw std::invalid_argument(
			"CGridVectorMap::setConfig: grid.resolution and grid.half_width of a non-empty map cannot change (its "
			"vectors' grids are laid out with them)");
	map_.setConfig(cfg);
	extractor_ = gridvector::VectorExtractor(cfg.extraction, cfg.grid);
}

void CGridVectorMap::internal_clear()
{
	map_.clear();
	insertedScans_ = 0;
}

bool CGridVectorMap::isEmpty() const { return map_.empty(); }

std::string CGridVectorMap::asString() const
{
	double len = 0;
	size_t nStatic = 0, nDynamic = 0;
	for (const auto& v : map_.vectors())
	{
		len += v.length();
		nStatic += v.state == gridvector::VectorState::Static;
		nDynamic += v.state == gridvector::VectorState::Dynamic;
	}
	std::ostringstream os;
	os << "CGridVectorMap: " << map_.size() << " grid vectors (" << nStatic << " static, "
	   << nDynamic << " dynamic), total length " << len << " m, " << insertedScans_
	   << " scans inserted, resolution " << map_.config().grid.resolution << " m";
	return os.str();
}

void CGridVectorMap::TLikelihoodOptions::loadFromConfigFile(
	const mrpt::config::CConfigFileBase& source, const std::string& section)
{
	if (source.sectionExists(section))
	{
		std::vector<std::string> keys;
		source.getAllKeys(section, keys);
		for (const auto& k : keys)
			if (k != "sigma" && k != "maxCorrDistance" && k != "zRandom" && k != "decimation")
				throw std::runtime_error(
					"CGridVectorMap config: unknown key '" + k + "' in section [" + section + "]");
	}
	// strictly: MRPT's read_double / read_int take "abc" as 0 and "2.5" as 2
	auto read = [&](const char* key, double& field, bool integer, bool ok(double)) {
		if (!source.keyExists(section, key)) return;
		std::string text = source.read_string(section, key, "");
		while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
		char* end = nullptr;
		const double v = std::strtod(text.c_str(), &end);
		if (text.empty() || *end || !std::isfinite(v) || (integer && v != std::floor(v)) || !ok(v))
			throw std::runtime_error("CGridVectorMap config: [" + section + "] " + key + " = '" + text + "' is not " +
									 (integer ? "an integer >= 1" : "a valid value (sigma, maxCorrDistance > 0; zRandom in [0,1))"));
		field = v;
	};
	double dec = decimation;
	read("sigma", sigma, false, [](double v) { return v > 0; });
	read("maxCorrDistance", maxCorrDistance, false, [](double v) { return v > 0; });
	read("zRandom", zRandom, false, [](double v) { return v >= 0 && v < 1; });
	read("decimation", dec, true, [](double v) { return v >= 1 && v <= 1e6; });
	decimation = int(dec);
}

void CGridVectorMap::TLikelihoodOptions::dumpToTextStream(std::ostream& out) const
{
	out << "[<prefix>_likelihoodOpts]\nsigma = " << sigma << "\nmaxCorrDistance = " << maxCorrDistance
		<< "\nzRandom = " << zRandom << "\ndecimation = " << decimation << "\n";
}
