#include "shape/topology.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include "polydem/error.hpp"

namespace polydem {
namespace {

using EdgeKey = std::pair<int, int>;

EdgeKey key_of(int a, int b) { return {std::min(a, b), std::max(a, b)}; }

[[noreturn]] void fail(const Shape& s, const std::string& what) {
  throw InputError("shape '" + s.name + "': " + what);
}

void check_indices(const Shape& s) {
  const int nv = static_cast<int>(s.vertices.size());
  if (nv == 0) fail(s, "has no vertex");
  auto check = [&](int i) {
    if (i < 0 || i >= nv)
      fail(s, "vertex index " + std::to_string(i) + " out of range 0.." + std::to_string(nv - 1));
  };
  for (const auto& e : s.edges) {
    check(e[0]);
    check(e[1]);
    if (e[0] == e[1])
      fail(s, "edge " + std::to_string(e[0]) + "-" + std::to_string(e[1]) + " joins a vertex to itself");
  }
  for (const auto& f : s.faces) {
    if (f.size() < 3) fail(s, "a face has fewer than 3 vertices");
    for (int i : f) check(i);
  }
}

// Faces bordering each edge key, from consecutive polygon vertices.
std::map<EdgeKey, std::vector<int>> faces_by_edge(const Shape& s) {
  std::map<EdgeKey, std::vector<int>> out;
  for (int f = 0; f < static_cast<int>(s.faces.size()); ++f) {
    const auto& poly = s.faces[f];
    for (size_t i = 0; i < poly.size(); ++i) out[key_of(poly[i], poly[(i + 1) % poly.size()])].push_back(f);
  }
  return out;
}

Vec3 vertex_centroid(const Shape& s) {
  Vec3 c = Vec3::Zero();
  for (const Vec3& v : s.vertices) c += v;
  return c / static_cast<double>(s.vertices.size());
}

// Largest distance of a vertex to the plane of the first face with an area: zero for a plate
// (and for faces that all lack an area).
double thickness(const Shape& s) {
  for (const auto& face : s.faces) {
    const Vec3 n = polygon_normal(s.vertices, face);
    if (!(n.norm() > 0.5)) continue;
    const Vec3& p = s.vertices[face[0]];
    double t = 0.0;
    for (const Vec3& v : s.vertices) t = std::max(t, std::abs(n.dot(v - p)));
    return t;
  }
  return 0.0;
}

double extent(const Shape& s) {
  const Vec3 c = vertex_centroid(s);
  double e = 0.0;
  for (const Vec3& v : s.vertices) e = std::max(e, (v - c).norm());
  return e;
}

// A solid's faces must point away from the vertex centroid (inside a convex body).
void orient_solid_faces(Shape& s) {
  const Vec3 c = vertex_centroid(s);
  for (auto& f : s.faces) {
    Vec3 fc = Vec3::Zero();
    for (int i : f) fc += s.vertices[i];
    fc /= static_cast<double>(f.size());
    if (polygon_normal(s.vertices, f).dot(fc - c) < 0.0) std::reverse(f.begin(), f.end());
  }
}

void check_edges_match(const Shape& s, const std::map<EdgeKey, std::vector<int>>& by_edge) {
  std::set<EdgeKey> listed;
  for (const auto& e : s.edges) {
    if (!listed.insert(key_of(e[0], e[1])).second)
      fail(s, "edge " + std::to_string(e[0]) + "-" + std::to_string(e[1]) + " is listed twice");
    if (!by_edge.count(key_of(e[0], e[1])))
      fail(s, "edge " + std::to_string(e[0]) + "-" + std::to_string(e[1]) + " is on no face");
  }
  if (listed.size() != by_edge.size())
    fail(s, "the edge list misses " + std::to_string(by_edge.size() - listed.size()) +
                " face edge(s) (leave edges out to have them derived from the faces)");
}

// Zero-length edges and zero-area faces (repeated vertices) have no direction or normal.
void check_sizes(const Shape& s) {
  for (const auto& e : s.edges)
    if (s.vertices[e[0]] == s.vertices[e[1]])
      fail(s, "edge " + std::to_string(e[0]) + "-" + std::to_string(e[1]) +
                  " has zero length (repeated vertex)");
  for (size_t f = 0; f < s.faces.size(); ++f)
    if (!(polygon_normal(s.vertices, s.faces[f]).norm() > 0.5))  // Eigen leaves a zero vector zero
      fail(s, "face " + std::to_string(f) + " has zero area");
}

// Two vertices at one point leave a face or edge without direction, and a "solid" whose
// faces all lie in one plane has no inside: its centre of mass would be arbitrary.
void check_distinct_vertices(const Shape& s) {
  std::vector<int> order(s.vertices.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = static_cast<int>(k);
  const auto less = [&](int a, int b) {
    const Vec3 &u = s.vertices[a], &v = s.vertices[b];
    return std::tie(u.x(), u.y(), u.z()) < std::tie(v.x(), v.y(), v.z());
  };
  std::sort(order.begin(), order.end(), less);
  for (size_t k = 1; k < order.size(); ++k)
    if (s.vertices[order[k - 1]] == s.vertices[order[k]])
      fail(s, "vertices " + std::to_string(std::min(order[k - 1], order[k])) + " and " +
                  std::to_string(std::max(order[k - 1], order[k])) + " coincide (merge them, or hull the points)");
}

// Each edge once, in first-listed order (a and b, or b and a, are the same edge).
void merge_duplicate_edges(Shape& s) {
  std::set<EdgeKey> seen;
  std::vector<std::array<int, 2>> kept;
  for (const auto& e : s.edges)
    if (seen.insert(key_of(e[0], e[1])).second) kept.push_back(e);
  s.edges = std::move(kept);
}

// A sphere (1 vertex) or a segment (2 vertices, 1 edge) is convex; any other set of vertices
// and edges is a polyline, a cluster of spheres or a mix of both.
void prepare_faceless(Shape& s) {
  merge_duplicate_edges(s);
  const size_t nv = s.vertices.size();
  s.convex = (nv == 1 && s.edges.empty()) || (nv == 2 && s.edges.size() == 1);
}

// True when the faces close a convex polyhedron (every face edge on two faces, every listed
// edge on a face, every vertex on a face and inside every face plane) or are one polygon (a
// plate). Works on a copy: the faces are oriented outward only once convexity is known.
bool closes_convex_core(const Shape& given) {
  if (given.surface) return false;
  if (given.faces.size() == 1) return true;
  Shape s = given;
  const bool plate = s.faces.size() == 2 && thickness(s) <= 1e-9 * extent(s);
  if (!plate) orient_solid_faces(s);
  const auto by_edge = faces_by_edge(s);
  for (const auto& entry : by_edge)
    if (entry.second.size() != 2) return false;
  for (const auto& e : s.edges)
    if (!by_edge.count(key_of(e[0], e[1]))) return false;
  std::vector<char> on_face(s.vertices.size(), 0);
  for (const auto& f : s.faces)
    for (int i : f) on_face[i] = 1;
  for (char used : on_face)
    if (!used) return false;
  const double tolerance = 1e-9 * extent(s);  // m, round-off of coplanar corners
  for (const auto& f : s.faces) {
    const Vec3 n = polygon_normal(s.vertices, f);
    const Vec3& p = s.vertices[f[0]];
    for (const Vec3& v : s.vertices)
      if (n.dot(v - p) > tolerance) return false;
  }
  return true;
}

// A non-convex or open set of faces: kept as given (two-sided in contact), the edges are the
// listed ones and every face edge, each once.
void prepare_open_faces(Shape& s) {
  s.convex = false;
  for (const auto& entry : faces_by_edge(s)) s.edges.push_back({entry.first.first, entry.first.second});
  merge_duplicate_edges(s);
}

}  // namespace

Vec3 polygon_normal(const std::vector<Vec3>& vertices, const std::vector<int>& face) {
  Vec3 n = Vec3::Zero();
  for (size_t i = 0; i < face.size(); ++i) {
    const Vec3& a = vertices[face[i]];
    const Vec3& b = vertices[face[(i + 1) % face.size()]];
    n += Vec3((a.y() - b.y()) * (a.z() + b.z()), (a.z() - b.z()) * (a.x() + b.x()),
              (a.x() - b.x()) * (a.y() + b.y()));
  }
  return n.normalized();
}

void prepare_topology(Shape& s) {
  check_indices(s);
  check_distinct_vertices(s);
  if (s.faces.empty()) {
    prepare_faceless(s);
    check_sizes(s);
    s.face_normals.clear();
    return;
  }
  if (!closes_convex_core(s)) {
    prepare_open_faces(s);
    check_sizes(s);
    s.face_normals.clear();
    for (const auto& f : s.faces) s.face_normals.push_back(polygon_normal(s.vertices, f));
    return;
  }
  s.convex = true;
  // One polygon alone (as some Rockable libraries give plates): its back side is added.
  if (s.faces.size() == 1) s.faces.emplace_back(s.faces[0].rbegin(), s.faces[0].rend());
  // A plate (two faces in one plane) keeps its two opposite orders as given.
  const bool flat = thickness(s) <= 1e-9 * extent(s);
  const bool plate = s.faces.size() == 2 && flat;
  if (flat && !plate)
    fail(s, "its " + std::to_string(s.faces.size()) + " faces lie in one plane: a solid needs thickness (give a "
                "plate as one polygon)");
  if (!plate) orient_solid_faces(s);
  const auto by_edge = faces_by_edge(s);
  if (s.edges.empty()) {
    for (const auto& entry : by_edge) s.edges.push_back({entry.first.first, entry.first.second});
  } else {
    check_edges_match(s, by_edge);
  }
  check_sizes(s);
  s.face_normals.clear();
  for (const auto& f : s.faces) s.face_normals.push_back(polygon_normal(s.vertices, f));
}

std::vector<EdgeFaces> edge_faces(const Shape& s) {
  const auto by_edge = faces_by_edge(s);
  std::vector<EdgeFaces> out(s.edges.size());
  for (size_t e = 0; e < s.edges.size(); ++e) {
    auto it = by_edge.find(key_of(s.edges[e][0], s.edges[e][1]));
    if (it == by_edge.end()) continue;
    out[e] = {it->second[0], it->second[1]};
  }
  return out;
}

}  // namespace polydem
