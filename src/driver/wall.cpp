#include "driver/wall.hpp"

#include "output/vtk.hpp"

namespace polydem {

Wall::Wall(const WallSettings& s, Placement& at) : size_(s.size) {
  at.point = s.point;
  at.normal = s.normal.normalized();
}

void Wall::candidates(const Placement& at, const PosedBody& a, double range, std::vector<FeaturePair>& out) const {
  for (std::size_t v = 0; v < a.shape->vertices.size(); ++v)
    if ((a.vertices[v] - at.point).dot(at.normal) < a.radius + range)
      out.push_back({PairType::vertex_face, std::uint16_t(v), 0});
}

DriverMesh Wall::drawing(const Placement& at, const std::string& name, const ViewFrame& frame) const {
  std::vector<Vec3> corners = framed_wall(at.point, at.normal, size_, frame);
  std::vector<int> polygon(corners.size());
  for (std::size_t k = 0; k < corners.size(); ++k) polygon[k] = int(k);
  return {name, std::move(corners), {polygon}};
}

}  // namespace polydem
