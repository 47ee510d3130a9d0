#include "sim/time_step.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

namespace polydem {

namespace {

// Smallest effective mass a normal contact force meets on body b: at a contact point r from
// the centre with normal n, 1/m_eff = 1/m + (r x n)^T I^-1 (r x n). For a vertex contact
// r x n = v x n (the rounding lies along n), and over all n perpendicular to v it peaks at
// |v|^2 times the largest eigenvalue of I^-1 restricted to the plane normal to v.
double contact_point_mass(const Shape& shape, double scale, double mass, const Vec3& inertia) {
  const Mat3 inv_inertia = inertia.cwiseInverse().asDiagonal();
  double worst = 0.0;  // 1/kg, largest rotational compliance
  for (const Vec3& vertex : shape.vertices) {
    const Vec3 v = vertex * scale;
    if (v.squaredNorm() == 0.0) continue;  // a sphere's centre: the force passes through it
    const Vec3 e1 = v.unitOrthogonal(), e2 = v.normalized().cross(e1);
    Eigen::Matrix2d plane;
    plane << e1.dot(inv_inertia * e1), e1.dot(inv_inertia * e2), e2.dot(inv_inertia * e1), e2.dot(inv_inertia * e2);
    const double top = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(plane).eigenvalues().maxCoeff();
    worst = std::max(worst, v.squaredNorm() * top);
  }
  return 1.0 / (1.0 / mass + worst);
}

}  // namespace

TimeStepEstimate estimate_time_step(const Bodies& bodies, const std::vector<Shape>& shapes,
                                    const LawParams& particle, const LawParams* driver,
                                    std::optional<double> given_dt) {
  double m_rot = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < bodies.size(); ++b)
    m_rot = std::min(m_rot, contact_point_mass(shapes[bodies.shape[b]], bodies.scale[b], bodies.mass[b], bodies.inertia[b]));
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
