#include "neighbor/rebuild_trigger.hpp"

#include <stdexcept>
#include <string>

namespace polydem {
namespace {

// Bodies below which the check runs on one thread: forking (~10 us) costs more than the loop
// (~30 ns a body).
constexpr std::size_t kMinParallel = 1024;

}  // namespace

double displacement_bound(const Vec3& dx, const Quat& q_now, const Quat& q_built,
                          double bounding_radius) {
  if (bounding_radius == 0.0) return dx.norm();  // a point (a sphere's core): turning moves it nowhere
  const Quat q_rel = q_now * q_built.conjugate();
  // sin(theta/2) = |vector part| of the unit relative rotation; dividing by the norm forgives
  // quaternions that drifted slightly off unit length.
  const double sin_half = q_rel.vec().norm() / q_rel.norm();
  return dx.norm() + 2.0 * bounding_radius * sin_half;
}

void RebuildTrigger::mark_built(const std::vector<Vec3>& x, const std::vector<Quat>& q) {
  if (x.size() != q.size()) {
    throw std::invalid_argument("mark_built: " + std::to_string(x.size()) + " positions but " +
                                std::to_string(q.size()) + " orientations");
  }
  x_built = x;
  q_built = q;
  displacement_.assign(x.size(), 0.0);
  ++rebuild_count;
}

bool RebuildTrigger::needs_rebuild(const std::vector<Vec3>& x, const std::vector<Quat>& q,
                                   const std::vector<double>& bounding_radius, double skin) {
  const std::size_t n = x.size();
  if (q.size() != n || bounding_radius.size() != n) {
    throw std::invalid_argument("needs_rebuild: sizes of positions, orientations and radii differ");
  }
  if (rebuild_count == 0 || x_built.size() != n) return true;
  const double limit = 0.5 * skin;  // m, each body may use half the skin
  int exceeded = 0;
#pragma omp parallel for schedule(static) reduction(max : exceeded) if (n >= kMinParallel)
  for (std::size_t i = 0; i < n; ++i) {
    const double d = displacement_bound(x[i] - x_built[i], q[i], q_built[i], bounding_radius[i]);
    displacement_[i] = d;
    // Written as !(d <= limit) so a NaN state also asks for a rebuild.
    if (!(d <= limit)) exceeded = 1;
  }
  return exceeded != 0;
}

}  // namespace polydem
