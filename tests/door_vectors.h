// Test helpers of the door tests (hinge rule, the rules beyond it, the detector): vectors by their
// endpoints and state.
#pragma once

#include <gridvector/GridVector.h>

namespace gvtest
{
inline gridvector::GridVector vec(double x1, double y1, double x2, double y2, gridvector::VectorState s)
{
	gridvector::GridVector v(mrpt::math::TPoint2D(x1, y1), mrpt::math::TPoint2D(x2, y2), gridvector::GridOptions{});
	v.state = s;
	return v;
}
constexpr auto S = gridvector::VectorState::Static;
constexpr auto D = gridvector::VectorState::Dynamic;

}  // namespace gvtest
