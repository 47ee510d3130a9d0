// A torque-free asymmetric top through the whole pipeline: a rounded box whose principal
// moments come from the exact mass properties of the shape, spun near its intermediate axis in
// a scene with a contact law and no contact (tests/integrate checks the rotor alone over 10^6
// steps). Answers: energy and the world angular momentum are conserved, and w along the
// intermediate axis flips with the period of the elliptic-function solution of Euler's
// equations (flip_period in validation.hpp, Landau & Lifshitz, Mechanics, 37.10-37.12).
#include <catch2/catch.hpp>

#include <algorithm>
#include <vector>

#include "validation.hpp"

using namespace polydem;
using namespace polydem::test;
using namespace polydem::validation;

TEST_CASE("torque-free asymmetric top flips with the elliptic period", "[validation][rotation]") {
  const Shape box = box_shape({0.004, 0.008, 0.012}, 0.0005);
  Scene scene = base_scene(law(1e5, 0.5), false);
  scene.simulation.dt = 1e-4;  // s: w dt = 1e-3 rad per step
  // Principal axes are the world axes at identity orientation: spin about the intermediate one.
  const Vec3 moments = box.inertia_per_mass;
  int axes[3] = {0, 1, 2};
  std::sort(axes, axes + 3, [&](int a, int b) { return moments[a] < moments[b]; });
  BodySpec spec = body("box", Vec3::Zero());
  spec.angular_velocity = 10.0 * Vec3::Unit(axes[1]) + 0.5 * Vec3::Unit(axes[0]);  // rad/s, 5% off the axis
  Simulation sim(scene, library({box}), {spec});

  const Vec3 inertia = sim.bodies.inertia[0];
  const auto energy = [&] {
    const Vec3& l = sim.bodies.angular_momentum[0];
    return 0.5 * l.cwiseProduct(l).cwiseQuotient(inertia).sum();
  };
  const double e0 = energy();
  const Vec3 l0 = sim.bodies.orientation[0] * sim.bodies.angular_momentum[0];
  const Vec3 sorted(inertia[axes[0]], inertia[axes[1]], inertia[axes[2]]);
  const double period = flip_period(sorted, e0, l0.squaredNorm());

  std::vector<double> flips;  // s, sign changes of w about the intermediate axis (body frame)
  double w_prev = sim.bodies.angular_momentum[0][axes[1]], max_de = 0.0, max_dl = 0.0;
  const auto steps = std::llround(3.2 * period / sim.dt());
  for (long long s = 0; s < steps; ++s) {
    sim.step();
    const double w = sim.bodies.angular_momentum[0][axes[1]];
    if ((w < 0.0) != (w_prev < 0.0)) flips.push_back(sim.time() - sim.dt() * w / (w - w_prev));
    w_prev = w;
    max_de = std::max(max_de, std::abs(energy() - e0));
    max_dl = std::max(max_dl, (sim.bodies.orientation[0] * sim.bodies.angular_momentum[0] - l0).norm());
  }
  REQUIRE(flips.size() >= 6);
  const double measured = 2.0 * (flips.back() - flips.front()) / double(flips.size() - 1);
  std::printf("\n| case | quantity | answer | polydem | error |\n");
  // NO_SQUISH conserves a modified energy: |dE|/E stays O((w dt)^2) = 1e-6 without drift.
  CHECK(table_row("free top, box 4x8x12 mm", "energy J", e0, e0 + max_de) < 1e-6);
  // Each sub-step is an exact rotation of L: round-off only (3e4 steps x 1e-16).
  CHECK(table_row("free top, box 4x8x12 mm", "|L world| kg m^2/s", l0.norm(), l0.norm() + max_dl) < 1e-11);
  // The period depends on e and l2 through K(k): a relative energy error of 1e-6 moves it by
  // ~1e-6 ln(1/k'); measured 5e-8, the O(dt^2) phase error of the flips included.
  CHECK(table_row("free top, box 4x8x12 mm", "flip period s", period, measured) < 1e-6);
}
