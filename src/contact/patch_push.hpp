#pragma once
// The onset pushes of a patch whose sub-contacts start at different times within one step (issue 16: a cube
// landing almost flat, its far edge joining the near one's patch). Each sub-contact's share w_k = x_k / sum(x)
// (pair_kernel.hpp, patch_weights) then moves on the scale of the join's lag, not of the impact: the near edge
// carries the whole patch until the far one touches, then hands it half of it. The cells of velocity Verlet
// sample w_k at the steps only, which misses O(dt) of each share's impulse, the patch's torque. Here the overlaps
// drift along straight lines over the step (x_j at n+1 less r_j, the closing rate, per second before it; a new
// one from its touch) and each share's impulse over the step is integrated in closed form, and so is each later
// cell's while the shares settle (the lag may be shorter than dt). The step adds what the cells miss, as the lone
// contact's onset push does (second_order.hpp): with f the share, f(n) and f'(n) from the sub-contacts that
// touched at n (the formula the last step used), the push (a force over dt) is
//   P dt = integral over [n, n+3/2] - f(n) dt/2 - f'(n) dt^2/8 - f(n+1) dt
//          + sum over m = 2 ... 17 of (integral over cell n+m - f(n+m) dt),
// the cells ahead ending at the first predicted letting go (patch_window; the cut cell counted in part: continuous
// in dt). For one share whose dashpot starts tau before n+1 it is onset_force's g (tau - dt/2). Only a region where
// a sub-contact touched within the step, not all together, pushes (pair_kernel.hpp, patch_pushes); the push is an
// impulse at n+1, its work booked at once (law.hpp: the dashpot part dissipated, the spring part patch_work).
// The drift at v(n+1/2) misses as well the turn the moving shares make within the join step: an
// angle error of O(lag dt), first order while the lag is under a step. Each share's first moment
// over the step (below) turns the bodies after it (pair_kernel.hpp, PairTurn; integrate/turn_table.hpp,
// turn_bodies): the almost-flat landing, worst of 8, 9.90e-4 -> 3.86e-4 at 0.1 x critical.
#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "contact/law/types.hpp"

