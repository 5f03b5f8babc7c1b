// CGridVectorMap: map definition (registry), construction, clear, description.
#include "map/OccupancyConversion.h"
#include "io/IniValue.h"
#include <mrpt/config/CConfigFileBase.h>
#include "mrpt/CGridVectorMapImpl.h"
#include "mrpt/MrptOptionSections.h"
#include <mrpt/maps/CGridVectorMap.h>

#include <stdexcept>

#include <sstream>

using namespace mrpt::maps;

MAP_DEFINITION_REGISTER("mrpt::maps::CGridVectorMap,gridVectorMap", mrpt::maps::CGridVectorMap)

CGridVectorMap::TMapDefinition::TMapDefinition() = default;

void CGridVectorMap::TMapDefinition::loadFromConfigFile_map_specific(const mrpt::config::CConfigFileBase& source,
																	 const std::string& sectionNamePrefix)
{
	// [<prefix>_extraction], [<prefix>_grid], ... : see GridVectorConfig; MRPT's names
	// [<prefix>_creationOpts] and [<prefix>_insertOpts]: readMrptOptionSections; [<prefix>_likelihoodOpts] below.
	try
	{
		const std::string from = "CGridVectorMap config";
		config.loadFromConfigFile(source, sectionNamePrefix, from, {"creationOpts", "insertOpts", "likelihoodOpts"});
		gridvector::readMrptOptionSections(source, sectionNamePrefix, config, from);
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

mrpt::maps::CMetricMap* CGridVectorMap::internal_CreateFromMapDefinition(const mrpt::maps::TMetricMapInitializer& _def)
{
	const auto& def = dynamic_cast<const CGridVectorMap::TMapDefinition&>(_def);
	auto* obj = new CGridVectorMap(def.config);
	obj->likelihoodOptions = def.likelihoodOpts;
	return obj;
}

CGridVectorMap::CGridVectorMap(const gridvector::GridVectorConfig& cfg) : impl_(std::make_unique<Impl>(cfg)) {}
CGridVectorMap::CGridVectorMap(const CGridVectorMap& o)
	: CMetricMap(o),
	  likelihoodOptions(o.likelihoodOptions),
	  impl_(std::make_unique<Impl>(*o.impl_)),
	  insertedScans_(o.insertedScans_)
{}
// The moved-from map is left empty, with its configuration.
CGridVectorMap::CGridVectorMap(CGridVectorMap&& o)
	: CMetricMap(std::move(o)),
	  likelihoodOptions(o.likelihoodOptions),
	  impl_(std::make_unique<Impl>(o.config())),
	  insertedScans_(o.insertedScans_)
{
	std::swap(impl_, o.impl_);
	o.insertedScans_ = 0;
}
CGridVectorMap& CGridVectorMap::operator=(const CGridVectorMap& o)
{
	if (this != &o)
	{
		CMetricMap::operator=(o);
		likelihoodOptions = o.likelihoodOptions;
		*impl_ = *o.impl_;
		insertedScans_ = o.insertedScans_;
	}
	return *this;
}
CGridVectorMap& CGridVectorMap::operator=(CGridVectorMap&& o) noexcept
{
	CMetricMap::operator=(std::move(o));
	likelihoodOptions = o.likelihoodOptions;
	std::swap(impl_, o.impl_);  // o keeps this map's old state: valid, as a moved-from object must be
	std::swap(insertedScans_, o.insertedScans_);
	return *this;
}
CGridVectorMap::~CGridVectorMap() = default;

const gridvector::GlobalMap& CGridVectorMap::globalMap() const { return impl_->map; }
gridvector::GlobalMap& CGridVectorMap::globalMap() { return impl_->map; }
const std::vector<gridvector::GridVector>& CGridVectorMap::vectors() const { return impl_->map.vectors(); }
const gridvector::GridVectorConfig& CGridVectorMap::config() const { return impl_->map.config(); }

// Eq. 6: every cell of an MRPT grid from the vectors' counts.
COccupancyGridMap2D CGridVectorMap::getAsOccupancyGrid() const
{
	return gridvector::OccupancyConversion::toOccupancyGrid(impl_->map.vectors(), impl_->map.config().occupancy,
															impl_->map.config().grid);
}

void CGridVectorMap::setConfig(const gridvector::GridVectorConfig& cfg)
{
	cfg.validate();
	const auto& old = impl_->map.config().grid;
	if (!impl_->map.empty() && (cfg.grid.resolution != old.resolution || cfg.grid.halfWidth != old.halfWidth))
		throw std::invalid_argument(
			"CGridVectorMap::setConfig: grid.resolution and grid.half_width of a non-empty map cannot change (its "
			"vectors' grids are laid out with them)");
	impl_->map.setConfig(cfg);
	impl_->extractor = gridvector::VectorExtractor(cfg.extraction, cfg.grid);
}

void CGridVectorMap::internal_clear()
{
	impl_->map.clear();
	insertedScans_ = 0;
}

bool CGridVectorMap::isEmpty() const { return impl_->map.empty(); }

std::string CGridVectorMap::asString() const
{
	double len = 0;
	size_t nStatic = 0, nDynamic = 0;
	for (const auto& v : impl_->map.vectors())
	{
		len += v.length();
		nStatic += v.state == gridvector::VectorState::Static;
		nDynamic += v.state == gridvector::VectorState::Dynamic;
	}
	std::ostringstream os;
	const size_t nUnclassified = impl_->map.size() - nStatic - nDynamic;
	os << "CGridVectorMap: " << impl_->map.size() << " grid vectors (" << nStatic << " static, " << nDynamic
	   << " dynamic";
	if (nUnclassified > 0) os << ", " << nUnclassified << " not classified: no E-step has run";
	os << "), total length " << len << " m, " << insertedScans_ << " scans inserted, resolution "
	   << impl_->map.config().grid.resolution << " m";
	return os.str();
}

void CGridVectorMap::TLikelihoodOptions::loadFromConfigFile(const mrpt::config::CConfigFileBase& source,
															const std::string& section)
{
	const std::string from = "CGridVectorMap config";
	// COccupancyGridMap2D's likelihood-field names, as a section copied from a grid's holds them
	for (const auto& [grids, ours] :
		 {std::pair{"LF_stdHit", "sigma"}, std::pair{"LF_maxCorrsDistance", "maxCorrDistance"},
		  std::pair{"LF_zRandom", "zRandom"}, std::pair{"LF_decimation", "decimation"}})
		if (source.keyExists(section, grids))
			throw std::runtime_error(from + ": [" + section + "] " + grids +
									 " is COccupancyGridMap2D's key; this map's is " + ours);
	gridvector::io::requireKnownKeys(source, section, {"sigma", "maxCorrDistance", "zRandom", "decimation"}, from);
	using gridvector::io::readIniValue;
	readIniValue(source, section, "sigma", sigma, from, "a number > 0", [](double v) { return v > 0; });
	readIniValue(source, section, "maxCorrDistance", maxCorrDistance, from, "a number > 0",
				 [](double v) { return v > 0; });
	readIniValue(source, section, "zRandom", zRandom, from, "a number in [0,1)",
				 [](double v) { return v >= 0 && v < 1; });
	readIniValue(source, section, "decimation", decimation, from, "an integer in [1,1000000]",
				 [](int v) { return v >= 1 && v <= 1000000; });
}

void CGridVectorMap::TLikelihoodOptions::dumpToTextStream(std::ostream& out) const
{
	out << "[<prefix>_likelihoodOpts]\nsigma = " << sigma << "\nmaxCorrDistance = " << maxCorrDistance
		<< "\nzRandom = " << zRandom << "\ndecimation = " << decimation << "\n";
}
