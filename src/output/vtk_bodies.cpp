#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <stdexcept>

#include "output/appended.hpp"
#include "output/vtk.hpp"

namespace polydem {

namespace {

constexpr std::uint8_t kVtkPolygon = 7;

struct UnitMesh {
  std::vector<Vec3> points;
  std::vector<std::vector<int>> faces;  // counter-clockwise seen from outside
};

// Icosahedron subdivided once: 42 unit vectors, 80 triangles. It holds the six +-axis points,
// so a sphere's bounds are exact when the body is not rotated.
UnitMesh make_icosphere() {
  const double t = 0.5 * (1.0 + std::sqrt(5.0));
  UnitMesh m;
  m.points = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
              {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  const std::array<std::array<int, 3>, 20> ico = {{{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11},
                                                   {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                                   {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8}, {3, 8, 9},
                                                   {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}}};
  std::map<std::pair<int, int>, int> midpoint;
  auto mid = [&](int a, int b) {
    const auto key = std::minmax(a, b);
    auto [it, fresh] = midpoint.try_emplace(key, int(m.points.size()));
    if (fresh) m.points.push_back(0.5 * (m.points[a] + m.points[b]));
    return it->second;
  };
  for (const auto& f : ico) {
    const int ab = mid(f[0], f[1]), bc = mid(f[1], f[2]), ca = mid(f[2], f[0]);
    m.faces.insert(m.faces.end(), {{f[0], ab, ca}, {f[1], bc, ab}, {f[2], ca, bc}, {ab, bc, ca}});
  }
  for (Vec3& p : m.points) p.normalize();
  return m;
}

// The faceless shape as the sphere swept over its vertices: each icosphere direction d maps to
// the support point of the rounded body, argmax_v(v.d) + radius d. Triangles stay planar, so
// the result is a closed surface (a sphere for 1 vertex, a capsule for 2).
UnitMesh swept_sphere(const Shape& s) {
  static const UnitMesh sphere = make_icosphere();
  UnitMesh m = sphere;
  for (Vec3& d : m.points) {
    std::size_t best = 0;
    for (std::size_t k = 1; k < s.vertices.size(); ++k)
      if (s.vertices[k].dot(d) > s.vertices[best].dot(d)) best = k;
    d = s.vertices[best] + s.radius * d;
  }
  return m;
}

// Appends `part` to `m`, its corner indices shifted past m's points.
void append(UnitMesh& m, const UnitMesh& part) {
  const int base = int(m.points.size());
  m.points.insert(m.points.end(), part.points.begin(), part.points.end());
  for (std::vector<int> f : part.faces) {
    for (int& i : f) i += base;
    m.faces.push_back(std::move(f));
  }
}

// The open side of a cylinder of radius r around segment [a, b]: kSides quads.
UnitMesh tube(const Vec3& a, const Vec3& b, double r) {
  constexpr int kSides = 16;
  const Vec3 t = (b - a).normalized();
  const Vec3 u = t.unitOrthogonal(), w = t.cross(u);
  UnitMesh m;
  for (int k = 0; k < kSides; ++k) {
    const double phi = 2.0 * kPi * k / kSides;
    const Vec3 d = r * (std::cos(phi) * u + std::sin(phi) * w);
    m.points.push_back(a + d);
    m.points.push_back(b + d);
  }
  for (int k = 0; k < kSides; ++k) {
    const int k1 = (k + 1) % kSides;
    m.faces.push_back({2 * k, 2 * k1, 2 * k1 + 1, 2 * k + 1});  // counter-clockwise seen from outside
  }
  return m;
}

// A polyline or a cluster drawn as what it is: a sphere per vertex and a tube per edge (their
// overlaps drawn twice), not the hull of the swept spheres.
UnitMesh tubes_and_spheres(const Shape& s) {
  static const UnitMesh sphere = make_icosphere();
  UnitMesh m;
  for (const Vec3& v : s.vertices) {
    UnitMesh ball = sphere;
    for (Vec3& p : ball.points) p = v + s.radius * p;
    append(m, ball);
  }
  for (const auto& e : s.edges) append(m, tube(s.vertices[e[0]], s.vertices[e[1]], s.radius));
  return m;
}

// Per shape, the polygons to draw in the principal frame at scale 1: the core's faces, the
// rounded surface of a convex body (`rounded`, or no faces), or a polyline's or cluster's
// spheres and tubes.
std::vector<UnitMesh> shape_meshes(const std::vector<Shape>& shapes, bool rounded) {
  std::vector<UnitMesh> out;
  out.reserve(shapes.size());
  for (const Shape& s : shapes) {
    if (s.faces.empty() && !s.convex)
      out.push_back(tubes_and_spheres(s));
    else if (s.faces.empty() || (rounded && s.convex))
      out.push_back(swept_sphere(s));
    else
      out.push_back(UnitMesh{s.vertices, s.faces});
  }
  return out;
}

std::size_t corner_count(const UnitMesh& m) {
  std::size_t n = 0;
  for (const std::vector<int>& f : m.faces) n += f.size();
  return n;
}

int checked_shape(const Bodies& bodies, std::size_t b, std::size_t n_shapes) {
  const int s = bodies.shape[b];
  if (s < 0 || std::size_t(s) >= n_shapes)
    throw std::out_of_range("write_bodies_vtu: body " + std::to_string(bodies.id[b]) + " has shape index " + std::to_string(s) +
                            " of " + std::to_string(n_shapes));
  return s;
}

// The arrays of the .vtu, filled body by body.
struct BodyArrays {
  std::vector<Vec3> points, velocity, angular_velocity;
  CellTopology cells;
  std::vector<std::int64_t> id;
  std::vector<std::int32_t> group;
  std::vector<double> radius;

  // Sized up front: a frame of 10^5 bodies is 10^6 cells, and regrowth doubles its memory traffic.
  void reserve(const Bodies& bodies, const std::vector<std::uint32_t>& ids, const std::vector<UnitMesh>& meshes) {
    std::size_t n_points = 0, n_cells = 0, n_corners = 0;
    for (std::uint32_t b : ids) {
      const UnitMesh& m = meshes[checked_shape(bodies, b, meshes.size())];
      n_points += m.points.size();
      n_cells += m.faces.size();
      n_corners += corner_count(m);
    }
    points.reserve(n_points);
    cells.connectivity.reserve(n_corners);
    cells.offsets.reserve(n_cells);
    for (auto* v : {&velocity, &angular_velocity}) v->reserve(n_cells);
    id.reserve(n_cells);
    group.reserve(n_cells);
    radius.reserve(n_cells);
  }

  void add(const Bodies& bodies, std::size_t b, const UnitMesh& m, double rounded_radius) {
    const double scale = bodies.scale[b];
    const Mat3 rotation = bodies.orientation[b].toRotationMatrix();
    const std::int64_t base = std::int64_t(points.size());
    for (const Vec3& p : m.points) points.push_back(bodies.position[b] + rotation * (scale * p));
    for (const std::vector<int>& f : m.faces) cells.add_cell(f, base);
    const std::size_t n = m.faces.size();
    id.insert(id.end(), n, std::int64_t(bodies.id[b]));
    group.insert(group.end(), n, std::int32_t(bodies.group[b]));
    radius.insert(radius.end(), n, rounded_radius * scale);
    velocity.insert(velocity.end(), n, bodies.velocity[b]);
    angular_velocity.insert(angular_velocity.end(), n, bodies.angular_velocity[b]);
  }

  // The <Piece> element; the arrays move into `data`.
  std::string piece_xml(AppendedData& data) {
    const std::size_t n_cells = id.size();
    // One array per statement: offsets then ascend in file order.
    std::string xml = "<Piece NumberOfPoints=\"" + std::to_string(points.size()) + "\" NumberOfCells=\"" +
                      std::to_string(n_cells) + "\">\n<Points>\n";
    xml += data.array("Points", std::move(points));
    xml += "</Points>\n<Cells>\n";
    xml += topology_xml(data, std::move(cells));
    xml += data.array("types", std::vector<std::uint8_t>(n_cells, kVtkPolygon));
    xml += "</Cells>\n<CellData Scalars=\"id\" Vectors=\"velocity\">\n";
    xml += data.array("id", std::move(id));
    xml += data.array("group", std::move(group));
    xml += data.array("radius", std::move(radius));
    xml += data.array("velocity", std::move(velocity));
    xml += data.array("angular_velocity", std::move(angular_velocity));
    return xml + "</CellData>\n</Piece>\n";
  }
};

}  // namespace

void write_bodies_vtu(const std::string& path, const Bodies& bodies, const std::vector<Shape>& shapes, bool rounded,
                      const std::optional<Vec3>& gravity) {
  write_bodies_piece(path, bodies, bodies.by_user_id(), shapes, rounded, gravity);
}

void write_bodies_piece(const std::string& path, const Bodies& bodies, const std::vector<std::uint32_t>& ids,
                        const std::vector<Shape>& shapes, bool rounded, const std::optional<Vec3>& gravity) {
  const std::vector<UnitMesh> meshes = shape_meshes(shapes, rounded);
  BodyArrays arrays;
  arrays.reserve(bodies, ids, meshes);
  for (std::uint32_t b : ids) {
    const int s = bodies.shape[b];
    arrays.add(bodies, b, meshes[s], shapes[s].radius);
  }
  AppendedData data;
  std::string xml;
  if (gravity) xml = "<FieldData>\n" + data.field_array("gravity", {*gravity}) + "</FieldData>\n";
  xml += arrays.piece_xml(data);
  data.write_file(path, "UnstructuredGrid", xml);
}

}  // namespace polydem
