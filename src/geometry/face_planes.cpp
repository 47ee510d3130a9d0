#include "geometry/face_planes.hpp"

#include "geometry/segment.hpp"

namespace polydem {

void derive_face_planes(Shape& s) {
  s.edge_planes.clear();
  s.edge_plane_begin.assign(1, 0);
  for (std::size_t f = 0; f < s.faces.size(); ++f) {
    const Vec3& n = s.face_normals[f];
    int from = s.faces[f].back();
    for (const int to : s.faces[f]) {
      const Vec3 e = s.vertices[to] - s.vertices[from];  // m, edge in face order
      const Vec3 inward = n.cross(e).normalized();        // in the face plane
      s.edge_planes.push_back({inward, inward.dot(s.vertices[from]) + kInteriorMargin * e.norm()});
      from = to;
    }
    s.edge_plane_begin.push_back(static_cast<int>(s.edge_planes.size()));
  }
}

}  // namespace polydem
