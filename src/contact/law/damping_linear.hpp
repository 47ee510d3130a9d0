#pragma once
// Damping part, linear dashpot: f_d = -nu_w vn, nu = 2 alpha_n sqrt(kn m_eff) (N s/m) per
// pair, nu_w = w nu. Coefficient: LawParams::alpha_n, from damp_rate as given or from en
// (restitution.cpp solves the clamped law). Dissipates (f_d(n) + f_d(n+1))/2 (x(n+1) - x(n)).
// Normal and damping share the no-pull clamp: fn = max(kn_w x - nu_w vn, 0).
#include <algorithm>
#include <cmath>

#include "contact/law/types.hpp"

namespace polydem {

// N s/m, the dashpot coefficient of a pair of effective mass m_eff (kg), before patch weights.
inline double pair_damping(const LawParams& law, double m_eff) { return 2.0 * law.alpha_n * std::sqrt(law.kn * m_eff); }

// N, the clamped normal force for overlap x > 0: max(spring - nu_w vn, 0) (no pull).
inline double normal_damped(double spring, double nu_w, double vn) { return std::max(spring - nu_w * vn, 0.0); }

// s, the velocity Verlet stability limit of the contact oscillator w0 = sqrt(kn/m_eff):
// dt < 2/w0 (sqrt(1 + a^2) - a) with a dashpot of ratio a evaluated from the half-step
// velocity (Belytschko, Liu & Moran, Nonlinear Finite Elements, 2000: central difference
// with damping). For a = 0 this is 2 sqrt(m_eff/kn) = T/pi, T = 2 pi sqrt(m_eff/kn) the
// undamped period. The kernel's dashpot reads the end-of-step velocity with its own force
// implicit (second_order.hpp), stable up to T/pi for any damping (test_law_energy.cpp): this
// bound is below that and stays the step policy's reference. Use a fraction of it.
double critical_time_step(double kn, double m_eff, double alpha_n = 0.0);

}  // namespace polydem
