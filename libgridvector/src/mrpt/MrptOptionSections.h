// MRPT's own option sections of a map in a CMultiMetricMap .ini, for CGridVectorMap's keys.
#pragma once

#include <gridvector/GridVectorConfig.h>

#include <mrpt/config/CConfigFileBase.h>

#include <string>

namespace gridvector
{
/** Reads the map's keys from the section names MRPT users write for every map (as for
 * COccupancyGridMap2D), next to the grouped [<prefix>_extraction], [<prefix>_grid], ...:
 * - [<prefix>_creationOpts]: the grid group (Sec. 3.1, Eq. 2: the layout fixed when the map is
 *   made), besides MRPT's own enableSaveAs3DObject / enableObservationLikelihood /
 *   enableObservationInsertion (TMapGenericParams, read by MRPT);
 * - [<prefix>_insertOpts]: what inserting a scan uses, the extraction (Sec. 3.1) and map
 *   (Sec. 3.2) groups.
 * Keys are the groups' own (`resolution`, `split_threshold`, ...). Throws std::runtime_error
 * "<from>: ..." for a key no such group has, a key also set in its grouped section, or a value
 * its range refuses. */
void readMrptOptionSections(const mrpt::config::CConfigFileBase& source, const std::string& prefix,
							GridVectorConfig& config, const std::string& from);
}  // namespace gridvector
