#pragma once
// The frame the drivers are drawn in (output/frame.hpp): the bodies and the finite drivers.
#include <vector>

#include "driver/drivers.hpp"
#include "polydem/bodies.hpp"
#include "polydem/shape.hpp"
#include "output/frame.hpp"

namespace polydem {

// m, the box holding every body (its bounding sphere), every finite driver and every wall's
// point, padded by 5% of its largest side.
Box3 view_box(const Bodies& bodies, const std::vector<Shape>& shapes, const Drivers& drivers);

// The box and the active walls' inner sides, which cut the other walls and infinite cylinders.
ViewFrame view_frame(const Drivers& drivers, const Box3& box);

}  // namespace polydem
