#include "contact/restitution.hpp"

#include <cmath>
#include <stdexcept>

namespace polydem {

double scaled_contact_duration(double alpha) {
  if (alpha < 1.0) return 2.0 * std::acos(alpha) / std::sqrt((1.0 - alpha) * (1.0 + alpha));
  if (alpha == 1.0) return 2.0;  // critical damping: the limit of both branches
  return 2.0 * std::acosh(alpha) / std::sqrt((alpha - 1.0) * (alpha + 1.0));
}

double restitution_for_damping_ratio(double alpha) {
  if (!(alpha >= 0.0)) throw std::invalid_argument("restitution_for_damping_ratio: alpha < 0");
  if (std::isinf(alpha)) return 0.0;
  return std::exp(-alpha * scaled_contact_duration(alpha));
}

double damping_ratio_for_restitution(double en) {
  if (!(en > 0.0 && en <= 1.0))
    throw std::invalid_argument("damping_ratio_for_restitution: en not in (0, 1]");
  if (en == 1.0) return 0.0;
  // en(alpha) falls from 1 (alpha = 0) to 0 (en ~ 1/(4 alpha^2) for large alpha): bracket, then bisect.
  double lo = 0.0, hi = 1.0;
  while (restitution_for_damping_ratio(hi) > en) {
    lo = hi;
    hi *= 2.0;
  }
  for (int iteration = 0; iteration < 200 && hi - lo > 1e-15 * hi; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (restitution_for_damping_ratio(mid) > en ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace polydem
