#pragma once
// Tangential part, dashpot beside the spring (damp_tangential): -nu_t_w vt, nu_t = 2 alpha_t
// sqrt(kt m_eff) (N s/m) per pair. Coefficient: LawParams::alpha_t (-). No stored energy;
// dissipates nu_t_w |vt|^2 dt. Stability: the tangential oscillator with ratio alpha_t.
#include <algorithm>
#include <cmath>

#include "contact/law/types.hpp"

namespace polydem {

// N s/m, the tangential dashpot of a pair (0 without damp_tangential).
inline double pair_tangential_damping(const LawParams& law, double m_eff) {
  return law.tangential_damping ? 2.0 * law.alpha_t * std::sqrt(law.kt * m_eff) : 0.0;
}

// N. Spring plus dashpot stay within the Coulomb cap: the dashpot takes its share first (at
// most all of it) and the spring is capped at what is left, so steady sliding still carries
// exactly mu fp. The force reads vt_end, the tangential velocity predicted for the end of the
// step (second_order.hpp); its work over the step's displacement vt dt (vt at the half step;
// over a contact's life it differs from the kicks' trapezoid by a boundary term, as no history
// keeps the last step's dashpot force) goes to `dissipated`; the spring's cap is left in `ft_max`.
inline Vec3 tangential_dashpot(const Vec3& vt_end, const Vec3& vt, double nu_t_w, double& ft_max, double& dissipated,
                               double dt) {
  Vec3 damper = -nu_t_w * vt_end;
  const double size = damper.norm();  // N
  if (size > ft_max) damper *= ft_max / size;
  ft_max -= std::min(size, ft_max);
  dissipated -= damper.dot(vt) * dt;
  return damper;
}

// s, how long the spring beside the dashpot is on over a step in which the dashpot's share stops
// taking the whole cap: held at zero while it did (c0 = mu fp - nu_t_w |vt| <= 0 at n, N), it
// loads only from where that margin crossed zero on its way to c1 > 0 at n+1 (a line over the
// step). Counted from the step's start it would hold kt vt dt, not kt vt tau, an O(dt) excess
// the stick keeps to its end (oblique 45 deg with damp_tangential 0.3: first order below 1e-4).
inline double share_opened_time(double c0, double c1, double dt) {
  if (c0 > 0.0 || c1 <= 0.0) return dt;
  return dt * c1 / (c1 - c0);
}

}  // namespace polydem
