#pragma once
// Restitution of the Hertz law with the Tsuji dashpot and the no-pull clamp, and its inverse.
//
// m x'' = -fn, fn = max(K x^1.5 + 2 a sqrt(m kn(x)) x', 0), kn(x) = 1.5 K x^0.5: with x = X s,
// t = T tau, X^2.5 = m v0^2/K, T = X/v0 the impact is s'' = -s^1.5 - 2 a sqrt(1.5) s^0.25 s',
// s(0) = 0, s'(0) = 1, whatever m, K and v0: en depends on a alone (Tsuji et al. 1992). No
// closed form: integrated numerically (RK4) until the clamp releases.

namespace polydem {

// en for the damping ratio a >= 0 (1e-6 accurate).
double hertz_restitution_for_damping_ratio(double alpha);

// The a >= 0 that gives back en in (0, 1] (bisection on the monotone function above): ~2.2e9
// instructions a solve.
double solve_hertz_damping_ratio(double en);

// solve_hertz_damping_ratio(en), bit for bit: read from kHertzDampingRatio where en is a
// hundredth (0.01-0.99, as a scene writes it), else solved once per en and kept.
double hertz_damping_ratio_for_restitution(double en);

}  // namespace polydem
