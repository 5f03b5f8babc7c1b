// The simulator's built-in worlds, modelled on the paper's three experiments (Sec. 5).
#pragma once

#include "sim/World.h"

#include <string>
#include <vector>

namespace gridvector::sim
{
/** "corridor-loop" (Sec. 5.1: 38 x 20 m floor, a corridor ring with offices and
 * doors), "office" (Sec. 5.2: cluttered 20 x 8 m office with desks and chairs),
 * "long-corridor" (Sec. 5.3: 20 x 6 m corridor with doors on both sides). */
std::vector<std::string> builtinWorldNames();

/** Throws std::invalid_argument("unknown world 'x' (known: ...)"). */
World makeWorld(const std::string& name);

}  // namespace gridvector::sim
