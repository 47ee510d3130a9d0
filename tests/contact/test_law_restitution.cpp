// Restitution of the clamped linear spring-dashpot law (contact/restitution.hpp).
//
// Derivation. Overlap x >= 0, x(0) = 0, x'(0) = v0 > 0, w0 = sqrt(kn/m), a the damping ratio:
//   m x'' = -fn, fn = max(kn x + nu x', 0), nu = 2 a m w0.
// While fn > 0 (a < 1, wd = w0 sqrt(1 - a^2)):
//   x = v0/wd e^{-a w0 t} sin(wd t),  x' = v0 e^{-a w0 t} (cos(wd t) - a w0/wd sin(wd t)).
// fn/m = w0^2 x + 2 a w0 x' = 0  <=>  tan(wd t) = -2a sqrt(1-a^2)/(1-2a^2). With a = sin(th),
// that is tan(wd t) = -tan(2 th): wd t_c = pi - 2 asin(a) = 2 acos(a). There
// cos(wd t_c) - tan(th) sin(wd t_c) = -cos(2th) - tan(th) sin(2th) = -1, so x'(t_c) = -v0 e^{-a w0 t_c}
// and after t_c fn stays 0 (d/dt(kn x + nu x') = kn x' < 0 at constant velocity): the body leaves with
//   en = exp(-a w0 t_c),  w0 t_c = 2 acos(a)/sqrt(1 - a^2).
// For a > 1 replace sin -> sinh, wd -> s = w0 sqrt(a^2-1), a = cosh(u): s t_c = 2u = 2 acosh(a),
// x'(t_c) = -v0 e^{-a w0 t_c} again; at a = 1 both limits give w0 t_c = 2 (en = e^-2).
// The textbook en = exp(-a pi/sqrt(1-a^2)) assumes release at x = 0 (w0 t = pi/sqrt(1-a^2)).
#include <catch2/catch.hpp>

#include <cmath>

#include "contact/law.hpp"
#include "contact/restitution.hpp"
#include "polydem/error.hpp"

using namespace polydem;

namespace {

struct Release {
  double restitution;      // -, |x'| at release over v0
  double scaled_duration;  // -, w0 t_c
};

// Brute-force reference: RK4 of the clamped ODE (w0 = 1, v0 = 1) with a tiny step, release found
// by linear interpolation of fn = x + 2 a x' between the last two steps.
Release integrate_clamped(double a) {
  const double h = 1e-5;
  double x = 0.0, v = 1.0, t = 0.0;
  auto accel = [a](double xx, double vv) { return -std::max(xx + 2.0 * a * vv, 0.0); };
  double f_prev = 2.0 * a;
  while (true) {
    const double k1x = v, k1v = accel(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = accel(x + 0.5 * h * k1x, v + 0.5 * h * k1v);
    const double k3x = v + 0.5 * h * k2v, k3v = accel(x + 0.5 * h * k2x, v + 0.5 * h * k2v);
    const double k4x = v + h * k3v, k4v = accel(x + h * k3x, v + h * k3v);
    x += h / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x);
    v += h / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v);
    t += h;
    const double f = x + 2.0 * a * v;
    if (f <= 0.0 && t > h) {
      const double s = f_prev / (f_prev - f);  // fraction of the step where fn crossed 0
      return {-v, t - h + s * h};
    }
    f_prev = f;
  }
}

double plain_damping_ratio(double en) {
  const double l = std::log(en);
  return -l / std::sqrt(l * l + kPi * kPi);
}

}  // namespace

TEST_CASE("restitution closed form matches a brute-force integration of the clamped law", "[law]") {
  for (double a : {0.0, 0.1, 0.3, 0.6, 0.9, 1.0, 1.5, 4.0}) {
    const Release r = integrate_clamped(a);
    INFO("alpha = " << a);
    CHECK(restitution_for_damping_ratio(a) == Approx(r.restitution).epsilon(1e-6));
    CHECK(scaled_contact_duration(a) == Approx(r.scaled_duration).epsilon(1e-4));
  }
}

TEST_CASE("damping_ratio_for_restitution inverts the closed form", "[law]") {
  for (double en : {1e-4, 0.05, 0.1, 0.1353352832366127, 0.3, 0.5, 0.7, 0.9, 0.999, 1.0}) {
    const double a = damping_ratio_for_restitution(en);
    INFO("en = " << en << ", alpha = " << a);
    CHECK(restitution_for_damping_ratio(a) == Approx(en).epsilon(1e-12));
  }
  CHECK(damping_ratio_for_restitution(1.0) == 0.0);
  // en = e^-2 is exactly critical damping (w0 t_c = 2).
  CHECK(damping_ratio_for_restitution(std::exp(-2.0)) == Approx(1.0).epsilon(1e-9));
}

TEST_CASE("the plain alpha formula gives ~0.55 for en = 0.5 under the clamp, ours gives 0.5", "[law]") {
  const double plain = plain_damping_ratio(0.5);
  CHECK(plain == Approx(0.2155).epsilon(1e-3));
  CHECK(restitution_for_damping_ratio(plain) == Approx(0.55).margin(0.01));
  CHECK(restitution_for_damping_ratio(damping_ratio_for_restitution(0.5)) == Approx(0.5).epsilon(1e-12));
  // Without the clamp (release at x = 0) the plain formula would be exact: exp(-a pi/sqrt(1-a^2)).
  CHECK(std::exp(-plain * kPi / std::sqrt(1.0 - plain * plain)) == Approx(0.5).epsilon(1e-12));
}

TEST_CASE("prepare_law solves alpha_n from en and takes damp_rate as is", "[law]") {
  ContactParams p;
  p.kn = 1e5;
  p.kt = 1e5;
  p.mu = 0.5;
  p.en = 0.5;
  const LawParams law = prepare_law(p);
  CHECK(restitution_for_damping_ratio(law.alpha_n) == Approx(0.5).epsilon(1e-12));
  CHECK_FALSE(law.cohesion);
  CHECK_FALSE(law.rolling);

  ContactParams q = p;
  q.en = -1.0;
  q.damp_rate = 0.9;
  q.kr = 0.1;  // exaDEM-style kr without mur: rolling stays off
  CHECK(prepare_law(q).alpha_n == 0.9);
  CHECK_FALSE(prepare_law(q).rolling);
  q.mur = 0.1;
  CHECK(prepare_law(q).rolling);

  // Bad values are refused by the parser, with file, line and key (tests/io/scene_errors_test.cpp).
}
