// Oblique impact of a sphere on a wall in the sliding regime, translation and rotation
// integrated with velocity Verlet. While the contact slides the whole time, the tangential
// impulse is mu times the normal impulse J_n = m (1 + e) v_n (Coulomb), so (Walton 1993;
// Schaefer, Dippel & Wolf 1996, J. Phys. I France 6:5) with I = 2/5 m R^2 and lever R:
//   v_t' = v_t - mu (1 + e) v_n,   R w' = R^2 mu J_n / I = 5/2 mu (1 + e) v_n,
// valid while the contact point keeps slipping: v_t > 7/2 mu (1 + e) v_n, and from the first
// step on: the cap jumps to mu nu v_n at touching (dashpot), so the spring must load as fast,
// kt v_t tau >= mu nu v_n over the time tau it is on in that step (from the touch: law.hpp);
// otherwise a short stick (finite kt, not a law error) costs impulse.
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/law.hpp"

using namespace polydem;

namespace {

constexpr double kRadius = 0.01;                         // m
constexpr double kMass = 0.01;                           // kg
constexpr double kInertia = 0.4 * kMass * kRadius * kRadius;  // kg m^2, solid sphere

struct Outgoing {
  Vec3 velocity;  // m/s
  Vec3 spin;      // rad/s
};

// Wall z = 0 (normal +z), sphere approaching with v = (vt, 0, -vn), no spin. Touching a tenth into a step.
Outgoing oblique_impact(const LawParams& law, double vt, double vn, double dt) {
  Vec3 x(0, 0, kRadius + 10.1 * vn * dt), v(vt, 0, -vn), w = Vec3::Zero(), a = Vec3::Zero(),
      alpha = Vec3::Zero();
  ContactHistory h;
  bool touched = false;
  for (int step = 0; step < 100000; ++step) {
    v += 0.5 * dt * a;
    w += 0.5 * dt * alpha;
    x += dt * v;
    const double dn = x.z() - kRadius;
    if (dn < 0.0) touched = true;
    if (touched && dn > 0.0) break;
    const Vec3 arm = -kRadius * Vec3::UnitZ();  // m, centre to contact point
    // As the engine: springs see the half-step velocities, the dashpot the predicted end-of-step ones.
    const Vec3 v_end = v + 0.5 * dt * a, w_end = w + 0.5 * dt * alpha;
    const ContactKinematics k{Vec3::UnitZ(), dn, v + w.cross(arm), v_end + w_end.cross(arm), w, kMass, kRadius, 1.0};
    const ContactForce f = contact_force(law, k, h, dt);
    a = f.force / kMass;
    alpha = (arm.cross(f.force) + f.moment) / kInertia;
    v += 0.5 * dt * a;
    w += 0.5 * dt * alpha;
  }
  return {v, w};
}

}  // namespace

TEST_CASE("oblique sliding impact on a wall: v_t' = v_t - mu (1+e) v_n, R w' = 5/2 mu (1+e) v_n", "[law]") {
  for (double en : {0.3, 0.5, 0.9, 1.0}) {
    ContactParams p;
    p.kn = 1e4;
    p.kt = 1e4;
    p.mu = 0.2;
    p.en = en;
    const LawParams law = prepare_law(p);
    const double vn = 0.5, vt = 5.0;
    const double dt = 2 * kPi * std::sqrt(kMass / law.kn) / 200.0;  // s, T/200
    const double nu = 2 * law.alpha_n * std::sqrt(law.kn * kMass);  // N s/m
    REQUIRE(vt > 3.5 * p.mu * (1 + en) * vn);  // sliding all along
    REQUIRE(p.kt * vt * 0.9 * dt >= p.mu * nu * vn);  // sliding from the first step (on for 0.9 dt)
    const Outgoing out = oblique_impact(law, vt, vn, dt);
    INFO("en = " << en);
    CHECK(out.velocity.z() == Approx(en * vn).epsilon(0.005));
    CHECK(out.velocity.x() == Approx(vt - p.mu * (1 + en) * vn).epsilon(0.002));
    CHECK(kRadius * out.spin.y() == Approx(2.5 * p.mu * (1 + en) * vn).epsilon(0.005));
    CHECK(std::abs(out.velocity.y()) < 1e-12);
  }
}
