// CGridVectorMap: 3D visualisation for MRPT viewers (static blue, dynamic red).
#include "mrpt/CGridVectorMapImpl.h"
#include <mrpt/maps/CGridVectorMap.h>
#include <mrpt/opengl/CSetOfLines.h>
#include <mrpt/opengl/CSetOfObjects.h>

#include <algorithm>
#include <array>

using namespace mrpt::maps;
using gridvector::VectorState;

namespace
{
constexpr int kBins = 5;  // unknown-state vectors: colour graded by p_static

mrpt::img::TColor binColour(int bin)
{
	const double t = double(bin) / (kBins - 1);  // 0 = dynamic-looking, 1 = static-looking
	return mrpt::img::TColor(uint8_t(255 * (1 - t)), 0, uint8_t(255 * t));
}
}  // namespace

void CGridVectorMap::getVisualizationInto(mrpt::opengl::CSetOfObjects& o) const
{
	if (!genericMapParams.enableSaveAs3DObject) return;
	auto staticLines = mrpt::opengl::CSetOfLines::Create();
	auto dynamicLines = mrpt::opengl::CSetOfLines::Create();
	staticLines->setColor_u8(mrpt::img::TColor(0, 0, 255));
	dynamicLines->setColor_u8(mrpt::img::TColor(255, 0, 0));
	std::array<mrpt::opengl::CSetOfLines::Ptr, kBins> bins;
	for (int b = 0; b < kBins; ++b)
	{
		bins[size_t(b)] = mrpt::opengl::CSetOfLines::Create();
		bins[size_t(b)]->setColor_u8(binColour(b));
	}
	for (const auto& v : impl_->map.vectors())
	{
		mrpt::opengl::CSetOfLines* target = nullptr;
		if (v.state == VectorState::Static)
			target = staticLines.get();
		else if (v.state == VectorState::Dynamic)
			target = dynamicLines.get();
		else
			target = bins[size_t(std::clamp(int(v.pStatic() * kBins), 0, kBins - 1))].get();
		target->appendLine(v.start().x, v.start().y, 0, v.end().x, v.end().y, 0);
	}
	o.insert(staticLines);
	o.insert(dynamicLines);
	for (auto& b : bins) o.insert(b);
}