namespace polydem {

// One sub-contact of a patch over the step, s (s) the time before n+1: overlap x - r s (m) for
// s < touch (s; the whole step for one that touched at n).
struct PatchDrift {
  double x, r, touch;  // m, m/s (closing), s
  bool old;            // it touched at n: in the formula of the last step
};

namespace patch_detail {
// Share k's dashpot and spring parts over the patch's present sub-contacts on s in [a, b]:
// integral of x_k / S and x_k^2 / S (s, m s), S = X - R s their overlap sum (m; X at n+1, R its
// rate). With x_k = alpha S + beta both integrals are closed: alpha (b - a) + beta I1 and
// alpha^2 I_S + 2 alpha beta (b - a) + beta^2 I1, I1 the integral of 1/S.
inline std::array<double, 2> piece(double xk, double rk, double X, double R, double a, double b) {
  const double width = b - a, s_end = X - R * b, s_start = X - R * a;  // s, m, m
  const double mean = X - R * 0.5 * (a + b);                           // m, S at the piece's middle
  if (s_end <= 0.0 && s_start > 0.0 && R > 0.0)  // the touch: the present ones start together, x_k / S = r_k / R
    return {rk / R * width, (rk / R) * (rk / R) * 0.5 * s_start * width};
  if (s_end <= 0.0 || s_start <= 0.0) return {0.0, 0.0};  // the patch lets go in it: not modelled
  if (std::abs(R) * width <= 1e-6 * mean) {  // S nearly constant
    const double xm = xk - rk * 0.5 * (a + b);  // m, the midpoint rule: its error is O(width^3 R^2 / S^3)
    return {xm / mean * width, xm * xm / mean * width};
  }
  const double alpha = rk / R, beta = xk - alpha * X;  // -, m
  const double i1 = std::log(s_start / s_end) / R;      // s/m
  return {alpha * width + beta * i1, alpha * alpha * mean * width + 2.0 * alpha * beta * width + beta * beta * i1};
}

// The same pieces' first moments in s: integral of s x_k / S and s x_k^2 / S over [a, b] (s^2, m s^2),
// with the integral of s / S, (X I1 - (b - a)) / R, beside I1 (its round-off grows as S's change
// shrinks: ~1e-10 where the midpoint rule takes over).
inline std::array<double, 2> moment_piece(double xk, double rk, double X, double R, double a, double b) {
  const double width = b - a, s_end = X - R * b, s_start = X - R * a;  // s, m, m
  const double mean = X - R * 0.5 * (a + b);                           // m
  const double first = 0.5 * (b * b - a * a), second = (b * b * b - a * a * a) / 3.0;  // s^2, s^3
  const double of_sum = X * first - R * second;  // m s^2, the integral of s S
  if (s_end <= 0.0 && s_start > 0.0 && R > 0.0)  // the touch, as piece's
    return {rk / R * first, (rk / R) * (rk / R) * of_sum};
  if (s_end <= 0.0 || s_start <= 0.0) return {0.0, 0.0};
  if (std::abs(R) * width <= 1e-6 * mean) {
    const double middle = 0.5 * (a + b), xm = xk - rk * middle;  // s, m
    return {middle * xm / mean * width, middle * xm * xm / mean * width};
  }
  const double alpha = rk / R, beta = xk - alpha * X;     // -, m
  const double i1 = std::log(s_start / s_end) / R;        // s/m
  const double j1 = (X * i1 - width) / R;                 // s^2/m, the integral of s / S
  return {alpha * first + beta * j1, alpha * alpha * of_sum + 2.0 * alpha * beta * first + beta * beta * j1};
}

// Share k's value and slope in t (x_k / S, x_k^2 / S; per s and m/s) at s over `present`.
inline std::array<double, 4> at(const std::vector<PatchDrift>& d, std::size_t k, double s, bool only_old) {
  double X = 0.0, R = 0.0;  // m, m/s
  for (const PatchDrift& j : d)
    if (only_old ? j.old : true) X += std::max(j.x - j.r * s, 0.0), R += j.r;
  const double xk = std::max(d[k].x - d[k].r * s, 0.0), rk = d[k].r;
  if (!(X > 0.0) || (only_old && !d[k].old)) return {0.0, 0.0, 0.0, 0.0};
  return {xk / X, xk * xk / X, (rk * X - xk * R) / (X * X), (2.0 * xk * rk * X - xk * xk * R) / (X * X)};
}
}  // namespace patch_detail

// s after n+1 when the first sub-contact present at n+1 lets go (its overlap x - r s reaches 0:
// x / -r for one opening), at most `cap`: the model of the shares holds up to there.
inline double patch_window(const std::vector<PatchDrift>& d, double cap) {
  double end = cap;  // s
  for (const PatchDrift& j : d)
    if (j.r < 0.0) end = std::min(end, j.x / -j.r);
  return end;
}

// Sub-contact k's push, per unit of its dashpot force (-) and of kn (m), and the first moment
// about n+1 (s^2, m s^2) that the impulses at the steps miss of its force over [n, n+3/2]:
// PatchPush. Velocity Verlet's positions take each step's force as an impulse F(m) dt at t_m
// (x(m+1) = x(m) + v(m+1/2) dt), so a force that acts at t within the step moves every later
// position by its impulse times (t_{n+1} - t) less than the drift gives: the moment of s f(s)
// (s before n+1). The push sits at n+1 (no moment); the last step's impulse at n (moment f dt^2)
// counts the old formula's force over [n - 1/2, n] (f 5 dt^2/8 - f' dt^3/6), leaving it
// f(n) 3 dt^2/8 + f'(n) dt^3/6 for [n, n+1/2].
inline PatchPush patch_push(const std::vector<PatchDrift>& d, std::size_t k, double dt) {
  std::vector<double> cuts = {0.0, dt};  // s: the touches inside the step split it
  for (const PatchDrift& j : d)
    if (!j.old && j.touch > 0.0 && j.touch < dt) cuts.push_back(j.touch);
  std::sort(cuts.begin(), cuts.end());
  std::array<double, 2> sum = {0.0, 0.0}, moment = {0.0, 0.0};  // (s, m s), (s^2, m s^2)
  const auto add = [](std::array<double, 2>& to, const std::array<double, 2>& part) { to[0] += part[0], to[1] += part[1]; };
  for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
    const double a = cuts[p], b = cuts[p + 1];
    if (b <= a || (!d[k].old && d[k].touch < b)) continue;  // empty, or k not touching yet
    double X = 0.0, R = 0.0;  // m, m/s: the sub-contacts touching over [a, b]
    for (const PatchDrift& j : d)
      if (j.old || j.touch >= b) X += j.x, R += j.r;
    add(sum, patch_detail::piece(d[k].x, d[k].r, X, R, a, b));
    add(moment, patch_detail::moment_piece(d[k].x, d[k].r, X, R, a, b));
  }
  // After n+1 the shares keep moving on the join's scale (the lag between the touches, which may
  // be less than dt): the cells n+1 ... n+kAhead sample them at their steps, what they miss
  // counted here as well (their later error falls as (lag / steps)^2), up to the first letting
  // go (patch_window): past it the straight lines are not the patch's, and the step that sees
  // it changes the set and pushes anew. A cell cut there counts its part before, so the push
  // is continuous in dt.
  constexpr int kAhead = 16;
  const double end = patch_window(d, (kAhead + 0.5) * dt);  // s after n+1
  double X = 0.0, R = 0.0;  // m, m/s: every sub-contact, after n+1
  for (const PatchDrift& j : d) X += j.x, R += j.r;
  for (int m = 1; m <= kAhead + 1; ++m) {  // cell n+m: [m - 3/2, m - 1/2] dt after n+1 (for m = 1 its first half is the step's)
    const double from = std::max(m - 1.5, 0.0) * dt, to = std::min((m - 0.5) * dt, end);  // s after n+1
    if (to <= from) break;
    const std::array<double, 4> sample = patch_detail::at(d, k, -(m - 1) * dt, false);  // at n+m
    const double width = to - (m - 1.5) * dt;  // s, the cell's part the samples count
    const std::array<double, 2> cell = patch_detail::piece(d[k].x, d[k].r, X, R, -to, -from);
    add(sum, {cell[0] - sample[0] * width, cell[1] - sample[1] * width});
    // The moment over the join's window [n, n+3/2] alone, where the shares move by O(1) within a
    // step (the sample at n+1 has none): the later cells' misses weigh by up to 16 dt there, the
    // straight lines' error with them (the almost-flat landing at 0.1 x critical, worst of 8:
    // 3.86e-4 with cell n+1 alone, 4.15e-4 with all 17; tilted 1e-3 rad 8.38e-4 against 9.99e-4).
    if (m == 1) add(moment, patch_detail::moment_piece(d[k].x, d[k].r, X, R, -to, -from));
  }
  const std::array<double, 4> then = patch_detail::at(d, k, dt, true);
  const double dt2 = dt * dt, dt3 = dt2 * dt;  // s^2, s^3
  PatchPush push;
  push.dashpot = sum[0] / dt - 0.5 * then[0] - then[2] * dt / 8.0;
  push.spring = sum[1] / dt - 0.5 * then[1] - then[3] * dt / 8.0;
  push.dashpot_moment = moment[0] - then[0] * 3.0 * dt2 / 8.0 - then[2] * dt3 / 6.0;
  push.spring_moment = moment[1] - then[1] * 3.0 * dt2 / 8.0 - then[3] * dt3 / 6.0;
  return push;
}

}  // namespace polydem
