#pragma once
// What keeps the normal force second order in dt under velocity Verlet (SPEC "accuracy in
// time"). Each kick pair applies F(n+1) to the interval [n+1/2, n+3/2], the midpoint rule,
// exact to O(dt^2) for a force smooth in time. Two things break that, each worth O(dt) of
// restitution (3% at dt = 0.1 x critical with en = 0.5):
//  - a dashpot that reads the half-step velocity lags half a step. The dashpot reads instead
//    the end-of-step velocity: the bodies' prediction v(n+1/2) + F(n) dt/2m (integrate.hpp)
//    with this contact's own change of force taken implicitly on the pair's mass (exact
//    velocity Verlet with an implicit dashpot for a binary impact: stable up to 2/w for any
//    damping, so the critical step of damping_linear.hpp stays a safe bound);
//  - the force jumps (dashpot) or kinks (spring) where the overlap starts or the clamp lets go
//    between two steps. The midpoint rule then misses an impulse of the order of the jump times
//    dt, which the step where it happens adds back (the linear law here; Hertz's x^1/4 dashpot
//    in NormalHertz::onset_force and released_force).
// The impulses below come from integrating the force over the Verlet cells with the switch at
// its interpolated time; derived in tests/contact/test_law_impact.cpp.
#include <algorithm>

namespace polydem {

// m/s, dashpot_velocity (below) for hm = h / m_eff (s/kg) given.
[[gnu::always_inline]] inline double implicit_velocity(double vn_end, double spring, double c, double f_last, double hm) {
  return (vn_end + hm * (spring - f_last)) / (1.0 + hm * c);
}
// m/s, the normal velocity (> 0 separating) the dashpot reads at n+1: the predicted vn_end with
// this contact's force per unit patch weight moved from its last value f_last (N) to
// spring - c vn (N, N s/m), on the pair's mass m_eff (kg), over half a step h (s).
[[gnu::always_inline]] inline double dashpot_velocity(double vn_end, double spring, double c, double f_last,
                                                      double m_eff, double h) {
  return implicit_velocity(vn_end, spring, c, f_last, h / m_eff);
}

// Where the overlap x (m) starts at the normal velocity vn < 0 (m/s): it began tau = x / -vn
// before this step's end (the drift is a straight line), the dashpot at once (force g at the
// touch, N) and the spring from zero with slope spring/tau (N/s). Its cell then carries
// g (tau - dt/2) + slope (tau - dt/2)^2 / 2 less (or more) impulse than the force acted; the
// step adds them as forces (N): the dashpot's and the spring's.
struct OnsetForce {
  double dashpot, spring;  // N
};
[[gnu::always_inline]] inline OnsetForce onset_force(double x, double vn, double g, double spring, double dt) {
  const double tau = std::min(x / -vn, dt);  // s, since the touch
  const double early = tau - 0.5 * dt;       // s, how far before the middle of the step it touched
  return {g * early / dt, 0.5 * spring / tau * early * early / dt};
}

// N, added to the force of the step where the clamp lets go (or the overlap ends): the force
// fell from f_last > 0 to the unclamped u <= 0 (N) along a line, so it reached zero at
// theta = dt f_last / (f_last - u) into the step; the cells miss slope (theta - dt/2)^2 / 2.
[[gnu::always_inline]] inline double release_force(double f_last, double u, double dt) {
  const double slope = (f_last - u) / dt;  // N/s
  const double early = dt * f_last / (f_last - u) - 0.5 * dt;  // s
  return 0.5 * slope * early * early / dt;
}

}  // namespace polydem
