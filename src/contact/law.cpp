#include "contact/law.hpp"

#include <cmath>
#include <string>

#include "contact/restitution.hpp"
#include "polydem/error.hpp"

namespace polydem {

namespace {

[[noreturn]] void reject(const std::string& key, const std::string& message) {
  throw InputError(input_message("", 0, key, message));
}

void require_non_negative(const std::string& key, double value) {
  if (!(value >= 0.0 && std::isfinite(value)))
    reject(key, "must be a finite number >= 0, got " + std::to_string(value));
}

// The damping ratio from exactly one of en and damp_rate (< 0 means "not given").
double damping_ratio(const ContactParams& p) {
  const bool has_en = p.en >= 0.0, has_rate = p.damp_rate >= 0.0;
  if (has_en && has_rate) reject("en", "give en or damp_rate, not both (en is the restitution you get)");
  if (!has_en && !has_rate) reject("en", "missing: give en (restitution, e.g. en: 0.5) or damp_rate");
  if (has_rate) {
    require_non_negative("damp_rate", p.damp_rate);
    return p.damp_rate;
  }
  if (!(p.en > 0.0 && p.en <= 1.0))
    reject("en", "must be in (0, 1], got " + std::to_string(p.en) + " (1: elastic)");
  return damping_ratio_for_restitution(p.en);
}

}  // namespace

LawParams prepare_law(const ContactParams& p) {
  require_non_negative("kn", p.kn);
  if (p.kn == 0.0) reject("kn", "must be > 0 (normal stiffness, N/m)");
  require_non_negative("kt", p.kt);
  require_non_negative("kr", p.kr);
  require_non_negative("mur", p.mur);
  require_non_negative("mu", p.mu);
  require_non_negative("fc", p.fc);
  require_non_negative("dncut", p.dncut);
  if (p.mu > 0.0 && p.kt == 0.0)
    reject("kt", "must be > 0 when mu > 0, or friction is lost (kt = kn is common)");
  if (p.mur > 0.0 && p.kr == 0.0) reject("kr", "must be > 0 when mur > 0 (rolling stiffness, N m/rad)");
  if (!(p.damp_tangential >= 0.0 && p.damp_tangential < 1.0))
    reject("damp_tangential", "must be in [0, 1), got " + std::to_string(p.damp_tangential));
  if (p.fc > 0.0 && p.dncut == 0.0)
    reject("dncut", "must be > 0 when fc > 0 (width of the cohesion band, m)");
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
  return law;
}

double critical_time_step(double kn, double m_eff, double alpha_n) {
  const double omega = std::sqrt(kn / m_eff);  // rad/s
  return 2.0 / omega * (std::sqrt(1.0 + alpha_n * alpha_n) - alpha_n);
}

}  // namespace polydem
