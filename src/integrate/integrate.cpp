// Velocity Verlet kicks and drifts over all bodies; each body is independent, so the result is
// bitwise the same for any thread count.
#include "integrate/integrate.hpp"

#include "integrate/free_rotor.hpp"

namespace polydem {

namespace {

// Below this many bodies a parallel region costs more (a few us) than the loop itself.
constexpr std::size_t kParallelMinBodies = 256;

// fn(k) for k in [0, n), in parallel when n is large. Small n skips OpenMP entirely: even an
// if(false) region makes a futex call (a one-body 10^6-step run went from 8 s to 0.8 s).
template <class Fn>
void for_each_index(std::size_t n, const Fn& fn) {
  if (n < kParallelMinBodies) {
    for (std::size_t k = 0; k < n; ++k) fn(k);
    return;
  }
#pragma omp parallel for schedule(static)
  for (std::size_t k = 0; k < n; ++k) fn(k);
}

// Relative tolerance on principal moments for the isotropic fast path.
constexpr double kIsotropicTolerance = 1e-12;

// Translation, then the exact or split free-rotor flow, then w from the new (q, L_body).
template <bool kIsotropicPath>
void drift_body(Bodies& b, std::size_t i, double dt) {
  b.position[i] += b.velocity[i] * dt;
  if constexpr (kIsotropicPath) {
    free_rotor::rotate_isotropic(b.orientation[i], b.angular_momentum[i], b.inertia[i], dt);
  } else {
    free_rotor::rotate_asymmetric(b.orientation[i], b.angular_momentum[i], b.inertia[i], dt);
  }
  free_rotor::renormalize(b.orientation[i]);
  b.angular_velocity[i] = b.orientation[i] * b.angular_momentum[i].cwiseQuotient(b.inertia[i]);
}

}  // namespace

bool is_isotropic(const Vec3& inertia) {
  const double largest = inertia.maxCoeff();
  return largest - inertia.minCoeff() <= kIsotropicTolerance * largest;
}

RotorGroups group_rotors(const Bodies& b) {
  RotorGroups groups;
  for (std::size_t i = 0; i < b.size(); ++i) {
    (is_isotropic(b.inertia[i]) ? groups.isotropic : groups.asymmetric).push_back(i);
  }
  return groups;
}

void kick(Bodies& b, double h) {
  for_each_index(b.size(), [&b, h](std::size_t i) {
    b.velocity[i] += b.force[i] * (h / b.mass[i]);
    // Torque is summed in the world frame; L lives in the principal frame: apply R^T.
    b.angular_momentum[i] += b.orientation[i].conjugate() * (b.torque[i] * h);
    // Keep the derived field in step with L, for output and the next force evaluation.
    b.angular_velocity[i] = b.orientation[i] * b.angular_momentum[i].cwiseQuotient(b.inertia[i]);
  });
}

void drift(Bodies& b, double dt, const RotorGroups& groups) {
  for_each_index(groups.isotropic.size(),
                 [&](std::size_t k) { drift_body<true>(b, groups.isotropic[k], dt); });
  for_each_index(groups.asymmetric.size(),
                 [&](std::size_t k) { drift_body<false>(b, groups.asymmetric[k], dt); });
}

void drift(Bodies& b, double dt) {
  for_each_index(b.size(), [&b, dt](std::size_t i) {
    if (is_isotropic(b.inertia[i])) {
      drift_body<true>(b, i, dt);
    } else {
      drift_body<false>(b, i, dt);
    }
  });
}

void update_angular_velocity(Bodies& b) {
  for_each_index(b.size(), [&b](std::size_t i) {
    b.angular_velocity[i] = b.orientation[i] * b.angular_momentum[i].cwiseQuotient(b.inertia[i]);
  });
}

void set_angular_velocity(Bodies& b, std::size_t i, const Vec3& w_world) {
  b.angular_momentum[i] = b.inertia[i].cwiseProduct(b.orientation[i].conjugate() * w_world);
  b.angular_velocity[i] = w_world;
}

}  // namespace polydem
