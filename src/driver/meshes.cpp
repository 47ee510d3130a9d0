// Driver surfaces as polygon meshes for the VTK output, at their current placement.
#include <cmath>

#include "driver/drivers.hpp"
#include "driver/mesh.hpp"
#include "output/frame.hpp"
#include "output/vtk.hpp"

namespace polydem {

namespace {

constexpr int kSegments = 48;  // around a cylinder or a ball: smooth enough to look round

DriverMesh wall_mesh(const Driver& d, const ViewFrame& frame) {
  std::vector<Vec3> corners = framed_wall(d.point, d.normal, d.spec.size, frame);
  std::vector<int> polygon(corners.size());
  for (std::size_t k = 0; k < corners.size(); ++k) polygon[k] = int(k);
  return {d.spec.name, std::move(corners), {polygon}};
}

DriverMesh cylinder_mesh(const Driver& d, const ViewFrame& frame) {
  const auto [from, to] = framed_axis(d.center, d.axis, d.spec.length, frame);  // m along the axis
  const Vec3 u = d.axis.unitOrthogonal(), w = d.axis.cross(u);
  DriverMesh m{d.spec.name, {}, {}};
  for (int k = 0; k < kSegments; ++k) {
    const double angle = 2.0 * kPi * k / kSegments;
    const Vec3 r = d.spec.radius * (std::cos(angle) * u + std::sin(angle) * w);
    m.points.push_back(d.center + r + from * d.axis);
    m.points.push_back(d.center + r + to * d.axis);
  }
  for (int k = 0; k < kSegments; ++k) {
    const int next = (k + 1) % kSegments;
    m.polygons.push_back({2 * k, 2 * next, 2 * next + 1, 2 * k + 1});
  }
  return m;
}

DriverMesh ball_mesh(const Driver& d) {
  const int rings = kSegments / 2;
  const Vec3 u = Vec3::UnitX(), w = Vec3::UnitY(), z = Vec3::UnitZ();
  DriverMesh m{d.spec.name, {}, {}};
  for (int i = 0; i <= rings; ++i) {
    const double polar = kPi * i / rings;
    for (int k = 0; k < kSegments; ++k) {
      const double az = 2.0 * kPi * k / kSegments;
      m.points.push_back(d.center + d.spec.radius * (std::sin(polar) * (std::cos(az) * u + std::sin(az) * w) +
                                                     std::cos(polar) * z));
    }
  }
  for (int i = 0; i < rings; ++i)
    for (int k = 0; k < kSegments; ++k) {
      const int next = (k + 1) % kSegments;
      m.polygons.push_back({i * kSegments + k, i * kSegments + next, (i + 1) * kSegments + next, (i + 1) * kSegments + k});
    }
  return m;
}

DriverMesh stl_mesh(const Driver& d) {
  DriverMesh m{d.spec.name, {}, {}};
  for (const Vec3& v : d.mesh->vertices) m.points.push_back(d.center + d.orientation * v);
  for (const std::array<int, 3>& t : d.mesh->faces) m.polygons.push_back({t[0], t[1], t[2]});
  return m;
}

}  // namespace

std::vector<DriverMesh> Drivers::meshes(const ViewFrame& frame) const {
  std::vector<DriverMesh> out;
  for (const Driver& d : list_) {
    if (!d.active) continue;
    switch (d.spec.kind) {
      case DriverSpec::Kind::wall: out.push_back(wall_mesh(d, frame)); break;
      case DriverSpec::Kind::cylinder: out.push_back(cylinder_mesh(d, frame)); break;
      case DriverSpec::Kind::ball: out.push_back(ball_mesh(d)); break;
      case DriverSpec::Kind::stl: out.push_back(stl_mesh(d)); break;
    }
  }
  return out;
}

}  // namespace polydem
