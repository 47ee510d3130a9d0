#include "field/void_fraction.hpp"

#include <limits>

#include "polydem/parallel.hpp"

namespace polydem {

namespace {

double segment_distance(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const double t = ab.squaredNorm() > 0.0 ? std::clamp((x - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
  return (x - a - t * ab).norm();
}

Vec3 face_normal(const Shape& s, const std::vector<int>& f) {  // Newell's method, outward
  Vec3 n = Vec3::Zero();
  for (std::size_t k = 0; k < f.size(); ++k) n += s.vertices[f[k]].cross(s.vertices[f[(k + 1) % f.size()]]);
  return n.normalized();
}

}  // namespace

double core_distance(const Shape& s, const Vec3& x) {
  // Only a closed convex core is the intersection of its faces' half-spaces; a non-convex body
  // is the union of its swept elements, as its mass (shape/union_mass.hpp): no interior.
  bool inside = s.convex && !s.surface && s.faces.size() >= 4;
  double d = std::numeric_limits<double>::infinity();
  for (const std::vector<int>& f : s.faces) {
    const Vec3 n = face_normal(s, f);
    const double h = n.dot(x - s.vertices[f[0]]);
    inside = inside && h <= 0.0;
    bool over = true;  // x projects inside the (convex, counter-clockwise) face
    for (std::size_t k = 0; k < f.size() && over; ++k) {
      const Vec3& a = s.vertices[f[k]];
      over = (s.vertices[f[(k + 1) % f.size()]] - a).cross(x - a).dot(n) >= 0.0;
    }
    if (over) d = std::min(d, std::abs(h));
  }
  if (inside) return 0.0;
  for (const Vec3& v : s.vertices) d = std::min(d, (x - v).norm());
  for (const auto& e : s.edges) d = std::min(d, segment_distance(x, s.vertices[e[0]], s.vertices[e[1]]));
  return d;
}

std::vector<Vec3> shape_samples(const Shape& s, int n) {
  Vec3 lo = s.vertices[0], hi = s.vertices[0];
  for (const Vec3& v : s.vertices) { lo = lo.cwiseMin(v); hi = hi.cwiseMax(v); }
  lo.array() -= s.radius;
  hi.array() += s.radius;
  const Vec3 step = (hi - lo) / double(n);
  std::vector<Vec3> points;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const Vec3 x = lo + Vec3(i + 0.5, j + 0.5, k + 0.5).cwiseProduct(step);
        if (core_distance(s, x) <= s.radius) points.push_back(x);
      }
  if (points.empty()) points.push_back(Vec3::Zero());
  return points;
}

VoidFraction::VoidFraction(const std::vector<Shape>& shapes, int samples, double alpha_min) : alpha_min_(alpha_min) {
  for (const Shape& s : shapes) {
    samples_.push_back(shape_samples(s, samples));
    volume_.push_back(s.volume);
    reach_.push_back(s.bounding_radius);
  }
}

template <class Fn>
void VoidFraction::for_samples(const FieldBodies& rows, std::size_t b, const Fn& fn) const {
  const std::vector<Vec3>& pts = samples_[rows.shape[b]];
  const double scale = rows.scale[b];
  const double share = volume_[rows.shape[b]] * scale * scale * scale / double(pts.size());  // m^3
  const Mat3 R = rows.orientation[b].toRotationMatrix() * scale;
  for (const Vec3& p : pts) fn(rows.position[b] + R * p, share);
}

void VoidFraction::particle_volumes(const FluidGrid& grid, const FieldBodies& rows, std::vector<double>& vs) const {
  vs.resize(rows.size);
  const Vec3 lo = grid.origin, hi = grid.origin + grid.spacing.cwiseProduct(grid.cells.cast<double>());
  parallel_for(rows.size, [&](std::size_t b) {
    if (!rows.owned(b)) return;
    const double reach = reach_[rows.shape[b]] * rows.scale[b];
    const Vec3& x = rows.position[b];
    if ((x.array() - reach > lo.array()).all() && (x.array() + reach < hi.array()).all()) {
      const double s = rows.scale[b];
      vs[b] = volume_[rows.shape[b]] * s * s * s;  // wholly inside: no sampling needed
      return;
    }
    double v = 0.0;
    for_samples(rows, b, [&](const Vec3& p, double share) { if (grid.locate(p)) v += share; });
    vs[b] = v;
  });
}

VoidFractionField VoidFraction::field(const FluidGrid& grid, const Bodies& bodies) const {
  VoidFractionField f;
  f.alpha.assign(grid.size(), 1.0);
  const double cell = grid.cell_volume();
  const FieldBodies rows = field_rows(bodies);
  for (std::size_t b = 0; b < rows.size; ++b)  // in order: the floor makes the result order-dependent
    for_samples(rows, b, [&](const Vec3& p, double share) {
      const std::optional<Index3> c = grid.locate(p);
      if (!c) return;
      double& alpha = f.alpha[grid.index(*c)];
      const double next = alpha - share / cell;
      if (next > alpha_min_) {
        alpha = next;
      } else {
        f.excess += (alpha_min_ - next) * cell;
        alpha = alpha_min_;
      }
    });
  return f;
}

}  // namespace polydem
