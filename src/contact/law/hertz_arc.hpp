#pragma once
// The start of a Hertz impact with Tsuji's dashpot in scaled form (the onset step's arc,
// NormalHertz::onset_force): m x'' = -w K x^1.5 - nu x^1/4 x' from x = 0 at closing speed v is
// x = v t0 s(t / t0), t0 = (m / (w K v^1/2))^2/5, with s'' = -s^1.5 - c s^1/4 s', s(0) = 0,
// s'(0) = 1 and c = nu / sqrt(m w K) (the law's c for weight 1: 2 alpha_n sqrt(1.5)).
// s^1/4 is steep at the touch, so the arc is stepped by RK4 in sigma = tau^1/4, where s ~ sigma^4
// is smooth (8 steps to tau 0.3: the velocity's deficit 1 - s' within ~1e-4 of itself).
#include <cmath>

namespace polydem {

struct ScaledArc {
  double sigma = 0.0, s = 0.0, u = 1.0;  // -, tau^1/4, the scaled overlap and its rate
};

namespace hertz_arc_detail {
struct Slope {
  double s, u;  // d/dsigma
};
[[gnu::always_inline]] inline Slope slope(double sigma, double s, double u, double c) {
  const double y = s > 0.0 ? s : 0.0;
  const double dtau = 4.0 * sigma * sigma * sigma;  // dtau/dsigma
  const double root = std::sqrt(y);
  return {dtau * u, -dtau * (y * root + c * std::sqrt(root) * u)};
}
}  // namespace hertz_arc_detail

// The arc from `from` on to sigma `to` in `steps` RK4 steps, damping c (-).
inline ScaledArc advance_arc(ScaledArc from, double to, double c, int steps) {
  using hertz_arc_detail::slope;
  const double h = (to - from.sigma) / steps;
  for (int i = 0; i < steps; ++i) {
    const double a = from.sigma, b = a + 0.5 * h;
    const auto k1 = slope(a, from.s, from.u, c);
    const auto k2 = slope(b, from.s + 0.5 * h * k1.s, from.u + 0.5 * h * k1.u, c);
    const auto k3 = slope(b, from.s + 0.5 * h * k2.s, from.u + 0.5 * h * k2.u, c);
    const auto k4 = slope(a + h, from.s + h * k3.s, from.u + h * k3.u, c);
    from.s += h / 6.0 * (k1.s + 2.0 * (k2.s + k3.s) + k4.s);
    from.u += h / 6.0 * (k1.u + 2.0 * (k2.u + k3.u) + k4.u);
    from.sigma = a + h;
  }
  return from;
}

}  // namespace polydem
