// Registers gridvector's serializable classes with MRPT's RTTI when the library
// is loaded (linked, dlopen'ed or LD_PRELOAD'ed into a stock MRPT app), and on request.
#include <gridvector/Registration.h>
#include <mrpt/core/initializer.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/rtti/CObject.h>

// CGridVectorMap.cpp's MAP_DEFINITION_REGISTER adds `gridVectorMap` to MRPT's map registry
// at load time as well.
MRPT_INITIALIZER(gridvector_registerAllClasses) { gridvector::registerClasses(); }

void gridvector::registerClasses() { mrpt::rtti::registerClass(CLASS_ID(mrpt::maps::CGridVectorMap)); }
