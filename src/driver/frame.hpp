#pragma once
// The frame the drivers are drawn in (output/frame.hpp): the bodies and the finite drivers.
#include <vector>

#include "driver/drivers.hpp"
#include "polydem/bodies.hpp"
#include "polydem/shape.hpp"
#include "output/frame.hpp"

namespace polydem {

// m, the box of body b's bounding sphere added to `box` (B: Bodies, or a rank's LocalStore).
template <class B>
void add_body(Box3& box, const B& bodies, std::size_t b, const std::vector<Shape>& shapes) {
  box.add(bodies.position[b], shapes[bodies.shape[b]].bounding_radius * bodies.scale[b]);
}

// m, the box holding every body (`bodies`: their bounding spheres' box, add_body), every finite
// driver and every wall's point, padded by 5% of its largest side.
Box3 view_box(Box3 bodies, const Drivers& drivers);

// The box and the active walls' inner sides, which cut the other walls and infinite cylinders.
ViewFrame view_frame(const Drivers& drivers, const Box3& box);

}  // namespace polydem
