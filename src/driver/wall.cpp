#include "driver/wall.hpp"

#include "output/vtk.hpp"

namespace polydem {

Wall::Wall(const WallSettings& s, Placement& at) {
  at.point = s.point;
  at.normal = s.normal.normalized();
}

void Wall::candidates(const Placement& at, const PosedBody& a, double range, std::vector<FeaturePair>& out) const {
  for (std::size_t v = 0; v < a.shape->vertices.size(); ++v)
    if ((a.vertices[v] - at.point).dot(at.normal) < a.radius + range)
      out.push_back({PairType::vertex_face, std::uint16_t(v), 0});
}

bool Wall::contact(const Placement& at, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) const {
  const Vec3& v = a.vertices[f.a];
  const double height = (v - at.point).dot(at.normal);  // m, vertex above the plane
  const double gap = height - a.radius;
  if (gap >= max_gap) return false;
  out.normal = at.normal;
  out.gap = gap;
  out.point = v - at.normal * (a.radius + 0.5 * gap);  // middle of the overlap
  return true;
}

DriverMesh Wall::drawing(const Placement& at, const std::string& name, double extent) const {
  const Vec3 u = at.normal.unitOrthogonal() * extent;
  const Vec3 w = at.normal.cross(u);
  return {name, {at.point - u - w, at.point + u - w, at.point + u + w, at.point - u + w}, {{0, 1, 2, 3}}};
}

}  // namespace polydem
