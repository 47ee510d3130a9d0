#include "driver/frame.hpp"

namespace polydem {

namespace {

constexpr double kPadding = 0.05;  // of the box's largest side, around it

}  // namespace

Box3 view_box(Box3 box, const Drivers& drivers) {
  for (std::size_t j = 0; j < drivers.size(); ++j)
    if (drivers[j].active) drivers.bounds(std::uint32_t(j), box);
  if (box.empty()) box.add(Vec3::Zero(), 0.5);  // nothing to frame: a metre about the origin
  return box.padded(kPadding * (box.hi - box.lo).maxCoeff());
}

ViewFrame view_frame(const Drivers& drivers, const Box3& box) {
  ViewFrame frame{box, {}};
  for (std::size_t j = 0; j < drivers.size(); ++j) {
    const DriverState& d = drivers[j];
    if (d.active && drivers.is_wall(std::uint32_t(j))) frame.walls.push_back({d.point, d.normal});
  }
  return frame;
}

}  // namespace polydem
