// Registering gridvector's classes with MRPT (the map type `gridVectorMap`, its serialization).
#pragma once

namespace gridvector
{
/** Registers mrpt::maps::CGridVectorMap with MRPT's class registry and map registry. Loading the
 * library does this already (linked, dlopen'ed or LD_PRELOAD'ed); calling it is idempotent and
 * makes the dependency explicit, so no linker can drop the library from a program that creates
 * the map only by name (an .ini, a rawlog, a serialized map). */
void registerClasses();

}  // namespace gridvector
