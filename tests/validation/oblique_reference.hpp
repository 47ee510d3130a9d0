#pragma once
// An independent reference for the oblique sphere-wall impact: the engine's two-body spring
// problem (clamped spring-dashpot, capped tangential spring, lever R - x/2, optionally the
// tangential dashpot taking its share of the cap first and the rolling moment spring capped at
// mur (R - x/2) fn) integrated by RK4 with a tiny step. Used by test_oblique_impact.cpp and the
// accuracy cases.
#include <algorithm>
#include <cmath>

#include "validation.hpp"

namespace polydem::validation {

struct Rebound {
  double vt, spin, vn;  // m/s: centre tangential velocity, R w, centre normal velocity (after)
};

// The same problem as the engine, integrated finely. State: overlap x, normal velocity vz
// (> 0 away from the wall), tangential velocity vx, spin w about y, spring force ft along x,
// rolling moment mr about y on the sphere.
struct SpringContact {
  double m, inertia, nu;         // kg, kg m^2, N s/m
  double radius, kn, kt, mu;     // m, N/m, N/m, -
  double nu_t = 0.0;             // N s/m, the tangential dashpot (damp_tangential; 0: none)
  double kr = 0.0, mur = 0.0;    // N m/rad, -: the rolling spring (0: none)

  struct State {
    double x, vz, vx, w, ft, mr;
  };
  double fn(const State& s) const { return std::max(kn * s.x - nu * s.vz, 0.0); }
  double lever(const State& s) const { return radius - 0.5 * s.x; }
  double slip(const State& s) const { return s.vx - lever(s) * s.w; }  // m/s, contact point velocity along x
  // N, the dashpot's force, its share of the cap mu fn first.
  double damper(const State& s) const { return std::clamp(-nu_t * slip(s), -mu * fn(s), mu * fn(s)); }
  State rate(const State& s) const {
    const double f = s.ft + damper(s);  // N
    return {-s.vz, fn(s) / m, f / m, (-lever(s) * f + s.mr) / inertia, -kt * slip(s), -kr * s.w};
  }
  // The rebound from tangential and normal speeds vt0, vn0 (m/s) and spin w0 (rad/s), step h (s).
  Rebound integrate(double vt0, double vn0, double h, double w0 = 0.0) const {
    State s{0.0, -vn0, vt0, w0, 0.0, 0.0};
    for (long n = 0; n < 100000000; ++n) {
      const auto add = [](const State& a, const State& k, double f) {
        return State{a.x + f * k.x, a.vz + f * k.vz, a.vx + f * k.vx, a.w + f * k.w, a.ft + f * k.ft, a.mr + f * k.mr};
      };
      const State k1 = rate(s), k2 = rate(add(s, k1, 0.5 * h)), k3 = rate(add(s, k2, 0.5 * h)), k4 = rate(add(s, k3, h));
      s = State{s.x + h / 6 * (k1.x + 2 * k2.x + 2 * k3.x + k4.x), s.vz + h / 6 * (k1.vz + 2 * k2.vz + 2 * k3.vz + k4.vz),
                s.vx + h / 6 * (k1.vx + 2 * k2.vx + 2 * k3.vx + k4.vx), s.w + h / 6 * (k1.w + 2 * k2.w + 2 * k3.w + k4.w),
                s.ft + h / 6 * (k1.ft + 2 * k2.ft + 2 * k3.ft + k4.ft), s.mr + h / 6 * (k1.mr + 2 * k2.mr + 2 * k3.mr + k4.mr)};
      const double cap = mu * fn(s) - std::abs(damper(s)), rolling_cap = mur * lever(s) * fn(s);  // N, N m
      s.ft = std::clamp(s.ft, -cap, cap);
      s.mr = std::clamp(s.mr, -rolling_cap, rolling_cap);
      if (n > 0 && fn(s) == 0.0) return {s.vx, radius * s.w, s.vz};  // released: free flight after
    }
    return {0.0, 0.0, 0.0};
  }
  // The cap and the release make integrate() first order in h: steps t_c/20000 and t_c/40000,
  // Richardson-extrapolated (2 fine - coarse); `change` gets the larger velocity change between them.
  Rebound extrapolated(double vt0, double vn0, double t_c, double& change, double w0 = 0.0) const {
    const Rebound fine = integrate(vt0, vn0, t_c / 40000.0, w0), coarse = integrate(vt0, vn0, t_c / 20000.0, w0);
    change = std::max(std::abs(fine.vt - coarse.vt), std::abs(fine.spin - coarse.spin));
    return {2 * fine.vt - coarse.vt, 2 * fine.spin - coarse.spin, 2 * fine.vn - coarse.vn};
  }
};


}  // namespace polydem::validation
