#include "contact/hertz_restitution.hpp"

#include <cmath>
#include <map>
#include <mutex>
#include <stdexcept>

#include "contact/hertz_damping_table.hpp"

namespace polydem {

namespace {

struct State {
  double s, u;  // scaled overlap and its rate
};

// Scaled clamped force, before the clamp.
double scaled_force(const State& y, double c) { return std::pow(y.s, 1.5) + c * std::pow(y.s, 0.25) * y.u; }

State rate(const State& y, double c) { return {y.u, -scaled_force({std::max(y.s, 0.0), y.u}, c)}; }

State rk4(const State& y, double h, double c) {
  auto at = [&](const State& k, double f) { return State{y.s + f * k.s, y.u + f * k.u}; };
  const State k1 = rate(y, c), k2 = rate(at(k1, 0.5 * h), c), k3 = rate(at(k2, 0.5 * h), c), k4 = rate(at(k3, h), c);
  return {y.s + h / 6.0 * (k1.s + 2.0 * k2.s + 2.0 * k3.s + k4.s), y.u + h / 6.0 * (k1.u + 2.0 * k2.u + 2.0 * k3.u + k4.u)};
}

}  // namespace

double hertz_restitution_for_damping_ratio(double alpha) {
  if (!(alpha >= 0.0)) throw std::invalid_argument("hertz_restitution_for_damping_ratio: alpha < 0");
  const double c = 2.0 * alpha * std::sqrt(1.5);
  State y{0.0, 1.0};
  double tau = 0.0;
  // Fine steps where s^0.25 is steep (the start), then 1e-4: the contact lasts ~3.2 in tau.
  while (tau < 100.0) {
    const double h = tau < 0.01 ? 1e-6 : 1e-4;
    const State next = rk4(y, h, c);
    tau += h;
    // Released within this step: the rate where the force (or, undamped, the overlap) crosses 0.
    const double g0 = scaled_force(y, c), g1 = next.s > 0.0 ? scaled_force(next, c) : 0.0;
    if (next.s <= 0.0 || g1 <= 0.0) {
      const double f = next.s <= 0.0 ? y.s / (y.s - next.s) : g0 / (g0 - g1);  // fraction of the step
      return -(y.u + f * (next.u - y.u));
    }
    y = next;
  }
  return 0.0;  // never released: fully damped
}

double solve_hertz_damping_ratio(double en) {
  double lo = 0.0, hi = 0.5;
  while (hertz_restitution_for_damping_ratio(hi) > en) {
    lo = hi;
    hi *= 2.0;
  }
  for (int iteration = 0; iteration < 60 && hi - lo > 1e-10 * hi; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (hertz_restitution_for_damping_ratio(mid) > en ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double hertz_damping_ratio_for_restitution(double en) {
  if (!(en > 0.0 && en <= 1.0)) throw std::invalid_argument("hertz_damping_ratio_for_restitution: en not in (0, 1]");
  if (en == 1.0) return 0.0;
  const long hundredths = std::lround(en * 100.0);
  if (hundredths >= 1 && en == static_cast<double>(hundredths) / 100.0) return kHertzDampingRatio[hundredths - 1];
  // Other en: solved once per en (~40 impacts integrated, ~1 s), since every law built with
  // that en (each pair kind, each test's scene) asks again.
  static std::mutex guard;
  static std::map<double, double> solved;
  const std::lock_guard<std::mutex> lock(guard);
  const auto known = solved.find(en);
  if (known != solved.end()) return known->second;
  return solved[en] = solve_hertz_damping_ratio(en);
}

}  // namespace polydem
