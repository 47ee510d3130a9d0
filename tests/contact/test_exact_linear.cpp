// The linear law's exact step (contact/law/exact_linear.hpp) against the closed form of the
// damped oscillator: a lone contact fed as the engine feeds the kernel (velocity Verlet, the
// half-step velocity and the predicted end velocity) samples the exact solution.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "contact/law.hpp"

using namespace polydem;

namespace {

constexpr double kMass = 0.01;     // kg
constexpr double kRadius = 0.005;  // m

LawParams damped_law(double en) {
  ContactParams p;
  p.kn = 1e4;
  p.en = en;
  LawParams law = prepare_law(p);
  law.exact_step = true;  // what simulation: accuracy turns on
  return law;
}

// A body pressed on a wall by `press` (N) from overlap x0 at rate v0 (m/s, > 0 closing), stepped
// n times at dt: the overlaps after each step.
// With `cache`, the kernel keeps k' and c' there as a pair list does (PairList::linear_steps).
std::vector<double> pressed_contact(const LawParams& law, double press, double x0, double v0, double dt, int n,
                                    LinearStep* cache = nullptr) {
  std::vector<double> out;
  double x = x0, v = v0, a = 0.0;
  ContactHistory h;
  for (int step = 0; step < n; ++step) {
    v += 0.5 * dt * a;
    x += dt * v;
    ContactKinematics k{Vec3::UnitZ(), -x, Vec3(0, 0, -v), Vec3(0, 0, -v - 0.5 * dt * a), Vec3::Zero(),
                        kMass, kRadius, 1.0};
    k.linear_step = cache;
    const ContactForce f = contact_force(law, k, h, dt);
    a = (press - f.fn) / kMass;
    v += 0.5 * dt * a;
    out.push_back(x);
  }
  return out;
}

}  // namespace

TEST_CASE("exact step: k' and c' tend to kn and the dashpot as dt -> 0", "[law][exact_step]") {
  const LawParams law = damped_law(0.5);
  const double c = 2.0 * law.alpha_n * std::sqrt(law.kn * kMass);  // N s/m
  const LinearStep small = linear_step(law.kn, law.alpha_n, kMass, 1e-7);
  CHECK(small.k == Approx(law.kn).epsilon(1e-4));
  CHECK(small.c == Approx(c).epsilon(1e-4));
}

TEST_CASE("exact step: a pressed damped contact samples the closed-form oscillation and rests at kn x = load",
          "[law][exact_step]") {
  for (double en : {0.1, 0.5, 0.9})
    for (double fraction : {0.1, 0.3}) {
      const LawParams law = damped_law(en);
      const double dt = fraction * critical_time_step(law.kn, kMass, law.alpha_n);  // s
      const double press = 1.0, x_eq = press / law.kn;  // N, m
      // Kicked by 10% of x_eq: the force stays positive, no release. The first two steps carry
      // the start (no last force yet); from there y = x - x_eq obeys the closed-form recurrence.
      const std::vector<double> x = pressed_contact(law, press, 1.1 * x_eq, 0.0, dt, 4000);
      const double w = std::sqrt(law.kn / kMass), z = law.alpha_n;  // rad/s, -
      const double e = std::exp(-z * w * dt), cs = std::cos(w * std::sqrt(1.0 - z * z) * dt);
      double worst = 0.0;  // m
      for (std::size_t n = 3; n + 1 < 60; ++n)
        worst = std::max(worst, std::abs((x[n + 1] - x_eq) - (2.0 * e * cs * (x[n] - x_eq) - e * e * (x[n - 1] - x_eq))));
      INFO("en = " << en << ", dt = " << fraction << " x critical");
      CHECK(worst < 1e-9 * x_eq);
      CHECK(x.back() == Approx(x_eq).epsilon(1e-9));  // at rest the spring is kn, not k'
    }
}

TEST_CASE("exact step: a damped impact on a wall rebounds at en up to 0.3 x critical", "[law][exact_step]") {
  for (double en : {0.1, 0.5, 0.9})
    for (double fraction : {0.1, 0.2, 0.3}) {
      const LawParams law = damped_law(en);
      const double dt = fraction * critical_time_step(law.kn, kMass, law.alpha_n);  // s
      const std::vector<double> x = pressed_contact(law, 0.0, -1e-7, 0.5, dt, 400);
      const double rebound = (x[x.size() - 2] - x.back()) / dt;  // m/s, free flight after the release
      INFO("en = " << en << ", dt = " << fraction << " x critical");
      CHECK(rebound / 0.5 == Approx(en).epsilon(3e-3));
    }
}

TEST_CASE("exact step: k' and c' kept per pair give the same bits as computed per step", "[law][exact_step]") {
  const LawParams law = damped_law(0.5);
  const double dt = 0.1 * critical_time_step(law.kn, kMass, law.alpha_n);  // s
  LinearStep cache;  // k = 0: not set, as PairList::resize_results leaves it
  const std::vector<double> fresh = pressed_contact(law, 0.0, -1e-7, 0.5, dt, 400);
  const std::vector<double> cached = pressed_contact(law, 0.0, -1e-7, 0.5, dt, 400, &cache);
  CHECK(cached == fresh);
  const LinearStep step = linear_step(law.kn, law.alpha_n, kMass, dt);
  CHECK(cache.k == step.k);
  CHECK(cache.c == step.c);
  CHECK(cache.rest == 1.0 - step.k / law.kn);
}
