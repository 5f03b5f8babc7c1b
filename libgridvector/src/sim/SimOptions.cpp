#include "sim/BuiltinWorlds.h"
#include "sim/SimOptions.h"

#include <algorithm>
#include <cmath>

namespace gridvector::sim
{
namespace
{
void require(bool ok, const std::string& key, const std::string& what)
{
	if (!ok) throw SimOptionError(key, what);
}

std::string worldNames()
{
	std::string names;
	for (const auto& n : builtinWorldNames()) names += (names.empty() ? "" : ", ") + n;
	return names;
}
}  // namespace

void SimOptions::validate() const
{
	const auto worlds = builtinWorldNames();
	require(std::find(worlds.begin(), worlds.end(), world) != worlds.end(), "world", "must be one of " + worldNames());
	require(seed >= 0, "seed", "must be >= 0");
	require(laps >= 0 && laps <= 1000, "laps", "must be in 0..1000");
	require(scans >= 0 && scans <= 10000000, "scans", "must be in 0..10000000");
	require(people >= -1 && people <= 200, "people", "must be in -1..200");
	require(doorSwingPeriod == 0 || (doorSwingPeriod >= 5 && doorSwingPeriod <= 3600), "door_swing_period",
			"must be 0 or in [5, 3600] s");
	require(pauseS >= 0 && pauseS <= 3600, "pause_s", "must be in [0, 3600] s");
	require(speed > 0 && speed <= 3, "speed", "must be in (0, 3] m/s");
	require(turnRateDeg > 0 && turnRateDeg <= 360, "turn_rate_deg", "must be in (0, 360]");
	require(dt > 0 && dt <= 5, "dt", "must be in (0, 5] s");
	require(beams >= 2 && beams <= 4000, "beams", "must be in 2..4000");
	require(fovDeg > 0 && fovDeg <= 360, "fov_deg", "must be in (0, 360]");
	require(maxRange > 0.5 && maxRange <= 200, "max_range", "must be in (0.5, 200] m");
	require(rangeSigma >= 0 && rangeSigma <= 1, "range_sigma", "must be in [0, 1] m");
	require(sigmaT >= 0 && sigmaT <= 1, "sigma_t", "must be in [0, 1]");
	require(sigmaR >= 0 && sigmaR <= 1, "sigma_r", "must be in [0, 1] rad");
	require(std::abs(driftDegPerM) <= 90, "drift_deg_per_m", "must be in [-90, 90]");
	require(std::isfinite(startTime) && startTime >= 0, "start_time", "must be >= 0");
}

}  // namespace gridvector::sim
