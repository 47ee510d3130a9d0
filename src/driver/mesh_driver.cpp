#include "driver/mesh_driver.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "driver/mesh.hpp"
#include "geometry/segment.hpp"
#include "output/vtk.hpp"
#include "polydem/error.hpp"
#include "shape/point_sources.hpp"

namespace polydem {

namespace {

Vec3 to_mesh(const Placement& d, const Vec3& p) { return d.orientation.conjugate() * (p - d.center); }
Vec3 to_world(const Placement& d, const Vec3& p) { return d.center + d.orientation * p; }

const Shape& mesh_point_shape() {
  static const Shape s = [] { Shape p; p.vertices = {Vec3::Zero()}; return p; }();
  return s;
}

const Shape& mesh_segment_shape() {
  static const Shape s = [] { Shape p; p.vertices = {Vec3::Zero(), Vec3::Zero()}; p.edges = {{0, 1}}; return p; }();
  return s;
}

// The body's features in the mesh frame, for the candidate distance tests.
struct LocalBody {
  std::vector<Vec3> vertices;
  std::vector<Vec3> face_normals;
  double core_radius = 0.0;  // m, farthest core vertex from the centre
};

void localise(const Placement& d, const PosedBody& a, LocalBody& out) {
  const Shape& s = *a.shape;
  out.vertices.resize(s.vertices.size());
  out.core_radius = 0.0;
  for (std::size_t v = 0; v < s.vertices.size(); ++v) {
    out.vertices[v] = to_mesh(d, a.vertices[v]);
    out.core_radius = std::max(out.core_radius, (a.vertices[v] - a.position).norm());
  }
  out.face_normals.resize(s.faces.size());
  for (std::size_t f = 0; f < s.faces.size(); ++f)
    out.face_normals[f] = d.orientation.conjugate() * (a.rotation * s.face_normals[f]);
}

void sort_unique(std::vector<std::uint32_t>& v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
}

// Mesh features within `reach` of the body's centre `c` (mesh frame): only those can come
// within the cutoff of the body's features (an exact, cheap filter of the grid's answer).
struct NearMesh {
  std::vector<std::uint32_t> faces, edges, vertices;
};

void near_features(const MeshFeatures& m, const Vec3& c, double reach, NearMesh& near) {
  thread_local std::vector<int> triangle(3);
  const double reach2 = reach * reach;
  const Vec3* mv = m.vertices.data();
  m.faces_near(c, reach, near.faces);
  std::size_t kept = 0;
  for (std::uint32_t f : near.faces) {
    std::copy(m.faces[f].begin(), m.faces[f].end(), triangle.begin());
    if (point_polygon_distance_sq(c, mv, triangle, m.face_normals[f]) < reach2) near.faces[kept++] = f;
  }
  near.faces.resize(kept);
  near.edges.clear();
  near.vertices.clear();
  for (std::uint32_t f : near.faces)
    for (int k = 0; k < 3; ++k) {
      const int e = m.face_edges[f][k];
      if (e >= 0 && point_segment_distance_sq(c, mv[m.edges[e][0]], mv[m.edges[e][1]] - mv[m.edges[e][0]]) < reach2)
        near.edges.push_back(std::uint32_t(e));
      const int v = m.faces[f][k];
      if (m.vertex_feature[v] && (mv[v] - c).squaredNorm() < reach2) near.vertices.push_back(std::uint32_t(v));
    }
  sort_unique(near.edges);
  sort_unique(near.vertices);
}

// True when n (mesh frame, unit) lies in the normal cone of mesh edge e or vertex v.
bool in_edge_cone(const MeshFeatures& m, std::uint32_t e, const Vec3& n) {
  for (std::uint32_t k = m.edge_inward_begin[e]; k < m.edge_inward_begin[e + 1]; ++k)
    if (n.dot(m.edge_inward[k]) > kConeSlack) return false;
  return true;
}

bool in_vertex_cone(const MeshFeatures& m, std::uint32_t v, const Vec3& n) {
  for (std::uint32_t k = m.neighbour_begin[v]; k < m.neighbour_begin[v + 1]; ++k) {
    const Vec3 w = m.vertices[m.neighbours[k]] - m.vertices[v];
    if (n.dot(w) > kConeSlack * w.norm()) return false;
  }
  return true;
}

// True when the projection of p on face f is over the face: its feature edges are closed (a
// duplicate with the edge is shadowed), a flat edge belongs to one of its two faces only.
bool over_face(const Placement& d, const MeshFeatures& m, std::uint32_t f, const Vec3* w, const Vec3& p, const Vec3& n) {
  for (int k = 0; k < 3; ++k) {
    const Vec3 e = w[(k + 1) % 3] - w[k];
    const double margin = kInteriorMargin * e.norm();  // m
    const int flat = m.face_flat[f][k];
    if (flat >= 0) {  // the same numbers from both faces
      const MeshFeatures::FlatEdge& fe = m.flat_edges[flat];
      const bool owner_side = (p - to_world(d, m.vertices[fe.lo])).dot(d.orientation * fe.inward) >= -margin;
      if (owner_side != (fe.owner == int(f))) return false;
    } else if (e.cross(p - w[k]).dot(n) < -margin * e.norm()) {  // > 0 inside, counter-clockwise
      return false;
    }
  }
  return true;
}

bool face_contact(const Placement& d, const MeshFeatures& m, const PosedBody& a, std::uint32_t v, std::uint32_t f,
                  double max_gap, ContactPoint& out) {
  const Vec3 w[3] = {to_world(d, m.vertices[m.faces[f][0]]), to_world(d, m.vertices[m.faces[f][1]]),
                     to_world(d, m.vertices[m.faces[f][2]])};
  const Vec3 n = d.orientation * m.face_normals[f];
  const Vec3& p = a.vertices[v];
  const double centre_side = (a.position - w[0]).dot(n);  // two-sided: the body's centre picks the side
  const Vec3 up = (centre_side != 0.0 ? centre_side : (p - w[0]).dot(n)) >= 0.0 ? n : Vec3(-n);
  const double gap = (p - w[0]).dot(up) - a.radius;
  if (gap >= max_gap || !over_face(d, m, f, w, p, n)) return false;
  out.normal = up;
  out.gap = gap;
  out.point = p - up * (a.radius + 0.5 * gap);  // middle of the overlap
  return true;
}

// The STL mesh in its frame; errors and warnings start with `where` (the scene's `file` key).
std::shared_ptr<const MeshFeatures> load_mesh(const MeshSettings& s) {
  try {
    std::size_t skipped = 0;
    auto mesh = std::make_shared<const MeshFeatures>(read_stl(s.file), s.scale, skipped);
    if (skipped > 0)
      std::fprintf(stderr, "warning: %s%zu zero-area triangle(s) of %s skipped\n", s.where.c_str(), skipped, s.file.c_str());
    return mesh;
  } catch (const InputError& e) {
    throw InputError(s.where + e.what());
  } catch (const std::invalid_argument& e) {
    throw InputError(s.where + s.file + ": " + e.what());
  }
}

}  // namespace

MeshDriver::MeshDriver(const MeshSettings& s, Placement& at) : mesh_(load_mesh(s)) {
  at.center = s.translation;
  at.orientation = s.rotation.normalized();
  at.normal = at.orientation * Vec3::UnitX();  // two orthogonal markers: any turn moves one (list rebuilds)
  at.axis = at.orientation * Vec3::UnitY();
}

bool MeshDriver::near(const Placement& d, const Vec3& center, double reach) const {
  return mesh_->any_face_near(to_mesh(d, center), reach);
}

bool MeshDriver::overlaps(const Placement& d, const Vec3& center, double radius) const {
  thread_local std::vector<std::uint32_t> faces;
  thread_local std::vector<int> triangle(3);
  const MeshFeatures& m = *mesh_;
  const Vec3 c = to_mesh(d, center);
  m.faces_near(c, radius, faces);
  for (std::uint32_t f : faces) {
    std::copy(m.faces[f].begin(), m.faces[f].end(), triangle.begin());
    if (point_polygon_distance_sq(c, m.vertices.data(), triangle, m.face_normals[f]) <= radius * radius) return true;
  }
  return false;
}

void MeshDriver::candidates(const Placement& d, const PosedBody& a, double range, std::vector<FeaturePair>& out) const {
  const MeshFeatures& m = *mesh_;
  const Shape& s = *a.shape;
  thread_local LocalBody body;
  thread_local NearMesh near;
  thread_local std::vector<int> triangle(3);
  localise(d, a, body);
  const double cutoff = a.radius + range, cutoff2 = cutoff * cutoff;
  near_features(m, to_mesh(d, a.position), body.core_radius + cutoff, near);
  const std::vector<std::uint32_t>&faces = near.faces, &edges = near.edges, &verts = near.vertices;
  const Vec3* mv = m.vertices.data();
  for (std::uint16_t v = 0; v < s.vertices.size(); ++v) {
    const Vec3& p = body.vertices[v];
    for (std::uint32_t f : faces) {
      std::copy(m.faces[f].begin(), m.faces[f].end(), triangle.begin());
      if (point_polygon_distance_sq(p, mv, triangle, m.face_normals[f]) < cutoff2) out.push_back({PairType::vertex_face, v, f});
    }
    for (std::uint32_t e : edges)
      if (point_segment_distance_sq(p, mv[m.edges[e][0]], mv[m.edges[e][1]] - mv[m.edges[e][0]]) < cutoff2)
        out.push_back({PairType::vertex_edge, v, e});
    for (std::uint32_t u : verts)
      if ((p - mv[u]).squaredNorm() < cutoff2) out.push_back({PairType::vertex_vertex, v, u});
  }
  for (std::uint16_t e = 0; e < s.edges.size(); ++e) {
    const Vec3& p0 = body.vertices[s.edges[e][0]];
    const Vec3 de = body.vertices[s.edges[e][1]] - p0;
    for (std::uint32_t u : verts)
      if (point_segment_distance_sq(mv[u], p0, de) < cutoff2) out.push_back({PairType::edge_vertex, e, u});
    for (std::uint32_t g : edges)
      if (segment_segment_distance_sq(p0, de, mv[m.edges[g][0]], mv[m.edges[g][1]] - mv[m.edges[g][0]]) < cutoff2)
        out.push_back({PairType::edge_edge, e, g});
  }
  for (std::uint16_t f = 0; f < s.faces.size(); ++f)
    for (std::uint32_t u : verts)
      if (point_polygon_distance_sq(mv[u], body.vertices.data(), s.faces[f], body.face_normals[f]) < cutoff2)
        out.push_back({PairType::face_vertex, f, u});
}

bool MeshDriver::contact(const Placement& d, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out) const {
  const MeshFeatures& m = *mesh_;
  if (f.type == PairType::vertex_face) return face_contact(d, m, a, f.a, f.b, max_gap, out);
  const bool edge = f.type == PairType::vertex_edge || f.type == PairType::edge_edge;
  Vec3 ends[2];
  PosedBody partner{nullptr, ends, Mat3::Identity(), Vec3::Zero(), 0.0, 1.0};
  if (edge) {
    ends[0] = to_world(d, m.vertices[m.edges[f.b][0]]);
    ends[1] = to_world(d, m.vertices[m.edges[f.b][1]]);
    partner.shape = &mesh_segment_shape();
    partner.position = 0.5 * (ends[0] + ends[1]);
  } else {
    ends[0] = to_world(d, m.vertices[f.b]);
    partner.shape = &mesh_point_shape();
    partner.position = ends[0];
  }
  if (!feature_contact(a, partner, {f.type, f.a, 0}, max_gap, out)) return false;
  const Vec3 n = d.orientation.conjugate() * out.normal;
  return edge ? in_edge_cone(m, f.b, n) : in_vertex_cone(m, f.b, n);
}

void MeshDriver::bounds(const Placement& at, Box3& box) const {
  for (const Vec3& v : mesh_->vertices) box.add(at.center + at.orientation * v);
}

DriverMesh MeshDriver::drawing(const Placement& at, const std::string& name, const ViewFrame&) const {
  DriverMesh m{name, {}, {}};
  for (const Vec3& v : mesh_->vertices) m.points.push_back(at.center + at.orientation * v);
  for (const std::array<int, 3>& t : mesh_->faces) m.polygons.push_back({t[0], t[1], t[2]});
  return m;
}

}  // namespace polydem
