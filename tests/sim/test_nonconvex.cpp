// Non-convex bodies in contact: exaDEM's alpha3 cross and Rockable's Rice polyline. The face
// patch rule holds per contact region (tests/contact regions: one spring kn per region), all
// feature pairs within reach are candidates, and elastic collisions keep their energy.
#include <catch2/catch.hpp>

#include <cmath>

#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kG = 9.807;                       // m/s^2
constexpr double kArm = 0.0048, kRound = 0.0024;   // m: alpha3 at 1/100 scale (exaDEM: 0.48, 0.24)
constexpr double kKn = 1e5;                        // N/m

Shape faceless(const char* name, std::vector<Vec3> vertices, std::vector<std::array<int, 2>> edges, double r) {
  Shape s;
  s.name = name;
  s.radius = r;
  s.vertices = std::move(vertices);
  s.edges = std::move(edges);
  compute_mass_properties(s);
  return s;
}

Shape cross_shape(double a = kArm) {
  return faceless("alpha3", {{a, 0, 0}, {-a, 0, 0}, {0, a, 0}, {0, -a, 0}, {0, 0, a}, {0, 0, -a}},
                  {{0, 1}, {2, 3}, {4, 5}}, kRound);
}

// Rockable's Rice, straight: three collinear vertices, two edges (a capsule with a middle vertex).
Shape straight_rice(double half_length, double r) {
  return faceless("rice", {{-half_length, 0, 0}, {0, 0, 0}, {half_length, 0, 0}}, {{0, 1}, {1, 2}}, r);
}

// Turns the principal frame so that the diagonal (1, 1, 1) points up: the -x, -y, -z tips down.
Quat tripod() { return Quat::FromTwoVectors(Vec3(1, 1, 1).normalized(), Vec3::UnitZ()); }

double mass_of(const Simulation& sim) {
  double m = 0.0;
  for (double b : sim.bodies.mass) m += b;
  return m;
}

// Active driver contacts: their normal forces (N) and the vertex of the body each is at.
std::vector<std::pair<int, double>> floor_contacts(const Simulation& sim) {
  std::vector<std::pair<int, double>> out;
  const PairList& list = sim.engine().driver_pairs();
  for (std::uint32_t s = 0; s < list.slot_count(); ++s)
    if (list.active[s]) out.emplace_back(list.features[s].a, list.record(s).fn);
  return out;
}

// Kinetic plus rotational energy (J).
double motion_energy(const Simulation& sim) {
  const EnergyRow e = sim.energy();
  return e.kinetic + e.rotational;
}

}  // namespace

TEST_CASE("a cross rests on three arm tips: three regions, the floor carries its weight", "[nonconvex]") {
  Scene scene = base_scene(law(kKn, 0.1), true, Vec3(0, 0, -kG));
  const Shape cross = cross_shape();
  REQUIRE_FALSE(cross.convex);
  const double tip_depth = kArm / std::sqrt(3.0);  // m, below the centre, of each lower tip
  scene.simulation.dt = 2e-6;
  Simulation sim(scene, library({cross}), {body("alpha3", {0, 0, tip_depth + kRound}, Vec3::Zero(), tripod())});
  run_for(sim, 0.1);  // ~60 periods of the normal mode at en = 0.1: rung down
  const double weight = mass_of(sim) * kG;
  const auto contacts = floor_contacts(sim);
  REQUIRE(contacts.size() == 3);
  double total = 0.0;
  for (const auto& [vertex, fn] : contacts) {
    INFO("vertex " << vertex << " carries " << fn << " N of " << weight);
    CHECK((vertex == 1 || vertex == 3 || vertex == 5));  // the -x, -y, -z tips: one per arm
    CHECK(fn == Approx(weight / 3).epsilon(1e-6));
    total += fn;
  }
  CHECK(std::abs(total - weight) < 1e-8 * weight);
  CHECK(std::abs(-sim.drivers[0].force.z() - weight) < 1e-8 * weight);
  // Three separate regions act as three springs: each tip sinks by (m g / 3) / kn.
  const double overlap = tip_depth + kRound - sim.bodies.position[0].z();
  CHECK(overlap == Approx(weight / 3 / kKn).epsilon(1e-6));
}

TEST_CASE("a straight polyline lying flat rests on one spring: overlap m g / kn", "[nonconvex]") {
  // Its three vertices touch in one region (joined by its edges, all in contact): the patch rule
  // shares kn among them, w = 1/3 each at equal depth x, so the floor pushes kn x = m g. Three
  // separate springs would give x = m g / (3 kn).
  Scene scene = base_scene(law(kKn, 0.1), true, Vec3(0, 0, -kG));
  const Shape rice = straight_rice(0.006, 0.001);
  REQUIRE_FALSE(rice.convex);
  scene.simulation.dt = 1e-6;
  Simulation sim(scene, library({rice}), {body("rice", {0, 0, 0.001})});
  run_for(sim, 0.05);
  const double weight = mass_of(sim) * kG;
  REQUIRE(floor_contacts(sim).size() == 3);
  const double overlap = 0.001 - sim.bodies.position[0].z();
  CHECK(overlap == Approx(weight / kKn).epsilon(1e-6));
}

