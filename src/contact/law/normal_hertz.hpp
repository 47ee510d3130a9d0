#pragma once
// Normal part, Hertz, with Mindlin's tangential stiffness (Hertz 1882; Mindlin 1949; as
// LIGGGHTS `model hertz`): f = 4/3 E* sqrt(R*) x^1.5 (N), x the overlap (m); tangent
// stiffness kn(x) = df/dx = 2 E* sqrt(R* x); tangential spring kt(x) = 8 G* sqrt(R* x), capped
// by Coulomb as the linear one. Stored: 8/15 E* sqrt(R*) x^2.5 = 2/5 f x.
// Coefficients: LawParams::e_star, g_star (Pa, from E and poisson of the two materials,
// prepare_law); R* (m) per contact from its curvature (ContactKinematics::r_star).
// Damping (Tsuji, Tanaka & Ishida 1992): nu(x) = 2 alpha_n sqrt(m_eff kn(x)) ~ x^(1/4), so the
// restitution does not depend on the impact speed; alpha_n is solved from en once per scene
// (hertz_restitution.cpp). Stability: the damped oscillator at kn(x) of the fastest expected
// impact (sim/time_step.cpp).
#include <algorithm>
#include <cmath>

#include "contact/law/hertz_arc.hpp"
#include "contact/law/tangential_spring.hpp"
#include "contact/law/types.hpp"

