// Determinism where the threads really run: 4,500 bodies, above every threshold that keeps a
// loop serial (kParallelMinItems = 256 items, the cell list's and the rebuild trigger's 1,024
// bodies, two pair blocks of kPairBlock pairs, for body pairs and driver pairs), with a rotating drum, a servo lid and a moving ball, at 1, 2 and 3 threads and
// with the count changed between steps.
#include <catch2/catch.hpp>

#include <omp.h>

#include <random>

#include "contact/pair_loop.hpp"
#include "neighbor/cell_common.hpp"
#include "sim_fixtures.hpp"
#include "state_hash.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr int kBodies = 4500;
constexpr double kDrumRadius = 0.13;  // m

// Bodies on a lattice of `spacing` inside the drum, layer after layer from the floor, with
// random velocities (m/s) and spins (rad/s) so they collide and the lists rebuild; `reach` is a
// body's largest half-extent. Polyhedra start aligned, faces facing across small gaps.
std::vector<BodySpec> lattice(const std::vector<const char*>& shapes, double spacing, double reach, bool turned) {
  std::mt19937_64 rng(11);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53 - 0.5; };
  std::vector<BodySpec> specs;
  const int side = int(2 * kDrumRadius / spacing);
  for (int k = 0; specs.size() < kBodies; ++k) {
    const Vec3 x(spacing * (k % side - side / 2), spacing * ((k / side) % side - side / 2),
                 reach + spacing * (k / (side * side)));
    if (x.head<2>().norm() > kDrumRadius - reach) continue;
    const Quat q = Quat(Eigen::Vector4d(u(), u(), u(), u())).normalized();
    BodySpec b = body(shapes[specs.size() % shapes.size()], x, 2.0 * Vec3(u(), u(), u()),
                      turned ? q : Quat::Identity());
    b.angular_velocity = 100.0 * Vec3(u(), u(), u());
    specs.push_back(b);
  }
  return specs;
}

Scene drum_scene(double top) {
  Scene s = base_scene(law(1e5, 0.5, 0.4, 1e5), true, Vec3(0, 0, -9.807));
  DriverSettings drum;
  drum.name = "drum";
  CylinderSettings c;
  c.radius = kDrumRadius;
  drum.kind = c;
  drum.motion.rotates = true;
  drum.motion.omega = 3.0;  // rad/s about z
  DriverSettings lid;
  lid.name = "lid";
  lid.kind = WallSettings{Vec3(0, 0, top), -Vec3::UnitZ()};
  lid.motion.force = 50.0;  // N, servo pressing down
  DriverSettings ball;
  ball.name = "ball";
  BallSettings b;
  b.center = Vec3(0, 0, top + 0.03);
  b.radius = 0.03;
  ball.kind = b;
  ball.motion.velocity = Vec3(0, 0, -2);
  s.drivers.insert(s.drivers.end(), {drum, lid, ball});
  return s;
}

struct Outcome {
  std::uint64_t hash;
  ContactStats stats;
};

// threads 0: the count changes every 7 steps (3, 1, 2, 3, ...), as the thread governor may
// change it between any two steps of a run.
// `shares`: the body pairs' loop cut with these shares of the work (ContactEngine::fix_shares), or
// empty: its cut follows the threads' pace.
Outcome run(int threads, const Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs, int steps,
            std::vector<double> shares = {}) {
  omp_set_num_threads(threads > 0 ? threads : 2);
  Simulation sim(scene, lib, specs);
  if (!shares.empty()) sim.engine().fix_shares(std::move(shares));
  ContactStats most;  // the largest lists seen: the thresholds must be passed while stepping
  for (int s = 0; s < steps; ++s) {
    if (threads == 0 && s % 7 == 0) omp_set_num_threads(1 + (s / 7 + 2) % 3);
    sim.step();
    most.body_pairs = std::max(most.body_pairs, sim.engine().stats().body_pairs);
    most.driver_pairs = std::max(most.driver_pairs, sim.engine().stats().driver_pairs);
  }
  most.rebuilds = sim.engine().stats().rebuilds;
  omp_set_num_threads(1);
  return {state_hash(sim.bodies), most};
}

