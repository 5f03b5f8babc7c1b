// CGridVectorMap's state behind its public header: the global map (Sec. 3.2), the extractor
// (Sec. 3.1) and the matching calls' static stretches.
#pragma once

#include "extraction/VectorExtractor.h"
#include "map/GlobalMap.h"
#include "mrpt/StaticStretchCache.h"

#include <mrpt/maps/CGridVectorMap.h>

struct mrpt::maps::CGridVectorMap::Impl
{
	explicit Impl(const gridvector::GridVectorConfig& cfg) : map(cfg), extractor(cfg.extraction, cfg.grid) {}

	gridvector::GlobalMap map;
	gridvector::VectorExtractor extractor;
	/** Static stretches while the map does not change (map.revision()); copies start empty. */
	gridvector::StaticStretchCache stretches;
};
