// start_step does in one pass, and in one parallel team, what kick, drift,
// predict_end_velocities and the gravity reset did as four loops; close_and_start_step what a
// closing kick, the join step's turns and start_step did: bit for bit, at 1 and 2 threads.
#include <catch2/catch.hpp>

#include <omp.h>

#include <cstring>
#include <random>

#include "integrate/integrate.hpp"
#include "integrate/turn_table.hpp"
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

// Every array a step's opening writes but force and torque, b against ref, bit for bit.
void check_same_pass(const Bodies& b, const Bodies& ref) {
  check_same_motion(b, ref);
  CHECK(same_bits(b.angular_momentum, ref.angular_momentum));
  CHECK(std::memcmp(b.orientation.data(), ref.orientation.data(), b.orientation.size() * sizeof(Quat)) == 0);
}

// Every array a step's opening writes, b against ref, bit for bit.
void check_same_state(const Bodies& b, const Bodies& ref) {
  check_same_pass(b, ref);
  CHECK(same_bits(b.force, ref.force));
}

// The cuboids asymmetric, every other of the rest a sphere (its q the identity, shape 1 of
// two_shapes), the others isotropic.
RotorGroups every_rotor_path(Bodies& b) {
  RotorGroups groups = group_rotors(b);
  std::vector<std::size_t> isotropic;
  for (std::size_t i : groups.isotropic) {
    if (i % 2 == 0) {
      b.orientation[i] = Quat::Identity();
      b.shape[i] = 1;
      groups.spheres.push_back(i);
    } else {
      isotropic.push_back(i);
    }
  }
  groups.isotropic = isotropic;
  REQUIRE(!groups.spheres.empty());
  REQUIRE(!groups.asymmetric.empty());
  REQUIRE(!groups.isotropic.empty());
  return groups;
}

// Shape 0 a polyhedron (two vertices will do: turns read no more), shape 1 a sphere.
std::vector<Shape> two_shapes() {
  std::vector<Shape> shapes(2);
  shapes[0].vertices = {Vec3(0.01, 0.0, 0.0), Vec3(0.0, 0.01, 0.0)};  // m
  shapes[1].vertices = {Vec3::Zero()};
  return shapes;
}

// A closing kick's contact sum, added to force and torque (after m gravity with `gravity_mass`,
// as ForceSums makes them where nothing else acts: close_and_start_step<true>'s `before`).
struct ContactSum {
  Bodies* b;
  bool gravity_mass;
  Vec3 gravity;                                                                   // m/s^2
  Vec3 force = Vec3(0.3, -0.2, 0.1), torque = Vec3(2e-4, 1e-4, -3e-4);            // N, N m
  void operator()(std::size_t i) const {
    if (gravity_mass) b->force[i] = b->mass[i] * gravity, b->torque[i].setZero();
    add_to(i, b->force[i], b->torque[i]);
  }
  void add_to(std::size_t, Vec3& f, Vec3& t) const { f += force, t += torque; }
};

struct Turn {
  std::uint32_t body;
  Vec3 moment;  // N m s^2, world
};

// Every fifth body's turn, increasing (spheres among them: they take none).
std::vector<Turn> some_turns(std::size_t n) {
  std::vector<Turn> turns;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-2e-6, 2e-6);  // ~1e-3 rad on 2e-3 kg m^2
  for (std::uint32_t i = 0; i < n; i += 5) turns.push_back({i, Vec3(u(rng), u(rng), u(rng))});
  return turns;
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
  const RotorGroups groups = every_rotor_path(separate);
  Bodies fused = separate;
  kick_after(separate, h, groups, ContactSum{&separate, false, gravity});
  start_step(separate, h, dt, groups, gravity);
  for (int threads : {1, 2}) {
    Bodies b = fused;
    omp_set_num_threads(threads);
    in_team(true, [&] { close_and_start_step(b, h, dt, groups, gravity, ContactSum{&b, false, gravity}); });
    check_same_state(b, separate);
  }
  omp_set_num_threads(1);
}

// A join step's turns left open with the kick (Simulation::step): the joined pass turns each
// body between its closing and opening kicks, as a closed kick, turn_bodies and start_step do.
TEST_CASE("close_and_start_step with turns equals kick_after, turn_bodies and start_step, bit for bit") {
  const double h = 5e-6, dt = 1e-5;      // s
  const Vec3 gravity(0.0, 0.0, -9.807);  // m/s^2
  const std::size_t n = 3 * kParallelMinItems;
  const std::vector<Shape> shapes = two_shapes();
  const std::vector<Turn> turns = some_turns(n);
  Bodies start = random_bodies(n);
  const RotorGroups groups = every_rotor_path(start);
  for (bool from_gravity : {false, true}) {  // close_and_start_step<true>: force and torque in registers
    INFO("from gravity " << from_gravity);
    Bodies separate = start;
    std::vector<double> work;  // J
    kick_after(separate, h, groups, ContactSum{&separate, from_gravity, gravity});
    turn_bodies(separate, turns, shapes, [&](double w) { work.push_back(w); });
    start_step(separate, h, dt, groups, gravity);
    REQUIRE(work.size() > turns.size() / 3);  // the spheres' and zero turns book nothing
    for (int threads : {1, 2}) {
      INFO(threads << " threads");
      Bodies b = start;
      TurnTable table;
      table.take(b, turns, shapes);
      omp_set_num_threads(threads);
      const ContactSum sums{&b, from_gravity, gravity};
      in_team(true, [&] {
        if (from_gravity)
          close_and_start_step<true>(b, h, dt, groups, gravity, sums, {}, NoWatch{}, true, table.pass());
        else
          close_and_start_step(b, h, dt, groups, gravity, sums, {}, NoWatch{}, true, table.pass());
      });
      std::vector<double> booked;
      table.book([&](double w) { booked.push_back(w); });
      CHECK(booked == work);
      CHECK(table.empty());
      check_same_pass(b, separate);
      if (!from_gravity) check_same_state(b, separate);
    }
  }
  omp_set_num_threads(1);
}

TEST_CASE("A turn table keeps no turn of a sphere and is empty again once booked") {
  const std::vector<Shape> shapes = two_shapes();
  Bodies b = random_bodies(12);
  b.shape[5] = 1;  // a sphere
  TurnTable table;
  table.take(b, std::vector<Turn>{{0, Vec3(1e-6, 0.0, 0.0)}, {5, Vec3(0.0, 1e-6, 0.0)}, {7, Vec3::Zero()}}, shapes);
  const PassTurns pass = table.pass();
  CHECK(pass.at(0) != nullptr);
  CHECK(pass.at(5) == nullptr);
  CHECK(pass.at(7) != nullptr);  // a zero moment is kept: it turns nothing and books nothing
  CHECK(pass.at(3) == nullptr);
  pass.at(0)->work = 2.0;
  std::vector<double> booked;
  table.book([&](double w) { booked.push_back(w); });
  CHECK(booked == std::vector<double>{2.0});
  CHECK(table.empty());
  table.take(b, std::vector<Turn>{{3, Vec3(1e-6, 0.0, 0.0)}}, shapes);
  CHECK(table.pass().at(0) == nullptr);  // book() cleared the last step's slots
  CHECK(table.pass().at(3) != nullptr);
}
