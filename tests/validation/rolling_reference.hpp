#pragma once
// An independent reference for a spinning sphere landing on a wall with rolling resistance and
// no friction: the engine's problem (clamped spring-dashpot, rolling moment spring capped at
// mur (R - x/2) fn) integrated by RK4 with a tiny step. Used by the accuracy cases.
#include <algorithm>
#include <cmath>

namespace polydem::validation {

// State: overlap x (m), normal velocity vz (m/s, > 0 away from the wall), spin w (rad/s) about
// the wall's tangent y, rolling moment mr (N m) on the sphere.
struct RollingContact {
  double m, inertia, nu;          // kg, kg m^2, N s/m
  double radius, kn, kr, mur;     // m, N/m, N m/rad, -

  struct State {
    double x, vz, w, mr;
  };
  double fn(const State& s) const { return std::max(kn * s.x - nu * s.vz, 0.0); }
  double cap(const State& s) const { return mur * (radius - 0.5 * s.x) * fn(s); }
  State rate(const State& s) const { return {-s.vz, fn(s) / m, s.mr / inertia, -kr * s.w}; }
  static State add(const State& a, const State& k, double f) {
    return {a.x + f * k.x, a.vz + f * k.vz, a.w + f * k.w, a.mr + f * k.mr};
  }
  // rad/s, the spin after the rebound from spin w0 and landing speed vn0 (m/s), step h (s).
  double spin_after(double w0, double vn0, double h) const {
    State s{0.0, -vn0, w0, 0.0};
    for (long n = 0; n < 100000000; ++n) {
      const State k1 = rate(s), k2 = rate(add(s, k1, 0.5 * h)), k3 = rate(add(s, k2, 0.5 * h)), k4 = rate(add(s, k3, h));
      s = add(add(add(add(s, k1, h / 6), k2, h / 3), k3, h / 3), k4, h / 6);
      s.mr = std::clamp(s.mr, -cap(s), cap(s));
      if (n > 0 && fn(s) == 0.0) return s.w;  // released: free flight after
    }
    return 0.0;
  }
  // The cap and the release make spin_after first order in h: steps t_c/20000 and t_c/40000,
  // Richardson-extrapolated (2 fine - coarse).
  double extrapolated(double w0, double vn0, double t_c) const {
    return 2.0 * spin_after(w0, vn0, t_c / 40000.0) - spin_after(w0, vn0, t_c / 20000.0);
  }
};

}  // namespace polydem::validation
