// Thread determinism: each body is integrated independently, so any thread count gives the
// same bits (Box2D test_determinism.c does the same for its solver).
#include <catch2/catch.hpp>

#include <omp.h>

#include <cstring>
#include <random>

#include "integrate/integrate.hpp"

using namespace polydem;

namespace {

constexpr std::size_t kBodies = 1000;
constexpr int kSteps = 100;

Bodies random_bodies(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::uniform_real_distribution<double> pos(0.1, 2.0);
  auto vec = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  Bodies b;
  b.resize(kBodies);
  for (std::size_t i = 0; i < kBodies; ++i) {
    b.position[i] = 10.0 * vec();
    b.velocity[i] = vec();
    b.orientation[i] = Quat(u(rng), u(rng), u(rng), u(rng)).normalized();
    b.mass[i] = pos(rng);
    // One body in three isotropic, so both rotation paths run.
    b.inertia[i] = i % 3 == 0 ? Vec3::Constant(pos(rng)) : Vec3(pos(rng), pos(rng), pos(rng));
    set_angular_velocity(b, i, 5.0 * vec());
  }
  return b;
}

// Forces and torques depend on the step and the body only, never on the thread schedule.
void random_loads(Bodies& b, int step) {
  std::mt19937_64 rng(1000 + step);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.force[i] = Vec3(u(rng), u(rng), u(rng));
    b.torque[i] = Vec3(u(rng), u(rng), u(rng));
  }
}

Bodies run(int threads, bool use_groups) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
  std::mt19937_64 rng(42);
  Bodies b = random_bodies(rng);
  const RotorGroups groups = group_rotors(b);
  const double dt = 1e-3;
  random_loads(b, 0);
  for (int n = 1; n <= kSteps; ++n) {
    kick(b, 0.5 * dt);
    use_groups ? drift(b, dt, groups) : drift(b, dt);
    random_loads(b, n);
    kick(b, 0.5 * dt);
  }
  omp_set_num_threads(saved);
  return b;
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

bool same_state(const Bodies& a, const Bodies& b) {
  return same_bits(a.position, b.position) && same_bits(a.orientation, b.orientation) &&
         same_bits(a.velocity, b.velocity) && same_bits(a.angular_velocity, b.angular_velocity) &&
         same_bits(a.angular_momentum, b.angular_momentum);
}

}  // namespace

TEST_CASE("1 and 2 threads give bitwise identical states", "[integrate]") {
  const Bodies one = run(1, true);
  const Bodies two = run(2, true);
  CHECK(same_state(one, two));
  // Sanity: the run moved the bodies (a no-op integrator would also be deterministic).
  std::mt19937_64 rng(42);
  const Bodies start = random_bodies(rng);
  CHECK_FALSE(same_bits(one.orientation, start.orientation));
  CHECK_FALSE(same_bits(one.velocity, start.velocity));
}

TEST_CASE("drift with and without precomputed groups gives the same bits", "[integrate]") {
  CHECK(same_state(run(1, true), run(1, false)));
}
