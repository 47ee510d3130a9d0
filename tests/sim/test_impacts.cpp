// Binary impacts of the whole engine against the closed forms of the linear spring-dashpot
// law with the no-pull clamp. For overlap x(t) of an underdamped oscillator (damping ratio z,
// w0 = sqrt(kn/m_eff), wd = w0 sqrt(1 - z^2)), x = v0/wd exp(-z w0 t) sin(wd t); the clamp
// releases when kn x + nu x' = 0, at wd t_c = pi - 2 asin(z), and then
//   e = exp(-z (pi - 2 asin z) / sqrt(1 - z^2)),   x_max = v0/w0 exp(-z acos(z) / sqrt(1 - z^2)).
// (Derivation: substitute x into kn x + 2 z sqrt(kn m) x' = 0; see e.g. Schwager & Poeschel,
// Phys. Rev. E 78, 051304 (2008), whose unclamped result this modifies.)
#include <catch2/catch.hpp>

#include <cmath>

#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

struct ImpactResult {
  double restitution, duration, max_overlap;
};

struct Closed {
  double e, duration, max_overlap;  // duration: until the overlap closes, t_c + nu/kn = t_c + 2 z / w0
};

Closed closed_form(double zeta, double kn, double m_eff, double v0) {
  const double w0 = std::sqrt(kn / m_eff), s = std::sqrt(1.0 - zeta * zeta), wd = w0 * s;
  const double t_c = (kPi - 2.0 * std::asin(zeta)) / wd;  // the clamp releases; then free flight at -x'(t_c)
  return {std::exp(-zeta * (kPi - 2.0 * std::asin(zeta)) / s), t_c + 2.0 * zeta / w0,
          v0 / w0 * std::exp(-zeta * std::acos(zeta) / s)};
}

// Runs until the normal relative velocity has turned and no contact remains.
ImpactResult run_impact(Simulation& sim, double v0, bool pair) {
  ImpactResult r{0, 0, 0};
  double t_start = -1.0;
  for (int s = 0; s < 200000; ++s) {
    sim.step();
    const std::size_t contacts = sim.engine().stats().contacts;
    const double gap = pair ? (sim.bodies.position[1] - sim.bodies.position[0]).norm() -
                                  2.0 * sim.shapes()[0].radius
                            : sim.bodies.position[0].z() - sim.shapes()[0].radius;
    r.max_overlap = std::max(r.max_overlap, -gap);
    if (contacts && t_start < 0) t_start = sim.time() - sim.dt();
    if (!contacts && t_start >= 0) {
      // The clamp releases the force before the overlap closes: contact time ends at release.
      const double vn = pair ? (sim.bodies.velocity[1] - sim.bodies.velocity[0]).z() : sim.bodies.velocity[0].z();
      r.restitution = vn / v0;
      r.duration = sim.time() - sim.dt() - t_start;  // overlap lasted from t_start to the last step
      return r;
    }
  }
  FAIL("impact did not end");
  return r;
}

}  // namespace

TEST_CASE("sphere-wall normal impact: restitution, duration, overlap", "[impact]") {
  const double radius = 0.005, v0 = 1.0, kn = 1e5;
  for (double en : {0.2, 0.3, 0.5, 0.7, 0.9}) {  // underdamped (en > e^-2), where the closed form holds
    Scene scene = base_scene(law(kn, en), true);
    const ShapeLibrary lib = library({sphere_shape(radius)});
    const double m = 2700.0 * lib.shapes[0].volume;
    scene.simulation.dt = kPi * std::sqrt(m / kn) / 400.0;  // 400 steps per contact: 0.25% time resolution
    Simulation sim(scene, lib, {body("sphere", {0, 0, radius + 1e-4}, {0, 0, -v0})});
    const ImpactResult r = run_impact(sim, v0, false);
    const LawParams p = prepare_law(scene.forces.contact.config);
    const Closed c = closed_form(p.alpha_n, kn, sim.bodies.mass[0], v0);
    INFO("en " << en << " restitution " << r.restitution << " max overlap " << r.max_overlap << " closed " << c.max_overlap);
    CHECK(c.e == Approx(en).epsilon(1e-9));           // alpha_n solved for the clamped law
    CHECK(r.restitution == Approx(en).epsilon(0.005)); // 0.5%: time discretisation, dt = 0.1 x critical
    CHECK(r.max_overlap == Approx(c.max_overlap).epsilon(0.01));
    CHECK(r.duration == Approx(c.duration).epsilon(0.01));
  }
}

TEST_CASE("sphere-sphere normal impact: restitution with m_eff = m/2", "[impact]") {
  const double radius = 0.005, v = 0.5, kn = 1e5;
  for (double en : {0.2, 0.5, 0.8}) {
    Scene scene = base_scene(law(kn, en), false);
    const ShapeLibrary lib = library({sphere_shape(radius)});
    const double m_eff = 0.5 * 2700.0 * lib.shapes[0].volume;
    scene.simulation.dt = kPi * std::sqrt(m_eff / kn) / 400.0;
    Simulation sim(scene, lib, {body("sphere", {0, 0, 0}, {0, 0, v}),
                                body("sphere", {0, 0, 2 * radius + 1e-4}, {0, 0, -v})});
    const ImpactResult r = run_impact(sim, 2 * v, true);  // approach speed 2v
    const LawParams p = prepare_law(scene.forces.contact.config);
    const Closed c = closed_form(p.alpha_n, kn, 0.5 * sim.bodies.mass[0], 2 * v);
    INFO("en " << en << " restitution " << r.restitution);
    CHECK(r.restitution == Approx(en).epsilon(0.005));
    CHECK(r.max_overlap == Approx(c.max_overlap).epsilon(0.01));
    CHECK(r.duration == Approx(c.duration).epsilon(0.01));
  }
}

TEST_CASE("free fall at two time steps is exact", "[gravity]") {
  const Vec3 g(0, 0, -9.807);
  for (double dt : {1e-4, 3e-4}) {
    Scene scene = base_scene(law(1e5, 0.5), false, g);
    scene.simulation.dt = dt;
    const ShapeLibrary lib = library({sphere_shape(0.005)});
    Simulation sim(scene, lib, {body("sphere", {0, 0, 1}, {0.1, 0, 0.5})});
    for (int s = 0; s < 1000; ++s) sim.step();
    const double t = sim.time();
    // Velocity Verlet integrates a constant force exactly: x = x0 + v0 t + g t^2 / 2.
    CHECK(sim.bodies.position[0].z() == Approx(1.0 + 0.5 * t - 0.5 * 9.807 * t * t).epsilon(1e-12));
    CHECK(sim.bodies.position[0].x() == Approx(0.1 * t).epsilon(1e-12));
    CHECK(sim.bodies.velocity[0].z() == Approx(0.5 - 9.807 * t).epsilon(1e-12));
  }
}
