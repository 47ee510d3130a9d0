#include "sim/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace polydem {

TimeStepEstimate estimate_time_step(const Bodies& bodies, const std::vector<Shape>& shapes,
                                    const LawParams& particle, const LawParams* driver,
                                    std::optional<double> given_dt) {
  double m_rot = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    const double l = shapes[bodies.shape[b]].bounding_radius * bodies.scale[b];
    const double i_min = bodies.inertia[b].minCoeff();
    m_rot = std::min(m_rot, 1.0 / (1.0 / bodies.mass[b] + l * l / i_min));
  }
  TimeStepEstimate e;
  e.m_eff = m_rot;
  double limit = std::numeric_limits<double>::infinity();
  if (bodies.size() > 1 && particle.kn > 0) limit = critical_time_step(particle.kn, 0.5 * m_rot, particle.alpha_n);
  if (driver && driver->kn > 0) limit = std::min(limit, critical_time_step(driver->kn, m_rot, driver->alpha_n));
  e.critical = limit;
  e.chosen = given_dt ? *given_dt : kAutoFraction * limit;
  return e;
}

}  // namespace polydem
