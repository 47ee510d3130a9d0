#pragma once
// Restitution of the linear spring-dashpot law with the no-pull clamp, and its inverse.
//
// Binary impact, overlap x = -dn, m_eff x'' = -fn, fn = max(kn x + nu x', 0), nu = 2 alpha
// sqrt(kn m_eff): the body separates when the clamp releases (kn x + nu x' = 0), before x
// returns to 0, so the textbook en = exp(-alpha pi / sqrt(1 - alpha^2)) does not hold.
// Both functions are independent of kn and m_eff.

namespace polydem {

// Scaled contact duration w0 t_c (w0 = sqrt(kn/m_eff)) until the clamp releases:
// (pi - 2 asin a)/sqrt(1 - a^2) = 2 acos(a)/sqrt(1 - a^2) for a < 1, 2 at a = 1,
// 2 acosh(a)/sqrt(a^2 - 1) for a > 1 (derivation in tests/contact/test_law_restitution.cpp).
double scaled_contact_duration(double alpha);

// en = exp(-alpha w0 t_c): |x'(t_c)| = v0 exp(-alpha w0 t_c) at the release, for every alpha >= 0.
double restitution_for_damping_ratio(double alpha);

// The alpha >= 0 that gives back en in (0, 1] (bisection on a monotone function, ~1e-15 relative).
double damping_ratio_for_restitution(double en);

}  // namespace polydem
