#pragma once
// Cohesion part (SPEC "cohesion"): -fc_w inside the overlap, fc_w (dn/dncut - 1) in the band
// 0 <= dn < dncut beyond touching, 0 past it. Coefficients: LawParams::fc (N), dncut (m).
// Conservative within one linear piece: stored as a potential (negative: energy is needed to
// pull the pair apart); weight changes dissipate. No stability limit of its own.
#include "contact/law/types.hpp"

namespace polydem {

// N (negative: attractive).
inline double cohesion_force(double fc_w, double dncut, double dn) {
  return dn < 0.0 ? -fc_w : fc_w * (dn / dncut - 1.0);
}
// J, potential of cohesion_force (zero at dncut, -fc_w dncut/2 at touching, slope fc_w inside).
inline double cohesion_potential(double fc_w, double dncut, double dn) {
  if (dn < 0.0) return fc_w * (dn - 0.5 * dncut);
  if (dn >= dncut) return 0.0;
  const double rest = dncut - dn;
  return -0.5 * fc_w * rest * rest / dncut;
}

// J, cohesion potential at gap dn with weight w, 0 beyond the band.
inline double cohesion_energy(const LawParams& law, double w, double dn) {
  return dn < law.dncut ? cohesion_potential(w * law.fc, law.dncut, dn) : 0.0;
}

// J, cohesion over the step from gap dn0 to dn1 (weights w0, w1): trapezoid work taken from
// the bodies minus the potential gained (0 within one linear piece at a fixed weight).
inline double cohesion_dissipated(const LawParams& law, double w0, double dn0, double w1, double dn1) {
  const double f0 = dn0 < law.dncut ? cohesion_force(w0 * law.fc, law.dncut, dn0) : 0.0;
  const double f1 = dn1 < law.dncut ? cohesion_force(w1 * law.fc, law.dncut, dn1) : 0.0;
  return 0.5 * (f0 + f1) * (dn0 - dn1) + cohesion_energy(law, w0, dn0) - cohesion_energy(law, w1, dn1);
}

}  // namespace polydem
