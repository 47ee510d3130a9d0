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
  for (auto* v : {&position, &velocity, &angular_velocity, &velocity_end, &angular_velocity_end}) v->resize(n);
  orientation.resize(n);
  refresh(all);
  clear_forces();
}

void LocalStore::refresh(const Bodies& all, bool turning) {
  // The arrays' addresses held in locals: read through the vectors, each copy reloaded them
  // (Eigen's stores may alias anything).
  const Vec3 *x = all.position.data(), *v = all.velocity.data(), *w = all.angular_velocity.data();
  const Vec3 *ve = all.velocity_end.data(), *we = all.angular_velocity_end.data();
  const Quat* q = all.orientation.data();
  const std::uint32_t* id = global_id.data();
  Vec3 *to_x = position.data(), *to_v = velocity.data(), *to_w = angular_velocity.data();
  Vec3 *to_ve = velocity_end.data(), *to_we = angular_velocity_end.data();
  Quat* to_q = orientation.data();
  const std::size_t n = global_id.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::uint32_t g = id[k];
    to_x[k] = x[g];
    to_v[k] = v[g];
    to_w[k] = w[g];
    to_ve[k] = ve[g];
    to_we[k] = we[g];
    if (turning) to_q[k] = q[g];
  }
}

void LocalStore::clear_forces() {
  force.assign(global_id.size(), Vec3::Zero());
  torque.assign(global_id.size(), Vec3::Zero());
}

}  // namespace polydem
