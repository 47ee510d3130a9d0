// Tangential spring of the contact law: sticking, sliding, rotation into a new tangent plane,
// release out of reach. Constant overlap, no damping: fn = kn (-dn) exactly.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/law.hpp"

using namespace polydem;

namespace {

constexpr double kDt = 1e-5;       // s
constexpr double kOverlap = 1e-4;  // m

LawParams friction_law() {
  ContactParams p;
  p.kn = 1e4;  // fn = 1 N at the overlap above
  p.kt = 2e3;
  p.mu = 0.5;
  p.en = 1.0;
  return prepare_law(p);
}

ContactKinematics sliding_on_z(const Vec3& v_rel) {
  return {Vec3::UnitZ(), -kOverlap, v_rel, v_rel, Vec3::Zero(), 0.01, 0.01, 1.0};
}

}  // namespace

TEST_CASE("tangential spring: sticking gives -kt times the displacement, sliding gives mu fn against the slip", "[law]") {
  const LawParams law = friction_law();
  const double fn = law.kn * kOverlap;
  const Vec3 vt(0.3, -0.4, 0.0);  // m/s, |vt| = 0.5
  ContactHistory h;
  ContactForce f{};
  const int stick_steps = 40;  // displacement 2e-4 m: kt * 2e-4 = 0.4 N < mu fn = 0.5 N
  double dissipated = 0.0;
  for (int s = 0; s < stick_steps; ++s) {
    f = contact_force(law, sliding_on_z(vt), h, kDt);
    dissipated += f.dissipated;
  }
  const Vec3 displacement = vt * kDt * stick_steps;
  CHECK((f.force - (fn * Vec3::UnitZ() - law.kt * displacement)).norm() < 1e-12);
  CHECK(dissipated == 0.0);
  // elastic = normal spring + tangential spring energy kt s^2/2
  CHECK(f.elastic == Approx(0.5 * law.kn * kOverlap * kOverlap + 0.5 * law.kt * displacement.squaredNorm()));

  const int slide_steps = 200;  // a further 1e-3 m: far past the Coulomb limit
  for (int s = 0; s < slide_steps; ++s) {
    f = contact_force(law, sliding_on_z(vt), h, kDt);
    dissipated += f.dissipated;
  }
  const Vec3 ft = f.force - f.fn * Vec3::UnitZ();
  CHECK(ft.norm() == Approx(law.mu * fn).epsilon(1e-12));
  CHECK(ft.normalized().dot(-vt.normalized()) == Approx(1.0).epsilon(1e-12));
  // Slip work: mu fn times the slip distance (total minus the elastic stretch mu fn/kt).
  const double slip = vt.norm() * kDt * (stick_steps + slide_steps) - law.mu * fn / law.kt;
  CHECK(dissipated == Approx(law.mu * fn * slip).epsilon(1e-3));
}

TEST_CASE("tangential spring: rotating into a tilted tangent plane keeps its length", "[law]") {
  const LawParams law = friction_law();
  ContactHistory h;
  h.ft = Vec3(0.2, 0.3, 0.0);  // N, in the plane of n = z
  const double length = h.ft.norm();
  const Vec3 tilted = Eigen::AngleAxisd(0.5, Vec3(1, 1, 0).normalized()) * Vec3::UnitZ();
  const ContactKinematics k{tilted, -kOverlap, Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), 0.01, 0.01, 1.0};
  const ContactForce f = contact_force(law, k, h, kDt);
  CHECK(h.ft.norm() == Approx(length).epsilon(1e-14));
  CHECK(std::abs(h.ft.dot(tilted)) < 1e-14);
  CHECK(f.dissipated == 0.0);
  CHECK((f.force - f.fn * tilted - h.ft).norm() < 1e-15);
}

TEST_CASE("out of reach: no force, springs released and their energy counted as dissipated", "[law]") {
  const LawParams law = friction_law();
  ContactHistory h;
  h.ft = Vec3(0.1, 0.0, 0.0);
  const ContactKinematics apart{Vec3::UnitZ(), 1e-6, Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3::Zero(), 0.01, 0.01, 1.0};
  const ContactForce f = contact_force(law, apart, h, kDt);
  CHECK(f.force.norm() == 0.0);
  CHECK(f.fn == 0.0);
  CHECK(h.ft.norm() == 0.0);
  CHECK(f.dissipated == Approx(0.01 / (2 * law.kt)));
}
