// Rotor::sphere: a sphere's orientation moves nothing, so it is not integrated. Its position,
// velocities and predicted velocities must be the isotropic path's bits, its L the same world
// angular momentum, and only spheres (one vertex at the centre, isotropic inertia) take it.
#include <catch2/catch.hpp>

#include <omp.h>

#include <cstdint>
#include <random>
#include <vector>

#include "integrate/integrate.hpp"
#include "polydem/parallel.hpp"
#include "same_motion.hpp"

using namespace polydem;
using namespace polydem::testing;

namespace {

// Shape 0 a sphere, shape 1 one vertex off the centre of mass (its orientation moves it).
std::vector<Shape> shapes() {
  Shape off = sphere_shape("off-centre", 0.01);
  off.vertices = {Vec3(1e-3, 0.0, 0.0)};
  return {sphere_shape("ball", 0.01), off};
}

// Bodies i % 3: 0 a sphere, 1 the off-centre point (isotropic), 2 the sphere's shape with
// unequal moments (asymmetric); random state.
Bodies mixed_bodies(std::size_t n) {
  Bodies b;
  b.resize(n);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto vec = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  for (std::size_t i = 0; i < n; ++i) {
    b.shape[i] = i % 3 == 1 ? 1 : 0;
    b.position[i] = vec();
    b.orientation[i] = Quat(1.0 + u(rng), u(rng), u(rng), u(rng)).normalized();
    b.velocity[i] = vec();
    b.mass[i] = 1.5 + u(rng);                                                  // kg
    b.inertia[i] = i % 3 == 2 ? Vec3(1e-3, 2e-3, 3e-3) : Vec3::Constant(2e-3);  // kg m^2
    set_angular_velocity(b, i, 10.0 * vec());
  }
  return b;
}

// Forces and torques from the step and the body only (N, N m).
void loads(Bodies& b, int step) {
  std::mt19937_64 rng(100 + step);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < b.size(); ++i) {
    b.force[i] += Vec3(u(rng), u(rng), u(rng));
    b.torque[i] = 1e-3 * Vec3(u(rng), u(rng), u(rng));
  }
}

// A rank's store as the passes see it: not Bodies, so they walk its groups by runs.
struct Store : Bodies {};

// Steps with loads: start_step and kick over B (Bodies walks the groups' ids, Store their runs).
template <class B>
void run(B& b, const RotorGroups& groups, int steps) {
  const double dt = 1e-4, h = 0.5 * dt;  // s
  const Vec3 gravity(0.0, 0.0, -9.807);  // m/s^2
  for (int s = 0; s < steps; ++s) {
    in_team(true, [&] { start_pass(b, h, dt, groups, gravity); });
    loads(b, s);
    in_team(true, [&] { kick_after(b, h, groups, [](std::size_t) {}); });
  }
}

}  // namespace

TEST_CASE("a sphere turns no quaternion: the isotropic path's x, v and w bits, the same world L, at 1 and 2 threads",
          "[integrate]") {
  const std::size_t n = 3 * kParallelMinItems;  // enough for a team
  Bodies start = mixed_bodies(n);
  const RotorGroups groups = group_rotors(start, shapes());
  REQUIRE(groups.spheres.size() == n / 3);
  REQUIRE(groups.isotropic.size() == n / 3);  // the off-centre point keeps its orientation
  REQUIRE(groups.asymmetric.size() == n / 3);
  for (std::size_t k = 0; k < groups.spheres.size(); ++k) CHECK(groups.spheres[k] == 3 * k);
  drop_sphere_orientations(start, groups);
  Bodies turned = start;  // the reference: every isotropic body on the isotropic path
  run(turned, group_rotors(turned), 200);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    Bodies b = start;
    run(b, groups, 200);
    check_same_motion(b, turned);
    double worst = 0.0;  // relative, world L against the turned reference's R L_body
    for (std::size_t i = 0; i < n; ++i) {
      if (i % 3 != 0) {  // not spheres: the same path, the same bits
        CHECK(b.orientation[i].coeffs() == turned.orientation[i].coeffs());
        CHECK(b.angular_momentum[i] == turned.angular_momentum[i]);
        continue;
      }
      CHECK(b.orientation[i].coeffs() == Quat::Identity().coeffs());
      CHECK(turned.orientation[i].angularDistance(Quat::Identity()) > 1e-3);  // the reference did turn
      const Vec3 world = turned.orientation[i] * turned.angular_momentum[i];  // kg m^2/s
      worst = std::max(worst, (b.angular_momentum[i] - world).norm() / world.norm());
      worst = std::max(worst, (b.angular_momentum[i] - b.inertia[i].x() * b.angular_velocity[i]).norm() / world.norm());
    }
    CHECK(worst < 1e-13);  // round-off of 200 steps' sums
  }
  omp_set_num_threads(1);
}

