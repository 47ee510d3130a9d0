#pragma once
// The cube-flat rows of the accuracy sweep (accuracy_sweep.cpp, tools/bench/accuracy) and of
// test_accuracy_cube_flat.cpp: a rounded cube (9 mm, rounding 0.5 mm) landing on its face on a
// frictionless wall, its four vertex-face contacts one patch (SPEC: the face rebounds with en).
//  - flat: no torque, so the answer is the 1-D restitution at the contact: vz' = en v0;
//  - tilted 1e-3 rad about x at 0.1 m/s: one edge touches ~9 um before the other (the overlap
//    peaks near 13 um: both take part); its answer is the same landing at 0.002 x critical,
//    the step error alone (the patch's physics is test_cube_landing's and the flat row's).
// Each at dt = fraction x critical (`polydem check`), at `phases` places of the touch in its
// step (gap = phase x v0 dt + 1 nm), the worst returned.
#include <algorithm>
#include <cmath>
#include <optional>

#include "accuracy_cases.hpp"

namespace polydem::validation::accuracy {

constexpr double kCubeSide = 0.009, kCubeRounding = 0.0005;  // m
constexpr double kTilt = 1e-3;                               // rad, the tilted landing's
constexpr double kFlatSpeed = 0.01, kTiltSpeed = 0.1;        // m/s

struct CubeRebound {
  double vz = 0.0, spin = 0.0;  // m/s, rad/s (about x) after the impact
};

// One landing at dt = fraction x critical, touching at `phase` of its step; `contact_mass`:
// the wall's law takes damping_mass: contact.
inline CubeRebound cube_face_landing(double fraction, double tilt, double speed, double phase, bool contact_mass = false) {
  const Shape cube = cube_shape(kCubeSide, kCubeRounding);
  const ShapeLibrary lib = library({cube});
  const Quat q(Eigen::AngleAxisd(tilt, Vec3::UnitX()));
  double lowest = 1e9;
  for (const Vec3& p : cube.vertices) lowest = std::min(lowest, (q * p).z());
  Scene scene = base_scene(law(kKn, kEn), true);
  scene.forces.contact.config_driver.damping_contact_mass = contact_mass;
  std::vector<BodySpec> specs = {body("cube", {0, 0, -lowest + cube.radius + 1e-7}, {0, 0, -speed}, q)};
  scene.simulation.dt = fraction * critical_step(scene, lib, specs);
  specs[0].position.z() = -lowest + cube.radius + 1e-9 + phase * speed * *scene.simulation.dt;
  Simulation sim(scene, lib, specs);
  const MeasuredImpact out = run_impact(
      sim, speed, [&] { return 0.0; }, [&] { return sim.drivers[0].force.z(); }, [&] { return sim.bodies.velocity[0].z(); });
  if (out.restitution < 0.0) return {1e9, 1e9};  // never let go: every error check fails
  return {out.velocity.z(), out.angular_velocity.x()};
}

// Flat: relative error of vz' / v0 against en, worst of `phases` touch places.
inline double cube_flat_error(double fraction, int phases = 8, bool contact_mass = false) {
  double worst = 0.0;
  for (int k = 0; k < phases; ++k) {
    const CubeRebound r = cube_face_landing(fraction, 0.0, kFlatSpeed, double(k) / phases, contact_mass);
    worst = std::max(worst, std::abs(r.vz / kFlatSpeed / kEn - 1.0));
  }
  return worst;
}

// Tilted: max(|vz' - ref|, half side x |w' - ref|) / v0 against the landing at 0.002 x
// critical under the same dashpot mass (computed once per mass), worst of `phases` touch places.
inline double cube_tilted_error(double fraction, int phases = 8, bool contact_mass = false) {
  static std::optional<CubeRebound> refs[2];  // once per dashpot mass, when first asked
  if (!refs[contact_mass]) refs[contact_mass] = cube_face_landing(0.002, kTilt, kTiltSpeed, 0.0, contact_mass);
  const CubeRebound ref = *refs[contact_mass];
  double worst = 0.0;
  for (int k = 0; k < phases; ++k) {
    const CubeRebound r = cube_face_landing(fraction, kTilt, kTiltSpeed, double(k) / phases, contact_mass);
    worst = std::max(worst, std::max(std::abs(r.vz - ref.vz), 0.5 * kCubeSide * std::abs(r.spin - ref.spin)) / kTiltSpeed);
  }
  return worst;
}

// Almost flat: tilted kJoinTilt, its far edge kJoinGap above the near one at the touch, a
// fraction of a step at 0.1 x critical (v0 dt is 1.6 um there), so the far edge's vertices join the
// patch mid-contact, in the step after the near edge's or the same one (issue 16's tilted pair:
// an O(dt) onset push counted for the joining vertices until acc20). Against the rigid cube
// integrated with the patch's law by RK4 (corner_reference.hpp; t_c/20000 and t_c/40000 agree to
// 1e-10 of v0), max(|vz' - ref|, half side x |w' - ref|) / v0, worst of `phases` touch places.
constexpr double kJoinGap = 4e-7;                        // m, far edge above the near one
inline double cube_join_error(double fraction, int phases = 8) {
  static const CubeRebound ref = [] {
    const Shape cube = cube_shape(kCubeSide, kCubeRounding);
    const double core = cube.vertices[0].cwiseAbs().maxCoeff() * 2.0;  // m, the core's side
    const Quat q(Eigen::AngleAxisd(kJoinGap / core, Vec3::UnitX()));
    std::vector<Vec3> vertices;
    for (const Vec3& p : cube.vertices) vertices.push_back(q * p);
    Scene scene = base_scene(law(kKn, kEn), true);
    const double m = 2700.0 * cube.volume, alpha = prepare_law(scene.forces.contact.config).alpha_n;
    const CornerLanding landing{m, m * cube.inertia_per_mass.x(), kKn, 2.0 * alpha * std::sqrt(kKn * m), vertices};
    const double t_c = ClampedImpact{alpha, std::sqrt(kKn / m), kTiltSpeed, m}.release_time();
    const CornerLanding::State s = landing.land(kTiltSpeed, 1.5 * t_c, t_c / 20000.0);
    return CubeRebound{s.vz, s.w.x()};
  }();
  const Shape cube = cube_shape(kCubeSide, kCubeRounding);
  const double tilt = kJoinGap / (cube.vertices[0].cwiseAbs().maxCoeff() * 2.0);  // rad
  double worst = 0.0;
  for (int k = 0; k < phases; ++k) {
    const CubeRebound r = cube_face_landing(fraction, tilt, kTiltSpeed, double(k) / phases);
    worst = std::max(worst, std::max(std::abs(r.vz - ref.vz), 0.5 * kCubeSide * std::abs(r.spin - ref.spin)) / kTiltSpeed);
  }
  return worst;
}

}  // namespace polydem::validation::accuracy
