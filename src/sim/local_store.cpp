#include "sim/local_store.hpp"

namespace polydem {

void LocalStore::select(const Bodies& all, std::vector<std::uint32_t> ids, std::vector<std::uint8_t> is_ghost) {
  global_id = std::move(ids);
  ghost = std::move(is_ghost);
  const std::size_t n = global_id.size();
  shape.resize(n);
  scale.resize(n);
  mass.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    shape[k] = all.shape[global_id[k]];
    scale[k] = all.scale[global_id[k]];
    mass[k] = all.mass[global_id[k]];
  }
  refresh(all);
}

void LocalStore::refresh(const Bodies& all, bool turning) {
  const std::size_t n = global_id.size();
  position.resize(n);
  velocity.resize(n);
  angular_velocity.resize(n);
  velocity_end.resize(n);
  angular_velocity_end.resize(n);
  if (turning) {
    orientation.resize(n);
    for (std::size_t k = 0; k < n; ++k) orientation[k] = all.orientation[global_id[k]];
  }
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t g = global_id[k];
    position[k] = all.position[g];
    velocity[k] = all.velocity[g];
    angular_velocity[k] = all.angular_velocity[g];
    velocity_end[k] = all.velocity_end[g];
    angular_velocity_end[k] = all.angular_velocity_end[g];
  }
  force.assign(n, Vec3::Zero());
  torque.assign(n, Vec3::Zero());
}

}  // namespace polydem
