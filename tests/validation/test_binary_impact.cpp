// Binary normal impacts through the whole engine over en = 0.05 .. 1 (both sides of the
// critical damping en = e^-2), against the closed forms of the clamped linear spring-dashpot
// derived in validation.hpp: restitution, duration of the force, maximum overlap, maximum force.
// tests/sim/test_impacts.cpp covers en 0.2 .. 0.9 for equal spheres; this sweep adds the
// overdamped range, en = 1, the peak force and unequal masses (m_eff = m1 m2/(m1 + m2)).
#include <catch2/catch.hpp>

#include <string>

#include "validation.hpp"

using namespace polydem;
using namespace polydem::test;
using namespace polydem::validation;

namespace {

constexpr double kRadius = 0.005;  // m
constexpr double kKn = 1e5;        // N/m
constexpr int kStepsPerContact = 400;  // dt = t_c/400

// Tolerances, relative. Restitution and overlap: second order in dt (contact/law/
// second_order.hpp), measured <= 5e-6 and 2.2e-6 at 400 steps (0.1% and 0.08% when the
// dashpot read the half-step velocity). Duration: counted in whole steps (1 step = 0.25%).
// Force: its peak is at the touch for z > 1/2, and the first step with a force carries the
// impulse of the part of the step before the touch (run_impact skips it), so the peak is
// sampled up to 2 dt after the touch, where f fell by 2 dt f'(0) = w0 dt |1 - 4 z^2|/z of it
// (2.8% at en = 0.05, measured 2.6%); for z < 1/2 it is sampled near its smooth maximum.
constexpr double kTolRestitution = 2e-5, kTolDuration = 0.01, kTolOverlap = 1e-5, kTolForce = 0.03;

struct Errors {
  double restitution, duration, overlap, force;
};

Errors report(const std::string& name, const ClampedImpact& c, const MeasuredImpact& r) {
  return {table_row(name.c_str(), "restitution", c.restitution(), r.restitution),
          table_row(name.c_str(), "force duration s", c.release_time(), r.duration),
          table_row(name.c_str(), "max overlap m", c.max_overlap(), r.max_overlap),
          table_row(name.c_str(), "max force N", c.max_force(), r.max_force)};
}

void check(const Errors& e) {
  CHECK(e.restitution < kTolRestitution);
  CHECK(e.duration < kTolDuration);
  CHECK(e.overlap < kTolOverlap);
  CHECK(e.force < kTolForce);
}

const double kEnSweep[] = {0.05, 0.1, 0.13, 0.2, 0.3, 0.5, 0.7, 0.9, 1.0};  // 0.05-0.13: overdamped

}  // namespace

TEST_CASE("sphere-wall impact over en 0.05 to 1", "[validation][impact]") {
  const double v0 = 0.5;  // m/s
  std::printf("\n| case | quantity | answer | polydem | error |\n");
  for (double en : kEnSweep) {
    Scene scene = base_scene(law(kKn, en), true);
    const ShapeLibrary lib = library({sphere_shape(kRadius)});
    const double m = 2700.0 * lib.shapes[0].volume;
    const double z = prepare_law(scene.forces.contact.config).alpha_n;
    const ClampedImpact c{z, std::sqrt(kKn / m), v0, m};
    CHECK(c.restitution() == Approx(en).epsilon(1e-9));  // the engine's damping ratio returns en exactly
    scene.simulation.dt = c.release_time() / kStepsPerContact;
    Simulation sim(scene, lib, {body("sphere", {0, 0, kRadius + 0.1 * v0 * scene.simulation.dt.value()}, {0, 0, -v0})});
    const MeasuredImpact r = run_impact(
        sim, v0, [&] { return sim.bodies.position[0].z() - kRadius; },
        [&] { return sim.drivers[0].force.norm(); }, [&] { return sim.bodies.velocity[0].z(); });
    INFO("en " << en << " damping ratio " << z);
    check(report("sphere-wall en " + std::to_string(en).substr(0, 4), c, r));
  }
}

TEST_CASE("unequal sphere-sphere impact over en 0.05 to 1", "[validation][impact]") {
  const double v1 = 0.2, v2 = -0.6;  // m/s: approach speed 0.8, not in the centre-of-mass frame
  std::printf("\n| case | quantity | answer | polydem | error |\n");
  for (double en : kEnSweep) {
    Scene scene = base_scene(law(kKn, en), false);
    const ShapeLibrary lib = library({sphere_shape(kRadius)});
    BodySpec light = body("sphere", {0, 0, 0}, {0, 0, v1}), heavy = body("sphere", {0, 0, 2 * kRadius}, {0, 0, v2});
    heavy.density = 4.0 * light.density;
    const double m1 = light.density * lib.shapes[0].volume, m2 = heavy.density * lib.shapes[0].volume;
    const double m_eff = m1 * m2 / (m1 + m2), v0 = v1 - v2;
    const double z = prepare_law(scene.forces.contact.config).alpha_n;
    const ClampedImpact c{z, std::sqrt(kKn / m_eff), v0, m_eff};
    scene.simulation.dt = c.release_time() / kStepsPerContact;
    heavy.position.z() += 0.1 * v0 * scene.simulation.dt.value();
    Simulation sim(scene, lib, {light, heavy});
    const MeasuredImpact r = run_impact(
        sim, v0, [&] { return (sim.bodies.position[1] - sim.bodies.position[0]).norm() - 2 * kRadius; },
        [&] { return sim.bodies.force[1].norm(); },
        [&] { return sim.bodies.velocity[1].z() - sim.bodies.velocity[0].z(); });
    // Momentum m1 v1 + m2 v2 is conserved by equal and opposite forces, to round-off.
    const double p0 = m1 * v1 + m2 * v2, p1 = m1 * sim.bodies.velocity[0].z() + m2 * sim.bodies.velocity[1].z();
    CHECK(std::abs(p1 - p0) < 1e-14 * m2 * std::abs(v2) * 10);
    INFO("en " << en << " damping ratio " << z);
    check(report("sphere-sphere 1:4 en " + std::to_string(en).substr(0, 4), c, r));
  }
}
