// start_step does in one pass, and in one parallel team, what kick, drift,
// predict_end_velocities and the gravity reset did as four loops: bit for bit, at 1 and 2 threads.
#include <catch2/catch.hpp>

#include <omp.h>

#include <cstring>
#include <random>

#include "integrate/integrate.hpp"
#include "polydem/parallel.hpp"
#include "same_motion.hpp"

using namespace polydem;
using namespace polydem::testing;

namespace {

// n bodies, every third a cuboid (asymmetric path), the rest spheres, with random state.
Bodies random_bodies(std::size_t n) {
  Bodies b;
  b.resize(n);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto vec = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  for (std::size_t i = 0; i < n; ++i) {
    b.position[i] = vec();
    b.orientation[i] = Quat(1.0 + u(rng), u(rng), u(rng), u(rng)).normalized();
    b.velocity[i] = vec();
    b.angular_momentum[i] = 1e-3 * vec();
    b.force[i] = vec();
    b.torque[i] = 1e-3 * vec();
    b.mass[i] = 1.5 + u(rng);                                                  // kg
    b.inertia[i] = i % 3 == 0 ? Vec3(1e-3, 2e-3, 3e-3) : Vec3::Constant(2e-3);  // kg m^2
  }
  update_angular_velocity(b);
  return b;
}

// Every array a step's opening writes, b against ref, bit for bit.
void check_same_state(const Bodies& b, const Bodies& ref) {
  check_same_motion(b, ref);
  CHECK(same_bits(b.angular_momentum, ref.angular_momentum));
  CHECK(same_bits(b.force, ref.force));
  CHECK(std::memcmp(b.orientation.data(), ref.orientation.data(), b.orientation.size() * sizeof(Quat)) == 0);
}

}  // namespace

TEST_CASE("start_step equals kick, drift, predict and the gravity reset, bit for bit, at 1 and 2 threads") {
  const double h = 5e-6, dt = 1e-5;      // s
  const Vec3 gravity(0.0, 0.0, -9.807);  // m/s^2
  const std::size_t n = 3 * kParallelMinItems;  // enough to run in a team
  Bodies separate = random_bodies(n);
  const RotorGroups groups = group_rotors(separate);
  REQUIRE(!groups.asymmetric.empty());
  Bodies fused = separate;
  kick(separate, h, groups);
  drift(separate, dt, groups);
  predict_end_velocities(separate, h, groups);
  for (std::size_t i = 0; i < n; ++i) {
    separate.force[i] = separate.mass[i] * gravity;
    separate.torque[i].setZero();
  }
  for (int threads : {1, 2}) {
    Bodies b = fused;
    omp_set_num_threads(threads);
    in_team(true, [&] { start_step(b, h, dt, groups, gravity); });
    check_same_state(b, separate);
  }
  omp_set_num_threads(1);
}

TEST_CASE("close_and_start_step equals kick_after and start_step, bit for bit, on every rotor path") {
  const double h = 5e-6, dt = 1e-5;      // s
  const Vec3 gravity(0.0, 0.0, -9.807);  // m/s^2
  const std::size_t n = 3 * kParallelMinItems;
  Bodies separate = random_bodies(n);
  RotorGroups groups = group_rotors(separate);  // the cuboids asymmetric, the rest isotropic
  std::vector<std::size_t> isotropic;
  for (std::size_t i : groups.isotropic) {  // every other isotropic body a sphere (its q the identity)
    if (i % 2 == 0) {
      separate.orientation[i] = Quat::Identity();
      groups.spheres.push_back(i);
    } else {
      isotropic.push_back(i);
    }
  }
  groups.isotropic = isotropic;
  REQUIRE(!groups.spheres.empty());
  REQUIRE(!groups.asymmetric.empty());
  const Vec3 contact_force(0.3, -0.2, 0.1), contact_torque(2e-4, 1e-4, -3e-4);  // N, N m
  auto add_contact = [&](Bodies& b) {
    return [&b, contact_force, contact_torque](std::size_t i) {
      b.force[i] += contact_force;
      b.torque[i] += contact_torque;
    };
  };
  Bodies fused = separate;
  kick_after(separate, h, groups, add_contact(separate));
  start_step(separate, h, dt, groups, gravity);
  for (int threads : {1, 2}) {
    Bodies b = fused;
    omp_set_num_threads(threads);
    in_team(true, [&] { close_and_start_step(b, h, dt, groups, gravity, add_contact(b)); });
    check_same_state(b, separate);
  }
  omp_set_num_threads(1);
}
