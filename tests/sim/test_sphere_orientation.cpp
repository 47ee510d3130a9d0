// A sphere's orientation is not integrated (integrate.hpp, Rotor::sphere): a run keeps it the
// identity with L in the world frame, and a checkpoint of an older build, whose spheres turned
// (random q, L in the body frame), resumes on the bits of the same state written by this one.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <filesystem>
#include <random>

#include "sim/checkpoint.hpp"
#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// 27 spheres of 5 mm dropped spinning, in random orientations, on a floor: contacts with it
// and each other, friction turning them.
struct SpinningDrop {
  Scene scene = base_scene(law(1e5, 0.5, 0.5, 1e5), true, Vec3(0, 0, -9.807));
  ShapeLibrary lib = library({sphere_shape(0.005)});
  std::vector<BodySpec> specs;
  SpinningDrop() {
    std::mt19937_64 rng(9);
    auto u = [&] { return double(rng() >> 11) * 0x1.0p-53 - 0.5; };
    for (int k = 0; k < 27; ++k) {
      BodySpec b = body("sphere", Vec3(0.0105 * (k % 3 - 1), 0.0105 * ((k / 3) % 3 - 1), 0.006 + 0.0105 * (k / 9)),
                        Vec3(0, 0, -0.3), Quat(Eigen::Vector4d(u(), u(), u(), u())).normalized());
      b.angular_velocity = 100.0 * Vec3(u(), u(), u());  // rad/s
      specs.push_back(b);
    }
  }
};

std::string temp_path(const char* name) {
  return (std::filesystem::temp_directory_path() / ("polydem_sphere_q_" + std::to_string(::getpid()) + name)).string();
}

// m^2 kg/s, the largest |L - I w| over the bodies, relative to |I w|.
double spin_mismatch(const Bodies& b) {
  double worst = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    const Vec3 iw = b.inertia[i].x() * b.angular_velocity[i];
    worst = std::max(worst, (b.angular_momentum[i] - iw).norm() / iw.norm());
  }
  return worst;
}

}  // namespace

TEST_CASE("spheres keep the identity orientation, and a checkpoint whose spheres turned resumes on the same bits",
          "[checkpoint]") {
  const SpinningDrop d;
  Simulation sim(d.scene, d.lib, d.specs);
  for (int s = 0; s < 400; ++s) sim.step();
  REQUIRE(sim.engine().stats().contacts > 0);
  for (const Quat& q : sim.bodies.orientation) CHECK(q.coeffs() == Quat::Identity().coeffs());
  CHECK(spin_mismatch(sim.bodies) < 1e-12);  // L = I w in the world frame, to round-off
  const double rotational = sim.energy().rotational;  // J
  double from_w = 0.0;
  for (std::size_t i = 0; i < sim.bodies.size(); ++i)
    from_w += 0.5 * sim.bodies.inertia[i].x() * sim.bodies.angular_velocity[i].squaredNorm();
  CHECK(rotational == Approx(from_w).epsilon(1e-12));

  const std::string now = temp_path("now.bin"), old = temp_path("old.bin");
  write_checkpoint(now, sim, OutputProgress{});
  // The same state as an older build held it: a turned q and L in that body frame.
  std::mt19937_64 rng(4);
  for (std::size_t i = 0; i < sim.bodies.size(); ++i) {
    const Quat q = Quat(Eigen::Vector4d(1.0, double(rng() % 7), -double(rng() % 5), 0.5)).normalized();
    sim.bodies.orientation[i] = q;
    sim.bodies.angular_momentum[i] = q.conjugate() * sim.bodies.angular_momentum[i];
  }
  write_checkpoint(old, sim, OutputProgress{});

  Simulation from_now(d.scene, d.lib, d.specs), from_old(d.scene, d.lib, d.specs);
  OutputProgress progress;
  read_checkpoint(now, from_now, progress);
  read_checkpoint(old, from_old, progress);
  std::filesystem::remove(now);
  std::filesystem::remove(old);
  for (const Quat& q : from_old.bodies.orientation) CHECK(q.coeffs() == Quat::Identity().coeffs());
  CHECK(spin_mismatch(from_old.bodies) < 1e-12);
  for (int s = 0; s < 400; ++s) {
    from_now.step();
    from_old.step();
  }
  // Nothing reads a sphere's q or L but the output: the motion is the same to the bit.
  CHECK(same_bits(from_old.bodies.position, from_now.bodies.position));
  CHECK(same_bits(from_old.bodies.velocity, from_now.bodies.velocity));
  CHECK(same_bits(from_old.bodies.angular_velocity, from_now.bodies.angular_velocity));
  CHECK(from_old.energy().rotational == Approx(from_now.energy().rotational).epsilon(1e-13));
}
