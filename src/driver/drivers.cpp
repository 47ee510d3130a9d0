#include "driver/drivers.hpp"

#include <cmath>

#include "output/vtk.hpp"

namespace polydem {

Drivers::Drivers(const std::vector<DriverSpec>& specs) {
  for (const DriverSpec& s : specs) {
    Driver d;
    d.spec = s;
    d.point = s.point;
    d.normal = s.normal.normalized();
    list_.push_back(d);
  }
}

void Drivers::advance(double t, double dt) {
  for (Driver& d : list_) {
    const Motion& m = d.spec.motion;
    if (m.remove_at && t + dt >= *m.remove_at) d.active = false;
    const bool moving = t >= m.start && (!m.stop || t < *m.stop);
    d.velocity = moving ? m.velocity : Vec3::Zero();
    d.point += d.velocity * dt;
  }
}

bool Drivers::near(std::uint32_t j, const Vec3& center, double reach) const {
  const Driver& d = list_[j];
  return d.active && (center - d.point).dot(d.normal) < reach;
}

void Drivers::candidates(const PosedBody& a, std::uint32_t j, double range,
                         std::vector<FeaturePair>& out) const {
  const Driver& d = list_[j];
  const std::size_t nv = a.shape->vertices.size();
  for (std::size_t v = 0; v < nv; ++v)  // a plane meets a convex body first at its vertices
    if ((a.vertices[v] - d.point).dot(d.normal) < a.radius + range)
      out.push_back({PairType::vertex_face, std::uint16_t(v), 0});
}

bool Drivers::contact(const PosedBody& a, std::uint32_t j, FeaturePair f, double max_gap,
                      ContactPoint& out) const {
  const Driver& d = list_[j];
  const Vec3& v = a.vertices[f.a];
  const double height = (v - d.point).dot(d.normal);  // m, vertex above the plane
  const double gap = height - a.radius;
  if (gap >= max_gap) return false;
  out.normal = d.normal;
  out.gap = gap;
  out.point = v - d.normal * (a.radius + 0.5 * gap);  // middle of the overlap
  return true;
}

std::vector<DriverMesh> Drivers::meshes(double extent) const {
  std::vector<DriverMesh> out;
  for (const Driver& d : list_) {
    if (!d.active) continue;
    const Vec3 u = d.normal.unitOrthogonal() * extent;
    const Vec3 w = d.normal.cross(u);
    out.push_back({d.spec.name, {d.point - u - w, d.point + u - w, d.point + u + w, d.point - u + w},
                   {{0, 1, 2, 3}}});
  }
  return out;
}

}  // namespace polydem
