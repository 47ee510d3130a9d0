#pragma once
// Tangential part, spring with Coulomb cap (SPEC; LAMMPS granular "linear_history"): the
// spring ft (history, N) turns with the tangent plane, grows by -kt_w vt dt and is capped at
// mu fp, fp the compressive normal force. Coefficients: LawParams::kt (N/m), mu (-).
// Stored: |ft|^2/(2 kt_w); slip under the cap dissipates (capped_spring). Active when mu > 0
// and kt_w > 0 (a sub-contact at the band edge has w = 0). Stability: kt on the tangential
// contact-point mass (sim/time_step.cpp).
#include <algorithm>
#include <cmath>

#include "contact/law/types.hpp"

namespace polydem {

// Adds an increment to a spring (force or moment) and caps its length at `cap`, back-solving
// the spring to the Coulomb limit (Luding 2008, Granular Matter 10:235, eqs. 17-19).
// Returns J, the slip work: the work of the relative motion on the spring over the step (the
// trapezoid rule velocity Verlet applies) minus the change of its energy, which reduces to
// (|trial| - cap)(old . trial/|trial| + cap)/(2k): cap times the slip when sliding steadily,
// the stored energy when the cap drops to 0, and 0 while sticking.
// `at_slip(cap)`: the cap to take where the spring passes `cap` (the same unit): a finer one
// (law.hpp: the force at n+1 under the exact step) that costs nothing while it sticks.
// `on_slip(|old|^2, trial, |trial|, cap)`: called where it slips (slip_start_push).
template <class AtSlip, class OnSlip>
[[gnu::always_inline]] inline double capped_spring(Vec3& spring, const Vec3& increment, double stiffness, double cap,
                                                   const AtSlip& at_slip, const OnSlip& on_slip) {
  const Vec3 old = spring;
  spring += increment;
  const double trial2 = spring.squaredNorm();
  if (trial2 <= cap * cap) return 0.0;  // sticking, the common case: no square root
  cap = at_slip(cap);
  if (trial2 <= cap * cap) return 0.0;
  const double trial = std::sqrt(trial2);
  on_slip(old.squaredNorm(), spring, trial, cap);
  const double along = old.dot(spring) / trial;  // old spring along the trial direction
  spring *= cap / trial;
  return (trial - cap) * (along + cap) / (2.0 * stiffness);
}
template <class AtSlip>
[[gnu::always_inline]] inline double capped_spring(Vec3& spring, const Vec3& increment, double stiffness, double cap,
                                                   const AtSlip& at_slip) {
  return capped_spring(spring, increment, stiffness, cap, at_slip, [](double, const Vec3&, double, double) {});
}
[[gnu::always_inline]] inline double capped_spring(Vec3& spring, const Vec3& increment, double stiffness, double cap) {
  return capped_spring(spring, increment, stiffness, cap, [](double c) { return c; });
}

// N, along the spring, added to the force (not to the spring) in the step where a spring that
// stuck at n (length `old` under the cap c0 then, N) slips by n+1 (trial length `trial` over the
// cap c1): both move along lines over the step and meet at theta = dt (c0 - old) / -d, where the
// force's slope drops by d/dt (d < 0, N); the kicks, which apply the value at n to the cell
// [n-1/2, n+1/2] and the cap at n+1 to the next, then carry d (theta/dt - 1/2)^2 dt/2 too much
// impulse (as the normal spring's kinks, second_order.hpp). The oblique impact's stick-slip
// switches were off by up to -d dt/8 of impulse each, with their place in the step.
[[gnu::always_inline]] inline double slip_start_push(double old, double trial, double c0, double c1) {
  const double d = (c1 - c0) - (trial - old);  // N, < 0: |trial| - c1 > 0 >= |old| - c0
  const double late = (c0 - old) / -d - 0.5;   // -, theta/dt - 1/2
  return 0.5 * d * late * late;
}

// The push along the trial spring (on_slip's arguments: |old|^2, trial, |trial|, cap) of a spring
// that stuck at n and slips by n+1. `cap_then`: the cap the last step's normal force gives; a
// spring that stuck over it (its stick read the force at n+1) was at its cap then, |old|.
[[gnu::noinline]] inline Vec3 slip_start_push_along(double old2, const Vec3& trial_spring, double trial,
                                                         double cap, double cap_then) {
  const double old = std::sqrt(old2);
  return (slip_start_push(old, trial, std::max(cap_then, old), cap) / trial) * trial_spring;
}

// Rotate ft into the plane normal to n keeping its length, add -kt_w vt dt, cap |ft| <= ft_max
// (at_slip, on_slip: capped_spring). Returns J, the slip.
template <class AtSlip, class OnSlip>
[[gnu::always_inline]] inline double tangential_spring(Vec3& ft, const Vec3& n, const Vec3& vt, double kt_w,
                                                       double ft_max, double dt, const AtSlip& at_slip,
                                                       const OnSlip& on_slip) {
  const double length2 = ft.squaredNorm();
  ft -= ft.dot(n) * n;
  const double in_plane2 = ft.squaredNorm();
  if (in_plane2 > 0.0) ft *= std::sqrt(length2 / in_plane2);
  return capped_spring(ft, -kt_w * dt * vt, kt_w, ft_max, at_slip, on_slip);
}

// s, how long a spring on within gap `edge` (m) has been on over the step that took the gap from
// gap_last to dn (m) at the normal velocity vn (m/s, < 0 closing): dt, but where it starts, the
// time since the edge was crossed (the drift is a straight line). Counted from the step's start,
// a spring that starts late in its step would hold kt vt dt, not kt vt tau: an O(dt) error in
// ft (oblique 45 deg at 0.3 x critical, touch at 13/16 of the step: 1.16e-2 -> 6.4e-3).
[[gnu::always_inline]] inline double spring_on_time(double edge, double gap_last, double dn, double vn, double dt) {
  if (gap_last < edge || dn >= edge || vn >= 0.0) [[likely]] return dt;
  return std::min((edge - dn) / -vn, dt);
}
// J, what the kicks' trapezoid takes from the bodies beyond what a spring ft (N) that started
// from zero this step stores, when it was loaded over `off` (s) less than the step the bodies
// moved at vt (m/s; off < 0: loaded over more, the exact onset's arc time): -ft.vt off / 2 (0 where
// it did not start). The ledger counts it dissipated.
[[gnu::always_inline]] inline double started_spring_work(const Vec3& ft, const Vec3& vt, double off) {
  return off != 0.0 ? -0.5 * ft.dot(vt) * off : 0.0;
}

// N, added to the force (not to the spring) in the step where a spring starts `on` (s) before
// its end: it ramps from zero at -kt_w vt (N/s, vt in m/s, kt_w N/m), and the kicks apply its
// value at n+1 to the cell [n+1/2, n+3/2], missing slope (on - dt/2)^2/2 of impulse (the
// normal spring's onset push, second_order.hpp). Without it the oblique impact's tangential
// impulse was off by up to kt vt dt^2/8 with the place of the touch in its step.
[[gnu::always_inline]] inline Vec3 started_spring_push(const Vec3& vt, double kt_w, double on, double dt) {
  const double early = on - 0.5 * dt;  // s
  return (-0.5 * kt_w * early * early / dt) * vt;
}

// J, energy held by a spring of stiffness k (0 for k = 0: that spring is off).
inline double spring_energy(const Vec3& f, double k) { return k > 0.0 ? 0.5 * f.squaredNorm() / k : 0.0; }

// J, what a weight change from w_old to w_new adds to a spring of base stiffness k holding
// f at fixed f: |f|^2/(2 k w_new) - |f|^2/(2 k w_old) (0 when the weight stays).
inline double reweighted(const Vec3& f, double k, double w_old, double w_new) {
  if (w_old == w_new) return 0.0;  // a lone contact, a steady patch: no division
  return 0.5 * f.squaredNorm() * (w_old - w_new) / (k * w_old * w_new);
}

}  // namespace polydem
