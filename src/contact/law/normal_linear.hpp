#pragma once
// Normal part, linear spring (SPEC "Contact force law"): f = kn_w x, x the overlap (m),
// kn_w = w kn (N/m, the patch share w of the pair's kn). Coefficient: LawParams::kn.
// Stored: 1/2 kn_w x^2. Its stability limit is the damped oscillator's (damping_linear.hpp).
#include <algorithm>

#include "contact/law/damping_linear.hpp"
#include "contact/law/tangential_spring.hpp"

namespace polydem {

// r_star (m, the contact's curvature radius) is unused: the linear law has no geometry.
struct NormalLinear {
  static constexpr bool kCurved = false;  // reads no curvature radius: the kernels skip computing it
  // N, the spring at overlap x (m) with patch weight w.
  [[gnu::always_inline]] static double spring(const LawParams& law, double, double w, double x) { return w * law.kn * x; }
  // J, the energy it stores there.
  static double energy(const LawParams& law, double, double w, double x) {
    const double f = w * law.kn * x;  // N
    return 0.5 * f * x;
  }
  // J, what a weight change w0 -> w1 over a step x0 -> x1 adds to the spring: the change of
  // w U(x) less the trapezoid work, 1/2 kn x0 x1 (w1 - w0) (0 for a lone contact).
  [[gnu::always_inline]] static double patch(const LawParams& law, double, double x0, double x1, double w0, double w1) {
    return 0.5 * law.kn * x0 * x1 * (w1 - w0);
  }
  // N s/m, the pair's dashpot before the weight (damping_linear.hpp), and at overlap x: the same.
  static double pair_damping(const LawParams& law, double m_eff, double) { return polydem::pair_damping(law, m_eff); }
  [[gnu::always_inline]] static double damping(double nu_pair, double) { return nu_pair; }
  // N/m, normal and tangential stiffness for the stability limit: constant, whatever the impact.
  static double impact_stiffness(const LawParams& law, double, double, double) { return law.kn; }
  static double impact_tangential_stiffness(const LawParams& law, double, double, double) { return law.kt; }
  // N/m, the tangential spring's stiffness before the weight (constant: kt).
  [[gnu::always_inline]] static double tangential_stiffness(const LawParams& law, double, double) { return law.kt; }
  // J, what the change of the tangential stiffness (here its weight alone) adds to the spring ft.
  [[gnu::always_inline]] static double tangential_patch(const LawParams& law, double, const Vec3& ft, double, double w0,
                                                        double, double w1) {
    return reweighted(ft, law.kt, w0, w1);
  }
};

}  // namespace polydem