TEST_CASE("a capsule and a straight polyline dropped flat rebound with en", "[nonconvex]") {
  const Shape capsule = faceless("capsule", {{-0.006, 0, 0}, {0.006, 0, 0}}, {{0, 1}}, 0.001);
  REQUIRE(capsule.convex);
  for (const Shape& s : {capsule, straight_rice(0.006, 0.001)})
    for (double en : {0.3, 0.5, 0.8}) {
      Scene scene = base_scene(law(kKn, en), true);
      scene.simulation.dt = 1e-7;
      const double v0 = 1.0;
      Simulation sim(scene, library({s}), {body(s.name.c_str(), {0, 0, 0.001 + 1e-6}, {0, 0, -v0})});
      REQUIRE(run_through_impact(sim, 200000));
      INFO(s.name << " en " << en);
      CHECK(sim.bodies.velocity[0].z() / v0 == Approx(en).epsilon(0.01));
    }
}

namespace {

// Largest change of kinetic + rotational energy from before to after two crosses collide
// elastically without friction, relative to the energy before.
double cross_collision_error(double dt) {
  Scene scene = base_scene(law(kKn, 1.0), false);
  scene.simulation.dt = dt;
  const Quat qa(Eigen::AngleAxisd(0.4, Vec3(1, 2, 0).normalized()));
  const Quat qb(Eigen::AngleAxisd(1.1, Vec3(0, 1, 3).normalized()));
  BodySpec a = body("alpha3", {-0.008, 0.0015, 0.0005}, {1.0, 0, 0}, qa);
  BodySpec b = body("alpha3", {0.008, -0.001, 0}, {-1.0, 0.1, 0}, qb);
  a.angular_velocity = Vec3(0, 20, 5);
  Simulation sim(scene, library({cross_shape()}), {a, b});
  const double before = motion_energy(sim);
  std::size_t touching = 0;
  for (int s = 0; s < int(0.03 / dt) && !(touching && sim.energy().contacts == 0); ++s) {
    sim.step();
    touching += sim.energy().contacts > 0;
  }
  REQUIRE(touching > 10);
  REQUIRE(sim.energy().contacts == 0);
  return std::abs(motion_energy(sim) - before) / before;
}

}  // namespace

TEST_CASE("elastic frictionless collisions of crosses conserve energy, better as dt shrinks", "[nonconvex]") {
  // Stated bound: 3e-5 (dt / 1 us)^2, second order as the velocity-Verlet kicks (measured 5.2e-5
  // at 2 us and 4.4e-6 at 0.5 us: single-contact regions, no patch-weight exchange).
  auto bound = [](double dt) { return 3e-5 * (dt / 1e-6) * (dt / 1e-6); };
  const double coarse = cross_collision_error(2e-6), fine = cross_collision_error(5e-7);
  INFO("relative energy change " << coarse << " at dt 2e-6 s, " << fine << " at 5e-7 s");
  CHECK(coarse < bound(2e-6));
  CHECK(fine < bound(5e-7));
}

TEST_CASE("two crosses meeting arm over arm push back in two regions and do not pass through", "[nonconvex]") {
  // Arms 5 roundings long (alpha3: 2). B above A, offset by (d, d) with 2 r < d < arm: B's x arm
  // lies across A's y arm, B's y arm across A's x arm (two edge-edge contacts, two regions), its
  // z arm between A's arms. Thrown down, B must come back up.
  Scene scene = base_scene(law(kKn, 1.0), false);
  scene.simulation.dt = 5e-7;
  const double d = 2.5 * kRound, h = 2 * kRound + 1e-5;
  Simulation sim(scene, library({cross_shape(5 * kRound)}),
                 {body("alpha3", {0, 0, 0}), body("alpha3", {d, d, h}, {0, 0, -1.0})});
  const double before = motion_energy(sim);
  double lowest = h;  // m, B's height over A: the cores cross at 0
  std::size_t most = 0;
  for (int s = 0; s < 40000 && !(most && sim.energy().contacts == 0); ++s) {
    sim.step();
    lowest = std::min(lowest, sim.bodies.position[1].z() - sim.bodies.position[0].z());
    most = std::max(most, sim.energy().contacts);
  }
  CHECK(most == 2);
  CHECK(lowest > 0.0);
  CHECK(sim.energy().contacts == 0);
  CHECK(sim.bodies.velocity[1].z() > sim.bodies.velocity[0].z());  // apart again
  CHECK(motion_energy(sim) == Approx(before).epsilon(1e-4));           // en = 1, no friction
}