namespace polydem {

// m, the largest overlap of an elastic Hertz impact at speed v (m/s) of effective mass m (kg):
// (15 m v^2 / (16 E* sqrt(R*)))^(2/5).
inline double hertz_max_overlap(double e_star, double r_star, double m, double v) {
  return std::pow(15.0 * m * v * v / (16.0 * e_star * std::sqrt(r_star)), 0.4);
}

struct NormalHertz {
  static constexpr bool kCurved = true;  // reads R*: the kernels compute it per pair
  // N, the spring at unit weight.
  [[gnu::always_inline]] static double force(const LawParams& law, double r_star, double x) {
    return (4.0 / 3.0) * law.e_star * std::sqrt(r_star * x) * x;
  }
  // J, its potential at unit weight.
  static double potential(const LawParams& law, double r_star, double x) { return 0.4 * force(law, r_star, x) * x; }
  [[gnu::always_inline]] static double spring(const LawParams& law, double r_star, double w, double x) {
    return w * force(law, r_star, x);
  }
  static double energy(const LawParams& law, double r_star, double w, double x) { return w * potential(law, r_star, x); }
  // J, what a weight change w0 -> w1 over the step x0 -> x1 adds: split the step's change of
  // w U(x) less its trapezoid work at the mean weight plus (w1 - w0) times
  // (U0 + U1)/2 - (f1 - f0)(x1 - x0)/4; the first term is the spring's own O(dx^3) error (left
  // out, as for the linear law), the second the patch (1/2 kn x0 x1 (w1 - w0) for f = kn x).
  static double patch(const LawParams& law, double r_star, double x0, double x1, double w0, double w1) {
    if (w0 == w1) return 0.0;
    const double f0 = force(law, r_star, x0), f1 = force(law, r_star, x1);  // N
    return (w1 - w0) * (0.2 * (f0 * x0 + f1 * x1) - 0.25 * (f1 - f0) * (x1 - x0));
  }
  // N s/m, the pair's dashpot before the weight and the x^(1/4) factor: 2 alpha_n sqrt(m 2 E* sqrt(R*)).
  static double pair_damping(const LawParams& law, double m_eff, double r_star) {
    return 2.0 * law.alpha_n * std::sqrt(2.0 * m_eff * law.e_star * std::sqrt(r_star));
  }
  [[gnu::always_inline]] static double damping(double nu_pair, double x) { return nu_pair * std::sqrt(std::sqrt(x)); }
  // The force at n is the hat average over [n-1, n+1] of the force along the motion (Verlet
  // then follows the exact samples to O(dt^4) where the force is smooth; README, Hertz): in
  // closed form for the overlap straight at the rate r (m/s, > 0 closing, at n) from x (m), the
  // touch inside the window included, plus hat_curvature for the overlap's bend.
  // N, the dashpot nu x^1/4 x' (nu in N s/m^1.25): 16/45 nu (second difference of x^9/4) / (r dt^2).
  // g = nu x^1/4 (N s/m), given.
  [[gnu::always_inline]] static double hat_dashpot(double nu, double g, double x, double r, double dt) {
    const double d = r * dt;  // m
    if (std::abs(d) < 1e-3 * x) return g * r * (1.0 - d * d / (64.0 * x * x));  // its series
    const auto h = [](double y) { return y > 0.0 ? y * y * std::sqrt(std::sqrt(y)) : 0.0; };  // m^9/4
    return 16.0 / 45.0 * nu * (h(x + d) - 2.0 * h(x) + h(x - d)) / (r * dt * dt);
  }
  // N, the spring at weight w: w K (second difference of x^7/2 / 8.75) / (r dt)^2; spring (N), w K x^1.5, given.
  [[gnu::always_inline]] static double hat_spring(const LawParams& law, double r_star, double w, double spring, double x,
                                                  double r, double dt) {
    const double d = r * dt;  // m
    if (std::abs(d) < 1e-3 * x) return spring * (1.0 + d * d / (16.0 * x * x));  // its series
    const double stiff = w * force(law, r_star, 1.0);  // N/m^1.5
    const auto q = [](double y) { return y > 0.0 ? y * y * y * std::sqrt(y) / 8.75 : 0.0; };  // m^7/2
    return stiff * (q(x + d) - 2.0 * q(x) + q(x - d)) / (d * d);
  }
  // N per unit weight, the hat's dt^2/12 (kn a + 3 g' r a + g j) for the overlap's acceleration
  // a = (f_rest - f)/m (m/s^2) and jerk j = (f_last - f)/(m dt): f = spring + g r the force at n,
  // f_last at n-1, f_rest the rest of the world's load (N), kn = 1.5 spring/x, g = nu x^1/4 and
  // g' = g/4x (N s/m, N s/m^2). Without it the error is A dt^2 (en 0.5: -0.18 (dt/critical)^2).
  [[gnu::always_inline]] static double hat_curvature(double spring, double g, double x, double r, double f_last,
                                                     double f_rest, double m, double dt) {
    const double f = spring + g * r;                                 // N
    const double a = (f_rest - f) / m, j = (f_last - f) / (m * dt);  // m/s^2, m/s^3
    return dt * dt / 12.0 * ((1.5 * spring + 0.75 * g * r) / x * a + g * j);
  }
  // The step where the overlap starts, approached at v > 0 (m/s) by a pair of mass m (kg) (nu as
  // hat_dashpot): the drift has put the overlap x (m) on the straight line, deeper than the
  // impact's arc (hertz_arc.hpp). As the linear law's exact onset (exact_linear.hpp), the arc
  // through x (the touch s before) is taken: the step's force brings the half-step velocity to
  // the arc's chord from s to s + dt, so the pair goes on along the exact impact's samples
  // shifted in time (the hat forces' samples). Returns that force (N). The arc's velocity at
  // s + dt/2, off the chord by ~dt^2 x''' ~ dt^5/4 near the touch, stays with an undamped spring's
  // point samples (en 1 at 0.3 x critical: 1.2e-2, the chord 2.2e-2; damped, the chord's error is order 2.5).
  static double onset_force(const LawParams& law, double r_star, double w, double nu, double m, double x, double v,
                            double dt) {
    const double stiff = w * force(law, r_star, 1.0);              // N/m^1.5, w K
    const double t0 = std::pow(m / (stiff * std::sqrt(v)), 0.4);  // s, the arc's time scale
    const double x0 = v * t0;                                      // m
    const double c = nu / std::sqrt(m * stiff);                    // -
    const auto sigma = [](double tau) { return std::sqrt(std::sqrt(tau)); };
    double tau = x / x0;  // -, the line's touch (the arc lies below the line: Newton from there)
    ScaledArc arc = advance_arc({}, sigma(tau), c, 8);
    for (int i = 0; i < 2 && arc.u > 0.1; ++i) {
      tau += (x / x0 - arc.s) / arc.u;
      arc = advance_arc(arc, sigma(tau), c, 1);
    }
    const double now = arc.s;                               // -, the arc at x
    const double end = sigma(tau + (c > 0.0 ? dt : 0.5 * dt) / t0);  // -, a step (a half step) on
    arc = advance_arc(arc, end, c, 1 + int(8.0 * (end - arc.sigma) / end));
    const double u = c > 0.0 ? (arc.s - now) * t0 / dt : arc.u;  // -, the new half-step velocity over v
    return std::max(m * v * (1.0 - u), 0.0) / dt;
  }
  // N, the force where the clamp lets go: the hat average of the clamped force w K y^1.5 +
  // nu r y^1/4 along y = x + r s (s in [-dt, dt], r < 0 opening; the rest as hat_spring) over
  // the part where it presses, y > y* = (nu (-r) / (w K))^4/5; fp, the unclamped hat, where the
  // whole window presses. Each side of the hat is [(dt -+ s) F1 +- F2] between its ends, F1 and
  // F2 the force's first and second integrals in s.
  static double released_force(const LawParams& law, double r_star, double w, double nu, double x, double r,
                               double dt, double fp) {
    const double stiff = w * force(law, r_star, 1.0);  // N/m^1.5, w K
    const double end = x + r * dt;                      // m, at the window's end
    if (!(stiff > 0.0) || (end > 0.0 && stiff * end * std::sqrt(std::sqrt(end)) >= -nu * r)) return fp;  // pressing there
    const double stop = std::pow(-nu * r / stiff, 0.8);  // m, y*
    const double s_stop = (stop - x) / r;  // s, where the force reaches 0
    if (s_stop <= -dt) return 0.0;
    const auto first = [&](double s) {  // N s, F1
      const double y = std::max(x + r * s, 0.0);  // m, not below 0 by round-off
      return (0.4 * stiff * y * y * std::sqrt(y) + 0.8 * nu * r * y * std::sqrt(std::sqrt(y))) / r;
    };
    const auto second = [&](double s) {  // N s^2, F2
      const double y = std::max(x + r * s, 0.0);  // m, not below 0 by round-off
      return (stiff * y * y * y * std::sqrt(y) / 8.75 + 16.0 / 45.0 * nu * r * y * y * std::sqrt(std::sqrt(y))) / (r * r);
    };
    const auto side = [&](double a, double b, double sign) {  // N s^2, the hat weight dt + sign s
      if (!(b > a)) return 0.0;
      return (dt + sign * b) * first(b) - sign * second(b) - (dt + sign * a) * first(a) + sign * second(a);
    };
    return (side(-dt, std::min(0.0, s_stop), 1.0) + side(0.0, std::min(dt, s_stop), -1.0)) / (dt * dt);
  }
  // N/m, the tangent stiffnesses at the largest overlap of an impact of mass m (kg) at v (m/s)
  // on a contact of curvature r_star (m): the stability limit takes these.
  static double impact_stiffness(const LawParams& law, double m, double v, double r_star) {
    return 2.0 * law.e_star * std::sqrt(r_star * hertz_max_overlap(law.e_star, r_star, m, v));
  }
  static double impact_tangential_stiffness(const LawParams& law, double m, double v, double r_star) {
    return tangential_stiffness(law, r_star, hertz_max_overlap(law.e_star, r_star, m, v));
  }
  // N/m, Mindlin's tangential stiffness before the weight.
  [[gnu::always_inline]] static double tangential_stiffness(const LawParams& law, double r_star, double x) {
    return 8.0 * law.g_star * std::sqrt(r_star * x);
  }
  // J, what the change of the tangential stiffness w kt(x) over the step adds to the spring ft
  // at fixed ft (no potential either: counted with the patch work).
  static double tangential_patch(const LawParams& law, double r_star, const Vec3& ft, double x0, double w0, double x1,
                                 double w1) {
    const double f2 = ft.squaredNorm();  // N^2
    const double k0 = w0 * tangential_stiffness(law, r_star, x0), k1 = w1 * tangential_stiffness(law, r_star, x1);
    if (f2 == 0.0 || !(k0 > 0.0)) return 0.0;  // nothing held, or a spring handed over at first touch
    return 0.5 * f2 * (1.0 / k1 - 1.0 / k0);
  }
};

}  // namespace polydem
