// gv-bench-log: a SLAM benchmark log from a corrected CARMEN log, as
// ../shared/bench/mkbench.py makes it (same noise model, same random draws).
#pragma once

#include "sim/OdometryNoise.h"

#include <cstdint>
#include <string>

namespace gridvector::sim
{
struct BenchmarkOptions
{
	int64_t seed = 1;
	OdometryNoiseOptions noise;  //!< mkbench defaults: 0.05, 0.02 rad, 0.8 deg/m
	double dt = 0.2;  //!< synthetic seconds between scans
};

struct BenchmarkSummary
{
	size_t scans = 0;
	std::string logPath, refPath;
};

/** Reads the FLASER lines of `in` (their first pose is the reference), writes
 * OUT.log (PARAM lines, then ODOM + FLASER per scan with odometry re-synthesised
 * by NoisyOdometry, ranges copied verbatim, timestamps 1.1e9 + k*dt) and
 * OUT.ref.txt ("t x y theta" per scan), both atomically. Malformed FLASER lines
 * throw "file:line: what is wrong"; outputs that cannot be written throw
 * "OUT.log: cannot write (reason)" before `in` is read. */
BenchmarkSummary makeBenchmarkLog(const std::string& in, const std::string& outPrefix,
								  const BenchmarkOptions& opt = {});

}  // namespace gridvector::sim
