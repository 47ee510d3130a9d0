// Binary normal impacts integrated with the kernel and velocity Verlet, fed as the engine
// feeds it (the half-step velocity for the springs, the bodies' predicted end-of-step velocity
// v(n+1/2) + a(n) dt/2 for the dashpot), against the closed forms of the clamped law.
//
// Second order (second_order.hpp): the kicks apply F(n+1) over the cell [n+1/2, n+3/2]. A force
// that switches on at t_c = t(n+1) - tau, as g + s (t - t_c) (g the dashpot's jump, s the
// spring's slope), gets from the cells of n and n+1 the impulse dt F(n+1) = dt (g + s tau),
// against int g + s (t - t_c) over [t_c, t(n) + 3dt/2], which is larger by
// g (tau - dt/2) + s (tau - dt/2)^2/2 (either side of the middle of the step); the step of the
// onset adds it. A force falling to zero at theta into a step, s (t_c - t), is missed by
// s (theta - dt/2)^2/2 likewise. What is left is the midpoint rule's O(dt^2).
//
// Closed forms (overlap x, x(0) = 0, x'(0) = v0, w0 = sqrt(kn/m_eff), a = alpha_n; the solution
// x(t) is derived in test_law_restitution.cpp):
//  - duration, until the clamp releases (kn x + nu x' = 0): w0 t_c = 2 acos(a)/sqrt(1-a^2) (a < 1),
//    2 acosh(a)/sqrt(a^2-1) (a > 1), 2 (a = 1);
//  - maximum overlap at x' = 0: tan(wd t) = sqrt(1-a^2)/a, wd t_m = acos(a), so
//    x_max = v0/wd e^{-a w0 t_m} sin(acos a) = v0/w0 exp(-a acos(a)/sqrt(1-a^2)); for a > 1,
//    s t_m = acosh(a) and x_max = v0/w0 exp(-a acosh(a)/sqrt(a^2-1)); a = 1 gives v0/w0 e^-1.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "contact/law.hpp"
#include "contact/restitution.hpp"

using namespace polydem;

