#pragma once
// The linear law's normal pair stepped exactly (SPEC "accuracy in time"). A lone contact of
// effective mass m, m x'' = -(kn x + c x'), c = 2 zeta sqrt(kn m), sampled every dt, obeys
// x(n+1) = 2 E cos(w_d dt) x(n) - E^2 x(n-1), E = exp(-zeta w dt): velocity Verlet follows
// these samples exactly when the force at n is k' x(n) + c' (x(n) - x(n-1))/dt with
//   k' = m/dt^2 (1 + E^2 - 2 E cos(w_d dt)),  c' = m/dt (1 - E^2),
// the secant rate being the half-step velocity the kernel has (k' -> kn, c' -> c as dt -> 0).
// Where the overlap starts, the drift has put x(n) on the straight line, deeper than the arc
// the force follows from the touch: the onset force puts x(n+1) on the arc that passes through
// x(n) with the approach speed (the exact impact, shifted in time by the lag), so the samples
// from there on are the arc's and the rebound is the exact one. Checked against the closed
// form in tests/contact/test_exact_linear.cpp.
#include <algorithm>
#include <cmath>

namespace polydem {

// With a load f_rest (N) from the rest of the world pressing the pair together (gravity, other
// contacts), the exact samples follow x - f_rest/kn: the force is k' x + c' r + (1 - k'/kn)
// f_rest, r = -vn the overlap rate (m/s), so that a contact at rest holds kn x = f_rest.
// k' and c' depend on the pair's mass alone (with the law and dt): a pair list keeps them per pair
// (PairList::linear_steps), set at the pair's first exact step after the list is built. k = 0:
// not set yet (k' > 0 for any damping and step).
// T: a double, or two-lane doubles where two pairs are stepped side by side (sphere_lanes.hpp),
// each lane by these same operations (the same bits).
template <class T>
struct LinearStepOf {
  T k{}, c{};  // N/m, N s/m
  T rest{};    // -, 1 - k'/kn: the share of the load the samples leave to the spring
  T force(T x, T r, T f_rest) const { return k * x + c * r + rest * f_rest; }
};
// N, that load, from the last force f_last (N) and the overlap rates at the half step r and
// predicted for the step's end r_end (m/s, the bodies' last forces: integrate.hpp): m_eff
// (kg) times the relative acceleration over the half step, less the contact's own part.
template <class T>
inline T rest_of_world(T f_last, T m, T dt, T r, T r_end) {
  return f_last + 2.0 * m * (r_end - r) / dt;
}
// N/m and N s/m per unit patch weight: k' and c' above for kn (N/m), damping ratio zeta (-),
// mass m (kg) and step dt (s). Written with expm1 so that k' keeps its digits at small dt.
// Out of line: kept out of the kernels' hot code (most calls hit the pair's cache below).
[[gnu::noinline]] inline LinearStep linear_step(double kn, double zeta, double m, double dt) {
  const double h = std::sqrt(kn / m) * dt;  // rad, w dt
  const double q = 1.0 - zeta * zeta;       // (w_d / w)^2, negative when overdamped
  const double half = 0.5 * h * std::sqrt(std::abs(q));  // rad, w_d dt / 2
  const double s = q >= 0.0 ? std::sin(half) : std::sinh(half);
  const double one_less_e = -std::expm1(-zeta * h);  // 1 - E
  const double e = 1.0 - one_less_e;
  // 1 + E^2 - 2 E cos = (1 - E)^2 + 4 E sin^2(w_d dt/2) (sinh: minus).
  const double k_term = one_less_e * one_less_e + (q >= 0.0 ? 4.0 : -4.0) * e * s * s;
  const double k = m / (dt * dt) * k_term;  // N/m
  return {k, m / dt * -std::expm1(-2.0 * zeta * h), 1.0 - k / kn};
}
// The pair's k' and c' from `cache`, computed there at first use: libm's expm1 and sin cost
// ~120 instructions, a quarter of a sphere contact's step.
inline const LinearStep& cached_linear_step(LinearStep& cache, double kn, double zeta, double m, double dt) {
  if (cache.k == 0.0) [[unlikely]] cache = linear_step(kn, zeta, m, dt);
  return cache;
}

namespace exact_detail {
// The impact arc from the touch at speed 1 (m/s): overlap (m) and rate at s (s) after it.
struct Arc {
  double x, v;
};
inline Arc unit_arc(double w, double zeta, double s) {
  const double q = 1.0 - zeta * zeta;
  const double wd = w * std::sqrt(std::abs(q));  // rad/s
  const double decay = std::exp(-zeta * w * s);
  double sn = s, cs = 1.0;  // sin(wd s)/wd and cos(wd s), critically damped: s and 1
  if (q > 0.0) sn = std::sin(wd * s) / wd, cs = std::cos(wd * s);
  if (q < 0.0) sn = std::sinh(wd * s) / wd, cs = std::cosh(wd * s);
  return {decay * sn, decay * (cs - zeta * w * sn)};
}
}  // namespace exact_detail

// The onset step's force: the overlap x (m) is on the approach line at speed v_in > 0 (m/s),
// x(n-1) = x - v_in dt. Finds s with arc(s) = x (Newton from x/v_in climbs the concave arc from
// below; a line deeper than the arc's top takes the top): `force` = m/dt^2 (x + v_in dt -
// arc(s + dt)) puts x(n+1) on that arc, whose touch was `since_touch` = s ago (more than the
// line's x/v_in: the springs that start with the contact count their time from there).
struct ExactOnset {
  double force, since_touch;  // N per unit weight, s
};
inline ExactOnset exact_onset_force(double kn, double zeta, double m, double dt, double x, double v_in) {
  const double w = std::sqrt(kn / m);  // rad/s
  const double target = x / v_in;      // s, the arc's overlap at speed 1
  const double q = 1.0 - zeta * zeta, wd = w * std::sqrt(std::abs(q));  // -, rad/s
  // s, where the arc tops: tan (tanh when overdamped) of wd s = wd / (zeta w).
  const double top = q > 0.0 ? std::atan2(wd, zeta * w) / wd : q < 0.0 ? std::atanh(wd / (zeta * w)) / wd : 1.0 / w;
  double s = std::min(target, top);
  for (int i = 0; i < 6 && s < top; ++i) {
    const exact_detail::Arc a = exact_detail::unit_arc(w, zeta, s);
    if (a.x >= target) break;
    s = std::min(s + (target - a.x) / a.v, top);
  }
  const double next = v_in * exact_detail::unit_arc(w, zeta, s + dt).x;  // m, x(n+1) on the arc
  return {m / (dt * dt) * (x + v_in * dt - next), s};
}

// Where the force lets go (the clamp, or the overlap's end) at theta after sample a, it falls
// along a line of slope -g (N/s): the arc lies below its tangent line by g (theta - t)^3/(6m)
// before theta and the free flight is that line after it. Exact samples then need, beyond the
// glued arc's force, g (dt - theta)^3/(6 dt^2) at a and g theta^3/(6 dt^2) at a + 1 (N).
// At a, the glued arc one step ahead: overlap x (m) and force u (N per unit weight) at a + 1,
// from overlap x, rate r = -vn (m/s), force u and load f_rest now (N per unit weight).
template <class T>
struct GluedAheadOf {
  T x, u;  // m, N
};
template <class T>
inline GluedAheadOf<T> glued_ahead(const LinearStepOf<T>& step, T m, T dt, T x, T r, T u, T f_rest) {
  const T r_next = r + (f_rest - u) * dt / m;  // m/s
  const T x_next = x + r_next * dt;            // m
  return {x_next, step.force(x_next, r_next, f_rest)};
}
// release_ahead: at a, the push when the glued arc's next force u_next <= 0; u > 0 the force
// now (N per unit weight).
inline double release_ahead(double u, double u_next, double dt) {
  const double later = dt * -u_next / (u - u_next);  // s, dt - theta
  return (u - u_next) / dt * later * later * later / (6.0 * dt * dt);
}
// release_behind: at a + 1, from the last force f_last > 0 and the glued force u <= 0 now (N).
inline double release_behind(double f_last, double u, double dt) {
  const double theta = dt * f_last / (f_last - u);  // s
  return (f_last - u) / dt * theta * theta * theta / (6.0 * dt * dt);
}

}  // namespace polydem
