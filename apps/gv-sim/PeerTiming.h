// A speed reference for gv-sim: MRPT's own 2D laser simulator on a grid of the
// same world, over the same true poses.
#pragma once

#include "sim/Simulator.h"

/** Seconds MRPT's COccupancyGridMap2D::laserScanSimulator needs for every scan of
 * r (static walls rasterised at 5 cm, same beam count and max range). */
double timeMrptLaserSimulator(const gridvector::sim::SimResult& r);
