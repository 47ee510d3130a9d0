// Velocity Verlet kicks and drifts over all bodies; each body is independent, so the result is
// bitwise the same for any thread count.
#include "integrate/integrate.hpp"

#include <type_traits>

#include "polydem/parallel.hpp"

namespace polydem {

namespace {

using integrate_detail::drift_body;
using integrate_detail::predict_body;

// Relative tolerance on principal moments for the isotropic fast path.
constexpr double kIsotropicTolerance = 1e-12;

}  // namespace

bool is_isotropic(const Vec3& inertia) {
  const double largest = inertia.maxCoeff();
  return largest - inertia.minCoeff() <= kIsotropicTolerance * largest;
}

bool keeps_no_orientation(const Shape& shape, const Vec3& inertia) {
  return shape.is_sphere() && shape.vertices[0] == Vec3::Zero() && is_isotropic(inertia);
}

RotorGroups group_rotors(const Bodies& b) {
  RotorGroups groups;
  for (std::size_t i = 0; i < b.size(); ++i) integrate_detail::add_rotor(b, i, nullptr, groups);
  integrate_detail::mark_spheres(b, groups);
  return groups;
}

RotorGroups group_rotors(const Bodies& b, const std::vector<Shape>& shapes) {
  RotorGroups groups;
  for (std::size_t i = 0; i < b.size(); ++i) integrate_detail::add_rotor(b, i, &shapes, groups);
  integrate_detail::mark_spheres(b, groups);
  return groups;
}

std::vector<float> pass_weights(const RotorGroups& groups, std::size_t n) {
  // callgrind, 1 thread: the pour's 400 steps from boxfill_t0.1.bin (close_and_start_step by
  // group), the peers' sphere bed's 300 (~114 a sphere with its rebuild check).
  constexpr float kSphere = 100.0f, kIsotropic = 280.0f, kAsymmetric = 1090.0f;
  std::vector<float> weight(n, kSphere);
  for (std::size_t b : groups.isotropic) weight[b] = kIsotropic;
  for (std::size_t b : groups.asymmetric) weight[b] = kAsymmetric;
  return weight;
}

IdRuns runs_of(const std::vector<std::size_t>& ids) {
  IdRuns runs;
  for (std::size_t k = 0; k < ids.size(); ++k)
    if (k == 0 || ids[k] != ids[k - 1] + 1) runs.first.push_back(ids[k]), runs.at.push_back(k);
  runs.at.push_back(ids.size());
  return runs;
}

RotorGroups with_runs(RotorGroups groups) {
  groups.sphere_runs = runs_of(groups.spheres);
  groups.isotropic_runs = runs_of(groups.isotropic);
  groups.asymmetric_runs = runs_of(groups.asymmetric);
  groups.in_runs = true;
  return groups;
}


void kick(Bodies& b, double h) {
  parallel_for(b.size(), [&b, h](std::size_t i) {
    b.velocity[i] += b.force[i] * (h / b.mass[i]);
    // Torque is summed in the world frame; L lives in the principal frame: apply R^T.
    b.angular_momentum[i] += b.orientation[i].conjugate() * (b.torque[i] * h);
    // Keep the derived field in step with L, for output and the next force evaluation.
    b.angular_velocity[i] = b.orientation[i] * b.angular_momentum[i].cwiseQuotient(b.inertia[i]);
  });
}

void kick(Bodies& b, double h, const RotorGroups& groups) {
  kick_after(b, h, groups, [](std::size_t) {});
}

void drift(Bodies& b, double dt, const RotorGroups& groups) {
  over_rotor_groups(b, groups, [&](const auto& a, std::size_t i, auto rotor) __attribute__((always_inline)) {
    drift_body<decltype(rotor)::value>(a, i, dt);
  });
}

void drift(Bodies& b, double dt) {
  const BodyArrays a = arrays_of(b);
  parallel_for(b.size(), [&a, dt](std::size_t i) {
    if (is_isotropic(a.inertia[i])) {
      drift_body<Rotor::isotropic>(a, i, dt);
    } else {
      drift_body<Rotor::asymmetric>(a, i, dt);
    }
  });
}

void predict_end_velocities(Bodies& b, double h, const RotorGroups& groups) {
  over_rotor_groups(b, groups, [&](const auto& a, std::size_t i, auto rotor) __attribute__((always_inline)) {
    predict_body<decltype(rotor)::value>(a, i, h);
  });
}

void start_step(Bodies& b, double h, double dt, const RotorGroups& groups, const Vec3& gravity, TeamCut cut) {
  start_pass(b, h, dt, groups, gravity, cut);
}

void update_angular_velocity(Bodies& b) {
  parallel_for(b.size(), [&b](std::size_t i) {
    b.angular_velocity[i] = b.orientation[i] * b.angular_momentum[i].cwiseQuotient(b.inertia[i]);
  });
}

void set_angular_velocity(Bodies& b, std::size_t i, const Vec3& w_world) {
  b.angular_momentum[i] = b.inertia[i].cwiseProduct(b.orientation[i].conjugate() * w_world);
  b.angular_velocity[i] = w_world;
}

}  // namespace polydem
