// Registers gridvector's serializable classes with MRPT's RTTI when the library
// is loaded (linked, dlopen'ed or LD_PRELOAD'ed into a stock MRPT app).
#include <mrpt/core/initializer.h>
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/rtti/CObject.h>

MRPT_INITIALIZER(gridvector_registerAllClasses)
{
	mrpt::rtti::registerClass(CLASS_ID(mrpt::maps::CGridVectorMap));
}