namespace {

constexpr double kRadius = 0.01;  // m
constexpr double kMass = 0.01;    // kg
constexpr double kV0 = 0.5;       // m/s, approach speed

struct Impact {
  double restitution;  // -, separation over approach speed
  double duration;     // s, from touching until the clamp releases
  double max_overlap;  // m
};

double release_time(double a, double w0) {
  if (a < 1.0) return 2.0 * std::acos(a) / (w0 * std::sqrt(1.0 - a * a));
  if (a > 1.0) return 2.0 * std::acosh(a) / (w0 * std::sqrt(a * a - 1.0));
  return 2.0 / w0;
}

double max_overlap(double a, double w0, double v0) {
  if (a < 1.0) return v0 / w0 * std::exp(-a * std::acos(a) / std::sqrt(1.0 - a * a));
  if (a > 1.0) return v0 / w0 * std::exp(-a * std::acosh(a) / std::sqrt(a * a - 1.0));
  return v0 / w0 * std::exp(-1.0);
}

LawParams normal_law(double en) {
  ContactParams p;
  p.kn = 1e4;
  p.en = en;
  return prepare_law(p);
}

// Sphere i above body j along z; mass_j = infinity makes j a fixed wall (its centre at -R).
// Touching happens at `phase` (in [0, 1)) of a step: the dashpot force jumps to nu v0 there;
// without the onset impulse the error would be +-a w0 dt/2 (first order).
Impact integrate_impact(const LawParams& law, double mass_j, double dt, double phase) {
  const bool wall = std::isinf(mass_j);
  const double m_eff = wall ? kMass : kMass * mass_j / (kMass + mass_j);
  const double nu = 2.0 * law.alpha_n * std::sqrt(law.kn * m_eff);
  double zi = kRadius + (10.0 + phase) * dt * kV0 * (wall ? 1.0 : 2.0), zj = -kRadius;  // m
  double vi = -kV0, vj = wall ? 0.0 : kV0, ai = 0.0, aj = 0.0;                              // m/s, m/s^2
  ContactHistory h;
  Impact out{0.0, 0.0, 0.0};
  double dn_prev = zi - zj - 2 * kRadius, raw_prev = 0.0, t = 0.0, t_touch = -1.0;
  bool released = false;
  for (int step = 0; step < 1000000; ++step) {
    vi += 0.5 * ai * dt;
    vj += 0.5 * aj * dt;
    zi += vi * dt;
    zj += vj * dt;
    t += dt;
    const double dn = zi - zj - 2 * kRadius;
    const Vec3 v_half(0, 0, vi - vj), v_end(0, 0, vi - vj + 0.5 * (ai - aj) * dt);  // as the engine passes them
    const ContactKinematics k{Vec3::UnitZ(), dn, v_half, v_end, Vec3::Zero(), m_eff, kRadius, 1.0};
    const ContactForce f = contact_force(law, k, h, dt);
    ai = f.force.z() / kMass;
    aj = wall ? 0.0 : -f.force.z() / mass_j;
    vi += 0.5 * ai * dt;
    vj += 0.5 * aj * dt;
    if (t_touch < 0.0 && dn < 0.0) t_touch = t - dt * dn / (dn - dn_prev);  // interpolated crossing
    out.max_overlap = std::max(out.max_overlap, -dn);
    const double raw = -law.kn * dn - nu * (vi - vj);  // N, unclamped normal force
    if (t_touch >= 0.0 && !released && raw <= 0.0) {
      out.duration = t - dt * raw / (raw - raw_prev) - t_touch;
      released = true;
    }
    if (released && dn > 0.0) break;
    dn_prev = dn;
    raw_prev = raw;
  }
  out.restitution = (vi - vj) / (wall ? kV0 : 2 * kV0);
  return out;
}

void check_impacts(double mass_j) {
  for (double en : {0.05, 0.1, 0.3, 0.5, 0.7, 0.9, 1.0}) {
    const LawParams law = normal_law(en);
    const double m_eff = std::isinf(mass_j) ? kMass : kMass * mass_j / (kMass + mass_j);
    const double w0 = std::sqrt(law.kn / m_eff);
    const double v0 = std::isinf(mass_j) ? kV0 : 2 * kV0;
    const double dt = 2 * kPi / w0 / 200.0;  // T/200
    const Impact r = integrate_impact(law, mass_j, dt, 0.5);
    INFO("en = " << en << ", alpha_n = " << law.alpha_n);
    CHECK(r.restitution == Approx(en).epsilon(0.005));
    CHECK(r.duration == Approx(release_time(law.alpha_n, w0)).epsilon(0.01));
    CHECK(r.max_overlap == Approx(max_overlap(law.alpha_n, w0, v0)).epsilon(0.005));
  }
}

}  // namespace

TEST_CASE("sphere-wall normal impact: restitution, duration and maximum overlap", "[law]") {
  check_impacts(std::numeric_limits<double>::infinity());
}

TEST_CASE("sphere-sphere normal impact (m_eff = m/2): restitution, duration and maximum overlap", "[law]") {
  check_impacts(kMass);
}

TEST_CASE("impact restitution: the touching-phase error is second order in dt", "[law]") {
  const LawParams law = normal_law(0.1);
  const double w0 = std::sqrt(law.kn / kMass);
  double worst[2] = {0.0, 0.0};
  for (int refine = 0; refine < 2; ++refine) {
    const double dt = 2 * kPi / w0 / (200.0 * (1 << refine));
    double mean = 0.0;
    const int phases = 16;
    for (int p = 0; p < phases; ++p) {
      const double wall = std::numeric_limits<double>::infinity();
      const double en = integrate_impact(law, wall, dt, (p + 0.5) / phases).restitution;
      mean += en / phases;
      worst[refine] = std::max(worst[refine], std::abs(en - 0.1));
    }
    INFO("dt = T/" << 200 * (1 << refine) << ", worst error " << worst[refine]);
    CHECK(mean == Approx(0.1).epsilon(0.005));
    CHECK(worst[refine] < 5e-5 / (1 << (2 * refine)));  // -, 2.4e-5 and 5.5e-6 measured
  }
  // Second order: halving dt quarters the worst-case error (observed order >= 1.8).
  CHECK(worst[0] / worst[1] >= std::pow(2.0, 1.8));
}
