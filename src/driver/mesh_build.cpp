// Topology (edges once, flat edges and vertices, normal cones) and the uniform grid of face
// bounding boxes of a mesh driver, built once in the mesh frame: a moving mesh needs no rebuild.
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <tuple>

#include "driver/mesh.hpp"
#include "shape/point_sources.hpp"

namespace polydem {

namespace {

// Collinear within this (|cross| / longest edge^2): a zero-area triangle has no normal.
constexpr double kDegenerate = 1e-10;
// Grid cells per face, at most: keeps the index small for meshes of very uneven triangles.
constexpr std::size_t kCellsPerFace = 4;

struct EdgeUse {
  int lo, hi;   // vertex indices, lo < hi
  int face, k;  // the face and its edge k (v_k -> v_k+1)
  bool operator<(const EdgeUse& o) const { return std::tie(lo, hi, face, k) < std::tie(o.lo, o.hi, o.face, o.k); }
};

// Unit in-plane direction perpendicular to edge (a, b), into the face whose third vertex is c.
Vec3 inward(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 u = (b - a).normalized();
  const Vec3 w = c - a;
  return (w - w.dot(u) * u).normalized();
}

}  // namespace

MeshFeatures::MeshFeatures(const TriangleMesh& mesh, double scale, std::size_t& skipped) {
  skipped = 0;
  for (const Vec3& v : mesh.vertices) {
    vertices.push_back(scale * v);
    if (!vertices.back().allFinite()) throw std::invalid_argument("a vertex coordinate is not finite (after scale)");
  }
  for (const std::array<int, 3>& t : mesh.triangles) {
    const Vec3 &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    const Vec3 n = (b - a).cross(c - a);
    const double longest2 = std::max({(b - a).squaredNorm(), (c - a).squaredNorm(), (c - b).squaredNorm()});
    if (!(n.norm() > kDegenerate * longest2)) {
      ++skipped;
      continue;
    }
    faces.push_back(t);
    face_normals.push_back(n.normalized());
  }
  if (faces.empty()) throw std::invalid_argument("no triangle with a non-zero area");
  build_topology();
  build_grid();
}

void MeshFeatures::build_topology() {
  std::vector<EdgeUse> uses;
  for (int f = 0; f < int(faces.size()); ++f)
    for (int k = 0; k < 3; ++k) {
      const int a = faces[f][k], b = faces[f][(k + 1) % 3];
      uses.push_back({std::min(a, b), std::max(a, b), f, k});
    }
  std::sort(uses.begin(), uses.end());
  face_edges.assign(faces.size(), {-1, -1, -1});
  face_flat.assign(faces.size(), {-1, -1, -1});
  vertex_feature.assign(vertices.size(), 0);
  std::vector<std::vector<int>> adjacent(vertices.size());
  edge_inward_begin.push_back(0);
  for (std::size_t s = 0; s < uses.size();) {
    std::size_t e = s;
    while (e < uses.size() && uses[e].lo == uses[s].lo && uses[e].hi == uses[s].hi) ++e;
    const Vec3 &a = vertices[uses[s].lo], &b = vertices[uses[s].hi];
    auto direction_into = [&](const EdgeUse& u) { return inward(a, b, vertices[faces[u.face][(u.k + 2) % 3]]); };
    adjacent[uses[s].lo].push_back(uses[s].hi);
    adjacent[uses[s].hi].push_back(uses[s].lo);
    const bool two = e - s == 2;
    const bool flat = two && face_normals[uses[s].face].cross(face_normals[uses[s + 1].face]).norm() < kFlatSin &&
                      direction_into(uses[s]).dot(direction_into(uses[s + 1])) < 0.0;  // not folded back
    if (flat) {  // uses are sorted by face: uses[s] is the owner
      face_flat[uses[s].face][uses[s].k] = face_flat[uses[s + 1].face][uses[s + 1].k] = int(flat_edges.size());
      flat_edges.push_back({uses[s].lo, direction_into(uses[s]), uses[s].face});
    } else {
      for (std::size_t u = s; u < e; ++u) {
        face_edges[uses[u].face][uses[u].k] = int(edges.size());
        edge_inward.push_back(direction_into(uses[u]));
      }
      edge_inward_begin.push_back(std::uint32_t(edge_inward.size()));
      edges.push_back({uses[s].lo, uses[s].hi});
      vertex_feature[uses[s].lo] = vertex_feature[uses[s].hi] = 1;
    }
    s = e;
  }
  neighbour_begin.push_back(0);
  for (const std::vector<int>& list : adjacent) {
    neighbours.insert(neighbours.end(), list.begin(), list.end());
    neighbour_begin.push_back(std::uint32_t(neighbours.size()));
  }
}

void MeshFeatures::build_grid() {
  Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
  double size = 0.0;  // m, mean largest box side
  for (const std::array<int, 3>& t : faces) {
    Vec3 flo = vertices[t[0]], fhi = vertices[t[0]];
    for (int k = 1; k < 3; ++k) {
      flo = flo.cwiseMin(vertices[t[k]]);
      fhi = fhi.cwiseMax(vertices[t[k]]);
    }
    box_lo_.push_back(flo);
    box_hi_.push_back(fhi);
    lo = lo.cwiseMin(flo);
    hi = hi.cwiseMax(fhi);
    size += (fhi - flo).maxCoeff();
  }
  const Vec3 extent = hi - lo;
  grid_lo_ = lo;
  cell_ = std::max(size / double(faces.size()), 1e-9 * extent.maxCoeff());
  if (!(cell_ > 0.0)) cell_ = 1.0;  // a single point: any cell holds it
  auto count_cells = [&]() {
    std::size_t total = 1;
    for (int k = 0; k < 3; ++k) {
      dims_[k] = int(std::min(extent[k] / cell_, 1e6)) + 1;
      total *= std::size_t(dims_[k]);
    }
    return total;
  };
  while (count_cells() > kCellsPerFace * faces.size() + 64) cell_ *= 1.25;
  std::vector<std::uint32_t> count(std::size_t(dims_[0]) * dims_[1] * dims_[2] + 1, 0);
  for (std::uint32_t f = 0; f < faces.size(); ++f)
    visit_cells(box_lo_[f], box_hi_[f], [&](std::size_t c) { ++count[c + 1]; });
  for (std::size_t c = 1; c < count.size(); ++c) count[c] += count[c - 1];
  cell_begin_ = count;
  cell_faces_.resize(count.back());
  for (std::uint32_t f = 0; f < faces.size(); ++f)
    visit_cells(box_lo_[f], box_hi_[f], [&](std::size_t c) { cell_faces_[count[c]++] = f; });
}

template <class Visit>
void MeshFeatures::visit_cells(const Vec3& lo, const Vec3& hi, Visit visit) const {
  std::array<int, 3> i0, i1;
  for (int k = 0; k < 3; ++k) {
    const double a = (lo[k] - grid_lo_[k]) / cell_, b = (hi[k] - grid_lo_[k]) / cell_;
    if (b < 0.0 || a >= double(dims_[k])) return;  // the box misses the grid
    i0[k] = std::max(0, int(std::floor(a)));
    i1[k] = std::min(dims_[k] - 1, int(std::floor(b)));
  }
  for (int z = i0[2]; z <= i1[2]; ++z)
    for (int y = i0[1]; y <= i1[1]; ++y)
      for (int x = i0[0]; x <= i1[0]; ++x) visit((std::size_t(z) * dims_[1] + y) * dims_[0] + x);
}

bool MeshFeatures::box_meets(std::uint32_t f, const Vec3& lo, const Vec3& hi) const {
  return (box_lo_[f].array() <= hi.array()).all() && (box_hi_[f].array() >= lo.array()).all();
}

std::size_t MeshFeatures::faces_near(const Vec3& centre, double radius, std::vector<std::uint32_t>& out) const {
  out.clear();
  const Vec3 lo = centre.array() - radius, hi = centre.array() + radius;
  std::size_t examined = 0;
  visit_cells(lo, hi, [&](std::size_t c) {
    for (std::uint32_t e = cell_begin_[c]; e < cell_begin_[c + 1]; ++e, ++examined)
      if (box_meets(cell_faces_[e], lo, hi)) out.push_back(cell_faces_[e]);
  });
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return examined;
}

bool MeshFeatures::any_face_near(const Vec3& centre, double radius) const {
  const Vec3 lo = centre.array() - radius, hi = centre.array() + radius;
  bool found = false;
  visit_cells(lo, hi, [&](std::size_t c) {
    for (std::uint32_t e = cell_begin_[c]; e < cell_begin_[c + 1] && !found; ++e) found = box_meets(cell_faces_[e], lo, hi);
  });
  return found;
}

double MeshFeatures::area() const {
  double total = 0.0;
  for (const std::array<int, 3>& t : faces)
    total += 0.5 * (vertices[t[1]] - vertices[t[0]]).cross(vertices[t[2]] - vertices[t[0]]).norm();
  return total;
}

}  // namespace polydem
