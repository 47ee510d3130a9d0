#include "contact/law.hpp"

#include <cmath>

#include "contact/hertz_restitution.hpp"
#include "contact/restitution.hpp"

namespace polydem {

namespace {

// -, the damping ratio: damp_rate as given, else solved from en for the law's normal part.
double damping_ratio(const ContactParams& p) {
  if (p.damp_rate >= 0.0) return p.damp_rate;
  return p.hertz ? hertz_damping_ratio_for_restitution(p.en) : damping_ratio_for_restitution(p.en);
}

// Pa, 1/((1 - nu_a^2)/E_a + (1 - nu_b^2)/E_b) and Mindlin's 1/((2 - nu_a)/G_a + (2 - nu_b)/G_b),
// G = E/(2 (1 + nu)) (as LIGGGHTS youngsModulus/poissonsRatio).
void combine_moduli(const ContactParams& a, const ContactParams& b, LawParams& law) {
  law.e_star = 1.0 / ((1.0 - a.poisson * a.poisson) / a.young + (1.0 - b.poisson * b.poisson) / b.young);
  const double g_a = a.young / (2.0 * (1.0 + a.poisson)), g_b = b.young / (2.0 * (1.0 + b.poisson));  // Pa
  law.g_star = 1.0 / ((2.0 - a.poisson) / g_a + (2.0 - b.poisson) / g_b);
}

}  // namespace

// The ranges were checked once, by the parser (io/scene_forces.cpp), where file, line and key are known.
LawParams prepare_law(const ContactParams& p, const ContactParams* particle) {
  LawParams law{};
  law.kn = p.kn;
  law.kt = p.kt;
  law.kr = p.kr;
  law.mur = p.mur;
  law.mu = p.mu;
  law.alpha_n = damping_ratio(p);
  law.tangential_damping = p.damp_tangential > 0.0 && p.mu > 0.0 && p.kt > 0.0;
  law.alpha_t = law.tangential_damping ? p.damp_tangential : 0.0;
  law.fc = p.fc;
  law.dncut = p.fc > 0.0 ? p.dncut : 0.0;
  law.cohesion = p.fc > 0.0;
  law.rolling = p.kr > 0.0 && p.mur > 0.0;  // SPEC: mur = 0 (the default) turns rolling off
  law.contact_mass = p.damping_contact_mass;
  if (p.hertz) {
    law.normal = NormalModel::hertz;
    combine_moduli(particle ? *particle : p, p, law);
  }
  return law;
}

double critical_time_step(double kn, double m_eff, double alpha_n) {
  const double omega = std::sqrt(kn / m_eff);  // rad/s
  return 2.0 / omega * (std::sqrt(1.0 + alpha_n * alpha_n) - alpha_n);
}

}  // namespace polydem
