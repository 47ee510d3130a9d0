#pragma once
// The cases of the work-precision sweep (accuracy_sweep.cpp, tools/bench/accuracy) and of its
// CI slice (test_accuracy.cpp): each runs one case with known answer at a time step given as a
// fraction of the critical step `polydem check` prints, and returns its relative error.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <vector>

#include "corner_reference.hpp"
#include "oblique_reference.hpp"
#include "rolling_reference.hpp"

namespace polydem::validation::accuracy {

using namespace polydem::test;


constexpr double kRadius = 0.005, kKn = 1e5, kEn = 0.5;  // m, N/m, -

// The contact critical step the engine prints for a scene (polydem check).
inline double critical_step(const Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs) {
  return Simulation(scene, lib, specs).time_step().critical;
}

// Sphere on a wall at 0.5 m/s, the step set by `step(scene, lib, specs)`, with the linear law's
// exact step (the spheres' default) or not: the rebound speed over the approach speed. `phase`
// in [0, 1): where in its step the touch falls (the start gap is that share of the stroke 0.5 m/s
// x dt, plus 1 nm); negative: a gap of 0.1 um (the sweep's one start). The gap counts from the
// law's reach (dncut with cohesion): the touch is where the pair starts to interact.
template <class SetStep>
double sphere_wall_rebound(const ContactParams& config, bool exact, const SetStep& step, double phase = -1.0) {
  Scene scene = base_scene(config, true);
  scene.simulation.exact_step = exact;
  const ShapeLibrary lib = library({sphere_shape(kRadius)});
  const double reach = kRadius + (config.fc > 0.0 ? config.dncut : 0.0);  // m, centre height where it starts
  std::vector<BodySpec> specs = {body("sphere", {0, 0, reach + 1e-7}, {0, 0, -0.5})};
  step(scene, lib, specs);
  if (phase >= 0.0) specs[0].position.z() = reach + 1e-9 + phase * 0.5 * *scene.simulation.dt;
  Simulation sim(scene, lib, specs);
  const MeasuredImpact r = run_impact(
      sim, 0.5, [&] { return sim.bodies.position[0].z() - kRadius; }, [&] { return sim.drivers[0].force.z(); },
      [&] { return sim.bodies.velocity[0].z(); });
  return r.restitution;
}

// The same: error of the restitution against en.
template <class SetStep>
double sphere_wall_error(const ContactParams& config, bool exact, const SetStep& step, double phase = -1.0) {
  return std::abs(sphere_wall_rebound(config, exact, step, phase) / config.en - 1.0);
}

// The same at dt = fraction x critical.
inline double binary_impact(double fraction, double en = kEn, bool exact = false) {
  return sphere_wall_error(law(kKn, en), exact, [&](Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs) {
    scene.simulation.dt = fraction * critical_step(scene, lib, specs);
  });
}

// The largest error over `phases` touch phases spread over the step (sphere_wall_error): a bed's
// impacts touch anywhere in a step.
inline double binary_impact_worst_phase(double fraction, double en, bool exact = true, int phases = 16) {
  double worst = 0.0;
  for (int k = 0; k < phases; ++k)
    worst = std::max(worst, sphere_wall_error(
                                law(kKn, en), exact,
                                [&](Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs) {
                                  scene.simulation.dt = fraction * critical_step(scene, lib, specs);
                                },
                                double(k) / phases));
  return worst;
}

// Cohesive sphere-wall impact (fc 0.5 N, dncut 10 um: the band's stiffness fc/dncut is half kn):
// the largest error of the rebound over 16 touch places in the step (the band's start), against
// the same impact at 0.0005 x critical (0.001 agrees to 2e-8). Measured 2.55e-3 at 0.1, 3.8e-5 at
// 0.0125 (order 2.02 over the three halvings; 0.8 between 0.05 and 0.025, where the kinks at the
// band's ends and at the touch fall together).
inline ContactParams cohesive_law() {
  ContactParams p = law(kKn, kEn);
  p.fc = 0.5;      // N
  p.dncut = 1e-5;  // m
  return p;
}
inline double cohesive_rebound(double fraction, double phase) {
  return sphere_wall_rebound(cohesive_law(), true, [&](Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs) {
    scene.simulation.dt = fraction * critical_step(scene, lib, specs);
  }, phase);
}
inline double cohesive_impact_worst_phase(double fraction) {
  static const double converged = cohesive_rebound(0.0005, 0.0);  // -, once: 2,000 steps a contact
  double worst = 0.0;
  for (int k = 0; k < 16; ++k) worst = std::max(worst, std::abs(cohesive_rebound(fraction, k / 16.0) / converged - 1.0));
  return worst;
}

// The worst over 16 touch phases at `dt: auto` (the exact step's kAutoAccuracy for a sphere).
inline double binary_impact_at_auto_worst_phase(double en) {
  double worst = 0.0;
  for (int k = 0; k < 16; ++k)
    worst = std::max(worst, sphere_wall_error(
                                law(kKn, en), true,
                                [&](Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs) {
                                  scene.simulation.dt.reset();
                                  scene.simulation.dt = Simulation(scene, lib, specs).dt();  // the step auto took
                                },
                                k / 16.0));
  return worst;
}

// The same at `dt: auto` with `simulation: accuracy` (the step chosen for that error).
inline double binary_impact_at_accuracy(double accuracy, double en = kEn) {
  return sphere_wall_error(law(kKn, en), true, [&](Scene& scene, const ShapeLibrary&, const std::vector<BodySpec>&) {
    scene.simulation.dt.reset();
    scene.simulation.accuracy = accuracy;
  });
}

// Hertz with Tsuji's dashpot (E 1e8 Pa, Poisson 0.3, as test_hertz_impact.cpp), sphere on a
// wall at 0.5 m/s, dt = fraction x critical: the worst restitution error over `phases` touch
// places in the step (one: the 0.1 um gap).
inline ContactParams hertz_law(double en) {
  ContactParams config;
  config.hertz = true;
  config.young = 1e8;  // Pa
  config.poisson = 0.3;
  config.en = en;
  return config;
}
inline double hertz_impact(double fraction, double en, int phases = 16) {
  const ContactParams config = hertz_law(en);
  const auto set_step = [&](Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs) {
    scene.simulation.dt = fraction * critical_step(scene, lib, specs);
  };
  if (phases == 1) return sphere_wall_error(config, false, set_step);
  double worst = 0.0;
  for (int k = 0; k < phases; ++k) worst = std::max(worst, sphere_wall_error(config, false, set_step, double(k) / phases));
  return worst;
}

// The step `simulation: accuracy` picks for that Hertz impact (en as hertz_law), as a fraction of
// the critical step, and the worst restitution error over 16 touch places at that step.
struct StepError {
  double fraction, error;  // -, -
};
inline StepError hertz_impact_at_accuracy(double accuracy, double en) {
  StepError out{0.0, 0.0};
  const auto set_step = [&](Scene& scene, const ShapeLibrary& lib, const std::vector<BodySpec>& specs) {
    scene.simulation.dt.reset();
    scene.simulation.accuracy = accuracy;
    const Simulation sim(scene, lib, specs);
    scene.simulation.dt = sim.dt();  // the step it took, so that the touch places are set from it
    out.fraction = sim.dt() / sim.time_step().critical;
  };
  for (int k = 0; k < 16; ++k) out.error = std::max(out.error, sphere_wall_error(hertz_law(en), false, set_step, k / 16.0));
  return out;
}

// Spheres of radius 5 and 7 mm (masses 1 : 2.74) meeting at 0.5 m/s: error of the restitution.
inline double sphere_pair_impact(double fraction, bool exact = false) {
  Scene scene = base_scene(law(kKn, kEn), false);
  scene.simulation.exact_step = exact;
  const double big = 1.4 * kRadius;  // m
  const ShapeLibrary lib = library({sphere_shape(kRadius), sphere_shape(big, "big")});
  const std::vector<BodySpec> specs = {body("sphere", {0, 0, kRadius + 1e-7}, {0, 0, -0.25}),
                                       body("big", {0, 0, -big}, {0, 0, 0.25})};
  scene.simulation.dt = fraction * critical_step(scene, lib, specs);
  Simulation sim(scene, lib, specs);
  const MeasuredImpact r = run_impact(
      sim, 0.5, [&] { return sim.bodies.position[0].z() - sim.bodies.position[1].z() - kRadius - big; },
      [&] { return 0.0; }, [&] { return sim.bodies.velocity[0].z() - sim.bodies.velocity[1].z(); });
  return std::abs(r.restitution / kEn - 1.0);
}

// A sphere landing at 45 deg on the wall (both components v, m/s) with spin w (rad/s), at
// `fraction` of the critical step, `phase` as in sphere_wall_error; m is set to its mass (kg).
inline MeasuredImpact oblique_landing(const ContactParams& config, double fraction, double phase, double v,
                                      const Vec3& w, double& m, bool exact = true) {
  Scene scene = base_scene(config, true);
  scene.simulation.exact_step = exact;
  const ShapeLibrary lib = library({sphere_shape(kRadius)});
  std::vector<BodySpec> specs = {body("sphere", {0, 0, kRadius + 1e-7}, {v, 0, -v})};
  specs[0].angular_velocity = w;
  scene.simulation.dt = fraction * critical_step(scene, lib, specs);
  if (phase >= 0.0) specs[0].position.z() = kRadius + 1e-9 + phase * v * *scene.simulation.dt;
  Simulation sim(scene, lib, specs);
  m = sim.bodies.mass[0];
  return run_impact(
      sim, v, [&] { return sim.bodies.position[0].z() - kRadius; }, [&] { return sim.drivers[0].force.z(); },
      [&] { return sim.bodies.velocity[0].z(); });
}

// Sphere on a wall at 45 deg, mu 0.3: error of v_t' and R w' against the RK4 reference, / v_t;
// with the linear law's exact normal step (the default for spheres) or the end-of-step dashpot,
// and the tangential dashpot of ratio `damp_tangential` (0: none).
// `phase` as in sphere_wall_error (negative: a gap of 0.1 um).
inline double oblique_impact(double fraction, bool exact = true, double phase = -1.0, double damp_tangential = 0.0) {
  const double mu = 0.3, v = 0.3 * std::sqrt(0.5);  // m/s, both components
  ContactParams config = law(kKn, kEn, mu, kKn);
  config.damp_tangential = damp_tangential;
  double m = 0.0;  // kg
  const MeasuredImpact r = oblique_landing(config, fraction, phase, v, Vec3::Zero(), m, exact);
  static std::map<double, Rebound> refs;  // per dashpot, the same for every step size: computed once
  if (!refs.count(damp_tangential)) {
    const LawParams prepared = prepare_law(config);
    const double z = prepared.alpha_n;
    const SpringContact reference{m, 0.4 * m * kRadius * kRadius, 2.0 * z * std::sqrt(kKn * m), kRadius, kKn, kKn, mu,
                                  pair_tangential_damping(prepared, m)};
    double change = 0.0;
    refs[damp_tangential] = reference.extrapolated(v, v, ClampedImpact{z, std::sqrt(kKn / m), v, m}.release_time(), change);
  }
  const Rebound& ref = refs[damp_tangential];
  return std::max(std::abs(r.velocity.x() - ref.vt), std::abs(kRadius * r.angular_velocity.y() - ref.spin)) / v;
}

// The largest error over `phases` touch places in the step (oblique_impact, the default step).
inline double oblique_impact_worst_phase(double fraction, int phases = 16, double damp_tangential = 0.0) {
  double worst = 0.0;
  for (int k = 0; k < phases; ++k)
    worst = std::max(worst, oblique_impact(fraction, true, double(k) / phases, damp_tangential));
  return worst;
}

// Sphere landing at 0.2 m/s spinning at 20 rad/s on a wall with rolling resistance (kr = 0.2 kn
// R^2, mur 0.1) and no friction: the rolling spring slips from the touch, sticks and slips out as
// the normal force falls. Error of the spin after, against the RK4 reference, / the spin before.
// `phase` as in sphere_wall_error (negative: a gap of 0.1 um).
inline double rolling_impact(double fraction, double phase = -1.0) {
  const double v = 0.2, w0 = 20.0, kr = 0.2 * kKn * kRadius * kRadius, mur = 0.1;  // m/s, rad/s, N m/rad, -
  ContactParams config = law(kKn, kEn);
  config.kr = kr, config.mur = mur;
  Scene scene = base_scene(config, true);
  const ShapeLibrary lib = library({sphere_shape(kRadius)});
  std::vector<BodySpec> specs = {body("sphere", {0, 0, kRadius + 1e-7}, {0, 0, -v})};
  specs[0].angular_velocity = Vec3(0, w0, 0);
  scene.simulation.dt = fraction * critical_step(scene, lib, specs);
  if (phase >= 0.0) specs[0].position.z() = kRadius + 1e-9 + phase * v * *scene.simulation.dt;
  Simulation sim(scene, lib, specs);
  run_impact(
      sim, v, [&] { return sim.bodies.position[0].z() - kRadius; }, [&] { return sim.drivers[0].force.z(); },
      [&] { return sim.bodies.velocity[0].z(); });
  static const double ref = [&] {  // the same for every step size: computed once
    const double m = sim.bodies.mass[0], z = prepare_law(scene.forces.contact.config).alpha_n;
    const RollingContact reference{m, 0.4 * m * kRadius * kRadius, 2.0 * z * std::sqrt(kKn * m), kRadius, kKn, kr, mur};
    return reference.extrapolated(w0, v, ClampedImpact{z, std::sqrt(kKn / m), v, m}.release_time());
  }();
  return std::abs(sim.bodies.angular_velocity[0].y() - ref) / w0;
}

// The largest error over `phases` touch places in the step (rolling_impact).
inline double rolling_impact_worst_phase(double fraction, int phases = 16) {
  double worst = 0.0;
  for (int k = 0; k < phases; ++k) worst = std::max(worst, rolling_impact(fraction, double(k) / phases));
  return worst;
}

// A sphere landing at 45 deg (0.3 m/s) spinning forward at half the rolling speed on a wall with
// friction (mu 0.3, kt = kn), the tangential dashpot (ratio 0.3) and rolling resistance (kr 0.2
// kn R^2, mur 0.1): the tangential spring slips, sticks and slips out, and the rolling spring
// with it. Error of v_t' and R w' against the RK4 reference (oblique_reference.hpp), / v_t.
// `phase` as in sphere_wall_error (negative: a gap of 0.1 um).
inline double rolling_friction_impact(double fraction, double phase = -1.0) {
  const double mu = 0.3, v = 0.3 * std::sqrt(0.5), w0 = 0.5 * v / kRadius;  // -, m/s (both components), rad/s
  const double kr = 0.2 * kKn * kRadius * kRadius, mur = 0.1, damp_tangential = 0.3;  // N m/rad, -, -
  ContactParams config = law(kKn, kEn, mu, kKn);
  config.damp_tangential = damp_tangential, config.kr = kr, config.mur = mur;
  double m = 0.0;  // kg
  const MeasuredImpact r = oblique_landing(config, fraction, phase, v, Vec3(0, w0, 0), m);
  static const Rebound ref = [&] {  // the same for every step size: computed once
    const LawParams prepared = prepare_law(config);
    const double z = prepared.alpha_n;
    const SpringContact reference{m,   0.4 * m * kRadius * kRadius, 2.0 * z * std::sqrt(kKn * m), kRadius, kKn, kKn, mu,
                                  pair_tangential_damping(prepared, m), kr, mur};
    double change = 0.0;
    return reference.extrapolated(v, v, ClampedImpact{z, std::sqrt(kKn / m), v, m}.release_time(), change, w0);
  }();
  return std::max(std::abs(r.velocity.x() - ref.vt), std::abs(kRadius * r.angular_velocity.y() - ref.spin)) / v;
}

// The largest error over `phases` touch places in the step (rolling_friction_impact).
inline double rolling_friction_impact_worst_phase(double fraction, int phases = 16) {
  double worst = 0.0;
  for (int k = 0; k < phases; ++k) worst = std::max(worst, rolling_friction_impact(fraction, double(k) / phases));
  return worst;
}

// Cube landing on a corner off its centre (test_cube_landing.cpp): error of the contact-point
// restitution against the rigid-body impulse with the rotational effective mass. With
// damping_mass: contact (contact_mass) the dashpot is tuned to that mass: the answer is en.
// rk4: against the rigid body integrated with the contact law instead (corner_reference.hpp),
// without the impulse's floor of 5.6e-4 (4.5e-4 with the contact's mass: the turn during the contact).
inline double cube_corner_error(double fraction, bool contact_mass, bool rk4 = false) {
  const Shape cube = cube_shape(0.009, 0.0005);
  const ShapeLibrary lib = library({cube});
  const Quat q(Eigen::AngleAxisd(0.35, Vec3::UnitX()) * Eigen::AngleAxisd(0.25, Vec3::UnitY()));
  double lowest = 1e9;
  for (const Vec3& p : cube.vertices) lowest = std::min(lowest, (q * p).z());
  Vec3 r = Vec3::Zero();
  for (const Vec3& p : cube.vertices)
    if ((q * p).z() < lowest + 1e-12) r = q * p;
  Scene scene = base_scene(law(kKn, kEn), true);
  scene.forces.contact.config_driver.damping_contact_mass = contact_mass;
  const double m = 2700.0 * cube.volume, inertia = m * cube.inertia_per_mass.x();
  const double m_star = vertex_mass(m, inertia, r);  // kg
  const double alpha = prepare_law(scene.forces.contact.config).alpha_n;
  double e_star = contact_mass ? kEn : ClampedImpact{alpha * std::sqrt(m / m_star), 1.0, 1.0, 1.0}.restitution();
  static std::optional<double> rk4_rebound[2];  // -, once per dashpot mass: 30,000 RK4 steps, not the engine's run time
  if (rk4 && !rk4_rebound[contact_mass]) {
    const double m_dashpot = contact_mass ? m_star : m;  // kg, at the touch
    const CornerLanding landing{m, inertia, kKn, 2.0 * alpha * std::sqrt(kKn * m_dashpot), {r}, contact_mass ? alpha : 0.0};
    const double t_c = ClampedImpact{alpha * std::sqrt(m_dashpot / m_star), std::sqrt(kKn / m_star), 0.01, m_star}.release_time();
    rk4_rebound[contact_mass] = landing.rebound(0.01, 1.5 * t_c, t_c / 20000.0);  // s: halving the step moves it by < 1e-10
  }
  if (rk4) e_star = *rk4_rebound[contact_mass];
  const std::vector<BodySpec> specs = {body("cube", {0, 0, -lowest + cube.radius + 1e-8}, {0, 0, -0.01}, q)};
  scene.simulation.dt = fraction * critical_step(scene, lib, specs);
  Simulation sim(scene, lib, specs);
  const MeasuredImpact out = run_impact(
      sim, 0.01, [&] { return 0.0; }, [&] { return sim.drivers[0].force.z(); }, [&] { return sim.bodies.velocity[0].z(); });
  return std::abs((out.velocity + out.angular_velocity.cross(r)).z() / 0.01 / e_star - 1.0);
}

// Free asymmetric top (test_free_top.cpp) over 3 flips: error of the flip period. Its step is
// a fraction of 2/w (w = 10 rad/s), the critical step of an oscillator of frequency w.
inline double free_top(double fraction) {
  const Shape box = box_shape({0.004, 0.008, 0.012}, 0.0005);
  Scene scene = base_scene(law(kKn, kEn), false);
  scene.simulation.dt = fraction * 2.0 / 10.0;
  int axes[3] = {0, 1, 2};
  std::sort(axes, axes + 3, [&](int a, int b) { return box.inertia_per_mass[a] < box.inertia_per_mass[b]; });
  BodySpec spec = body("box", Vec3::Zero());
  spec.angular_velocity = 10.0 * Vec3::Unit(axes[1]) + 0.5 * Vec3::Unit(axes[0]);
  Simulation sim(scene, library({box}), {spec});
  const Vec3 i = sim.bodies.inertia[0], l = sim.bodies.angular_momentum[0];
  const double e = 0.5 * l.cwiseProduct(l).cwiseQuotient(i).sum();
  const double period = flip_period(Vec3(i[axes[0]], i[axes[1]], i[axes[2]]), e, l.squaredNorm());
  std::vector<double> flips;
  double w_prev = l[axes[1]];
  const auto steps = std::llround(3.2 * period / sim.dt());
  for (long long n = 0; n < steps; ++n) {
    sim.step();
    const double w = sim.bodies.angular_momentum[0][axes[1]];
    if ((w < 0.0) != (w_prev < 0.0)) flips.push_back(sim.time() - sim.dt() * w / (w - w_prev));
    w_prev = w;
  }
  if (flips.size() < 2) return 1.0;
  return std::abs(2.0 * (flips.back() - flips.front()) / double(flips.size() - 1) / period - 1.0);
}


}  // namespace polydem::validation::accuracy