TEST_CASE("drop_sphere_orientations folds L into the world frame and keeps identity states bit for bit", "[integrate]") {
  Bodies b = mixed_bodies(6);
  const RotorGroups groups = group_rotors(b, shapes());
  b.angular_momentum[3] = Vec3(-0.0, 2e-3, -1e-3);  // a sphere already at the identity, with a signed zero
  b.orientation[3] = Quat::Identity();
  const Bodies before = b;
  drop_sphere_orientations(b, groups);
  const Vec3 world0 = before.orientation[0] * before.angular_momentum[0];
  CHECK(b.orientation[0].coeffs() == Quat::Identity().coeffs());
  CHECK((b.angular_momentum[0] - world0).norm() < 1e-15 * world0.norm());
  CHECK(std::signbit(b.angular_momentum[3].x()));  // untouched
  CHECK(b.angular_momentum[3] == before.angular_momentum[3]);
  CHECK(b.angular_velocity == before.angular_velocity);  // w is a world vector: unchanged
  for (std::size_t i : {1, 2, 4, 5}) {  // not spheres
    CHECK(b.orientation[i].coeffs() == before.orientation[i].coeffs());
    CHECK(b.angular_momentum[i] == before.angular_momentum[i]);
  }
  // The rotational energy 0.5 L.L / I (simulation.cpp) is the same before and after.
  const double e0 = 0.5 * before.angular_momentum[0].squaredNorm() / before.inertia[0].x();  // J
  CHECK(0.5 * b.angular_momentum[0].squaredNorm() / b.inertia[0].x() == Approx(e0).epsilon(1e-15));
}

namespace {

// Runs `alike` (spheres_alike) and the same groups reading the per-body arrays from `start`
// for 200 steps, at 1 and 2 threads: the same bits.
void check_alike_bits(const Bodies& start, const RotorGroups& alike) {
  REQUIRE(alike.spheres_alike);
  RotorGroups each = alike;  // the same bodies read from their arrays
  each.spheres_alike = false;
  Bodies reference = start;
  run(reference, each, 200);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    Bodies b = start;
    run(b, alike, 200);
    check_same_motion(b, reference);
    CHECK(same_bits(b.angular_momentum, reference.angular_momentum));
  }
  omp_set_num_threads(1);
}

}  // namespace

TEST_CASE("equal spheres take one mass and inertia: the per-body arrays' bits, in id order and a rank's share, "
          "at 1 and 2 threads",
          "[integrate]") {
  const std::size_t n = 4 * kParallelMinItems;  // enough for a team, in half of them too
  Bodies start = mixed_bodies(n);
  CHECK_FALSE(group_rotors(start, shapes()).spheres_in_order);  // mixed: spheres not 0..n-1
  for (std::size_t i = 0; i < n; ++i) {
    start.shape[i] = 0;
    start.orientation[i] = Quat::Identity();
    start.mass[i] = 1.5;                      // kg
    start.inertia[i] = Vec3::Constant(2e-3);  // kg m^2
    set_angular_velocity(start, i, start.angular_velocity[i]);
  }
  const RotorGroups alike = group_rotors(start, shapes());
  CHECK(alike.spheres_in_order);
  check_alike_bits(start, alike);
  std::vector<std::uint32_t> share;  // a rank's owned bodies: not 0..n-1
  for (std::uint32_t i = 1; i < n; i += 2) share.push_back(i);
  const RotorGroups owned = group_rotors(start, share, shapes());
  CHECK_FALSE(owned.spheres_in_order);
  check_alike_bits(start, owned);
  Bodies heavier = start;
  heavier.mass[n - 1] = 1.6;  // kg: one differs
  CHECK_FALSE(group_rotors(heavier, shapes()).spheres_alike);
  CHECK_FALSE(group_rotors(heavier, share, shapes()).spheres_alike);
}

TEST_CASE("a rank's groups walked by their runs between its ghosts: the ids' bits, at 1 and 2 threads", "[integrate]") {
  const std::size_t n = 8 * kParallelMinItems;  // enough for a team in each group's share
  Bodies start = mixed_bodies(n);
  for (std::size_t i = 0; i < n; ++i) {  // mixed_bodies' three kinds in blocks of 7 (runs within a group)
    const std::size_t kind = i / 7 % 3;
    start.shape[i] = kind == 1 ? 1 : 0;
    start.inertia[i] = kind == 2 ? Vec3(1e-3, 2e-3, 3e-3) : Vec3::Constant(2e-3);  // kg m^2
    set_angular_velocity(start, i, start.angular_velocity[i]);
  }
  std::vector<std::uint32_t> share;  // a rank's owned bodies: runs of 1 to 4, then 1 or 2 ghosts
  for (std::uint32_t i = 0, len = 1; i < n; i += len + 1 + len % 2, len = len % 4 + 1)
    for (std::uint32_t k = i; k < i + len && k < n; ++k) share.push_back(k);
  const RotorGroups ids = group_rotors(start, share, shapes());
  const RotorGroups runs = with_runs(ids);
  for (const auto& [group, of] : {std::pair{&ids.spheres, &runs.sphere_runs}, {&ids.isotropic, &runs.isotropic_runs},
                                  {&ids.asymmetric, &runs.asymmetric_runs}}) {
    REQUIRE(of->at.size() == of->first.size() + 1);
    CHECK(of->at.back() == group->size());
    std::vector<std::size_t> walked;  // the runs' indices again
    for (std::size_t r = 0; r < of->first.size(); ++r)
      for (std::size_t k = of->at[r]; k < of->at[r + 1]; ++k) walked.push_back(of->first[r] + (k - of->at[r]));
    CHECK(walked == *group);
    CHECK(of->first.size() < group->size());  // some runs hold more than one body
  }
  Bodies reference = start;
  run(reference, ids, 20);
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    Store b{start};
    run(b, runs, 20);
    check_same_motion(b, reference);
    CHECK(same_bits(b.angular_momentum, reference.angular_momentum));
  }
  omp_set_num_threads(1);
}
