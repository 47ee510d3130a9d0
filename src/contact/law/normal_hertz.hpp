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
  // N, the dashpot's force at the sample of overlap x (m), rate r (m/s, > 0 closing, at the
  // sample), nu (N s/m, the pair's times the weight): its impulse over the sample's Verlet cell
  // (half a step either side) divided by dt (s). The dashpot nu x^1/4 dx/dt is the time
  // derivative of 4/5 nu x^5/4, so that impulse is 4/5 nu (x^5/4 at the cell's ends), the ends'
  // overlaps x +- r dt/2 (not below 0); the step where the overlap starts takes onset_force.
  // Sampling nu x^1/4 r instead misses O(dt^1.25) near the touch, x^1/4 being steep there.
  [[gnu::always_inline]] static double cell_dashpot(double nu, double x, double r, double dt) {
    const auto grown = [](double y) { return y > 0.0 ? y * std::sqrt(std::sqrt(y)) : 0.0; };  // m^5/4
    const double half = 0.5 * r * dt;  // m
    return 0.8 * nu * (grown(x + half) - grown(x - half)) / dt;
  }
  // The step where the overlap starts, approached at v > 0 (m/s) by a pair of mass m (kg) (nu as
  // cell_dashpot): the drift has put the overlap x (m) on the straight line, deeper than the
  // impact's arc (hertz_arc.hpp). As the linear law's exact onset (exact_linear.hpp), the arc
  // through x (the touch s before) is taken: the step's force brings the half-step velocity to
  // the arc's at s + dt/2, so the pair goes on along the exact impact shifted in time. Returns
  // that force (N). The cell's impulse from the touch at x / v instead left the pair too deep by
  // ~dt^9/4: en 0.1 at 0.3 x critical 4.5% off (worst of 16 touch places); the arc's series to
  // t^7/2 (49fd0f7 to f521392) 1.7%, short there; stepped, 0.91%.
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
    const double end = sigma(tau + 0.5 * dt / t0);  // -, the half step on
    arc = advance_arc(arc, end, c, 1 + int(8.0 * (end - arc.sigma) / end));
    return std::max(m * v * (1.0 - arc.u), 0.0) / dt;
  }
  // N, the force of the step where the clamp lets go, fp (N) the clamped force sampled, the
  // overlap x (m) opening at rate r < 0 (m/s; nu, dt as cell_dashpot): w K y^1.5 + nu r y^1/4
  // falls to 0 at y* = (nu (-r) / (w K))^4/5 inside the cell (or before its end x + r dt/2). The cell's
  // impulse of the clamped force is that of the force from the cell's start down to y* (the
  // overlap linear in time: w (U(start) - U(y*)) / -r - 4/5 nu (start^5/4 - y*^5/4)); fp took
  // the dashpot's negative tail beyond y*. Without it en 0.9's let-go near y* (x^1/4 steep) was
  // order 1.25 between 0.1 and 0.05 x critical.
  static double released_force(const LawParams& law, double r_star, double w, double nu, double x, double r,
                               double dt, double fp) {
    const auto grown = [](double y) { return y * std::sqrt(std::sqrt(y)); };  // m^5/4
    const double half = -0.5 * r * dt;  // m, what the overlap loses over half a step
    const double end = x - half;        // m, at the cell's end
    const double stiff = w * force(law, r_star, 1.0);  // N/m^1.5, w K
    if (end > 0.0 && stiff * grown(end) >= -nu * r) return fp;  // still pressing at the cell's end
    const double start = x + half;  // m
    const double stop = std::max(std::pow(-nu * r / stiff, 0.8), std::max(end, 0.0));  // m
    if (stop >= start) return 0.0;
    const double impulse = w * (potential(law, r_star, start) - potential(law, r_star, stop)) / -r -
                           0.8 * nu * (grown(start) - grown(stop));  // N s
    return impulse / dt;
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