void check_same_bits_for_1_2_3_threads(const Scene& scene, const ShapeLibrary& lib,
                                       const std::vector<BodySpec>& specs, int steps) {
  REQUIRE(specs.size() > cells::kMinParallel);  // cell list, binning and rebuild trigger go parallel
  const Outcome one = run(1, scene, lib, specs, steps);
  CHECK(one.stats.body_pairs > 2 * kPairBlock);
  CHECK(one.stats.driver_pairs > 2 * kPairBlock);
  CHECK(one.stats.rebuilds >= 2);  // the rebuild runs in parallel too, not only the first
  CHECK(run(2, scene, lib, specs, steps).hash == one.hash);
  CHECK(run(2, scene, lib, specs, steps, {0.25, 0.75}).hash == one.hash);  // cuts far from the even one
  CHECK(run(2, scene, lib, specs, steps, {0.75, 0.25}).hash == one.hash);
  CHECK(run(3, scene, lib, specs, steps).hash == one.hash);
  CHECK(run(0, scene, lib, specs, steps).hash == one.hash);  // switching between steps
}

}  // namespace

TEST_CASE("4,500 spheres in a drum with a servo lid and a ball: same bits at 1, 2 and 3 threads",
          "[determinism][threads]") {
  const double r = 0.004, spacing = 2 * r + 0.0004;  // m, 0.4 mm gaps
  const auto specs = lattice({"sphere"}, spacing, r, true);
  const Scene scene = drum_scene(specs.back().position.z() + r + 0.0004);
  check_same_bits_for_1_2_3_threads(scene, library({sphere_shape(r)}), specs, 300);
}

TEST_CASE("4,500 cubes and hexagonal prisms in a drum with a servo lid and a ball: same bits at 1, 2 and 3 threads",
          "[determinism][threads]") {
  // Full extents (m): cube 7 x 7 x 7, prism 6.4 x 7.2 x 7 (a vertex on y); 0.1-0.9 mm gaps.
  const Shape cube = cube_shape(0.006, 0.0005), prism = prism_shape(6, 0.0031, 0.006, 0.0005, "prism");
  const double reach = 0.0036, spacing = 0.0073;
  const auto specs = lattice({"cube", "prism"}, spacing, reach, false);
  const Scene scene = drum_scene(specs.back().position.z() + reach + 0.0003);
  check_same_bits_for_1_2_3_threads(scene, library({cube, prism}), specs, 150);
}

TEST_CASE("A pour: 1,000 prisms falling apart above 400 touching cubes take the passes' own cut, same bits at 1, 2 and 3 threads",
          "[determinism][threads]") {
  // The cubes' pairs cut the walk (the prisms have none), so its body cut would leave every
  // falling prism's passes to the last thread: ContactEngine::pass_cut evens them instead,
  // folded so that each thread still moves the cubes it walks (TeamCut::folded).
  const Shape cube = cube_shape(0.006, 0.0005), prism = prism_shape(6, 0.0031, 0.006, 0.0005, "prism");
  std::vector<BodySpec> specs;
  for (int k = 0; k < 400; ++k)  // a 20 x 20 layer (7 mm cubes) on the floor, 0.2 mm gaps
    specs.push_back(body("cube", Vec3(0.0072 * (k % 20 - 10), 0.0072 * (k / 20 - 10), 0.0036)));
  for (int k = 0; k < 1000; ++k)  // 10 x 10 x 10, 3 cm apart, 5 cm up: no pair among them
    specs.push_back(body("prism", Vec3(0.03 * (k % 10 - 5), 0.03 * (k / 10 % 10 - 5), 0.05 + 0.03 * (k / 100)),
                         Vec3(0, 0, -1), Quat::Identity()));
  const Scene scene = base_scene(law(1e5, 0.5, 0.4, 1e5), true, Vec3(0, 0, -9.807));
  const ShapeLibrary lib = library({cube, prism});
  omp_set_num_threads(2);
  Simulation sim(scene, lib, specs);
  sim.step();
  omp_set_num_threads(1);
  const TeamCut passes = sim.engine().pass_cut(), walk = sim.engine().body_cut();
  REQUIRE(passes.threads == 2);
  CHECK(passes.at != walk.at);  // a cut of its own, folded on the walk's
  REQUIRE(passes.folded);
  CHECK(walk.at[1] < 400);
  CHECK(passes.at[1] == walk.at[1]);  // each thread moves the cubes it walks,
  CHECK(passes.at[2] > 400);          // thread 1 some of the prisms after them,
  CHECK(passes.at[3] == passes.at[2]);
  CHECK(passes.at[3] < 1400);         // thread 0 the rest
  CHECK(passes.at[4] == 1400);
  const std::uint64_t one = run(1, scene, lib, specs, 60).hash;
  CHECK(run(2, scene, lib, specs, 60).hash == one);
  CHECK(run(3, scene, lib, specs, 60).hash == one);
  CHECK(run(0, scene, lib, specs, 60).hash == one);
}
