#include "driver/frame.hpp"

#include <cmath>

#include "driver/mesh.hpp"

namespace polydem {

namespace {

constexpr double kPadding = 0.05;  // of the box's largest side, around it

Box3 driver_box(const Driver& d) {
  Box3 box;
  switch (d.spec.kind) {
    case DriverSpec::Kind::wall: box.add(d.point); break;
    case DriverSpec::Kind::cylinder:
      if (d.spec.length)
        for (double end : {-0.5, 0.5}) box.add(d.center + end * *d.spec.length * d.axis, d.spec.radius);
      break;
    case DriverSpec::Kind::ball: box.add(d.center, d.spec.radius); break;
    case DriverSpec::Kind::stl:
      for (const Vec3& v : d.mesh->vertices) box.add(d.center + d.orientation * v);
      break;
  }
  return box;
}

}  // namespace

Box3 view_box(const Bodies& bodies, const std::vector<Shape>& shapes, const Drivers& drivers) {
  Box3 box;
  for (std::size_t b = 0; b < bodies.size(); ++b)
    box.add(bodies.position[b], shapes[bodies.shape[b]].bounding_radius * bodies.scale[b]);
  for (std::size_t j = 0; j < drivers.size(); ++j)
    if (drivers[j].active) box.add(driver_box(drivers[j]));
  if (box.empty()) box.add(Vec3::Zero(), 0.5);  // nothing to frame: a metre about the origin
  return box.padded(kPadding * (box.hi - box.lo).maxCoeff());
}

ViewFrame view_frame(const Drivers& drivers, const Box3& box) {
  ViewFrame frame{box, {}};
  for (std::size_t j = 0; j < drivers.size(); ++j) {
    const Driver& d = drivers[j];
    if (d.active && d.spec.kind == DriverSpec::Kind::wall) frame.walls.push_back({d.point, d.normal});
  }
  return frame;
}

}  // namespace polydem
