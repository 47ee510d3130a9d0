#include "shape/hull_faces.hpp"

#include <algorithm>
#include <map>
#include <numeric>

namespace polydem {
namespace {

// sin of the turn at a polygon corner below which the corner is a straight-through point.
constexpr double kCollinearSine = 1e-9;

int find_root(std::vector<int>& parent, int i) {
  while (parent[i] != i) i = parent[i] = parent[parent[i]];
  return i;
}

Vec3 triangle_normal(const std::vector<Vec3>& v, const std::array<int, 3>& t) {
  return (v[t[1]] - v[t[0]]).cross(v[t[2]] - v[t[0]]).normalized();
}

// The boundary loop of one group of triangles: its directed edges whose reverse is outside.
std::vector<int> boundary_loop(const std::vector<std::array<int, 3>>& triangles,
                               const std::vector<int>& members) {
  std::map<std::pair<int, int>, int> count;
  for (int t : members)
    for (int k = 0; k < 3; ++k) ++count[{triangles[t][k], triangles[t][(k + 1) % 3]}];
  std::map<int, int> next;
  for (const auto& [edge, n] : count)
    if (!count.count({edge.second, edge.first})) next[edge.first] = edge.second;
  std::vector<int> loop;
  const int start = next.begin()->first;
  int v = start;
  do {
    loop.push_back(v);
    v = next.at(v);
  } while (v != start && loop.size() <= next.size());
  return loop;
}

bool is_straight(const std::vector<Vec3>& v, int prev, int at, int next) {
  const Vec3 a = (v[at] - v[prev]).normalized();
  const Vec3 b = (v[next] - v[at]).normalized();
  return a.cross(b).norm() < kCollinearSine && a.dot(b) > 0.0;
}

}  // namespace

std::vector<std::vector<int>> merge_coplanar(const std::vector<Vec3>& vertices,
                                             const std::vector<std::array<int, 3>>& triangles,
                                             double angle_tolerance) {
  const int nt = static_cast<int>(triangles.size());
  std::vector<Vec3> normals;
  for (const auto& t : triangles) normals.push_back(triangle_normal(vertices, t));
  std::map<std::pair<int, int>, int> owner;  // directed edge -> triangle
  for (int t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) owner[{triangles[t][k], triangles[t][(k + 1) % 3]}] = t;
  std::vector<int> parent(nt);
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& [edge, t] : owner) {
    auto it = owner.find({edge.second, edge.first});
    if (it == owner.end()) continue;
    const double angle =
        std::atan2(normals[t].cross(normals[it->second]).norm(), normals[t].dot(normals[it->second]));
    if (angle < angle_tolerance) parent[find_root(parent, t)] = find_root(parent, it->second);
  }
  std::map<int, std::vector<int>> groups;  // ordered by root: deterministic face order
  for (int t = 0; t < nt; ++t) groups[find_root(parent, t)].push_back(t);
  std::vector<std::vector<int>> faces;
  for (const auto& entry : groups) faces.push_back(boundary_loop(triangles, entry.second));
  return faces;
}

std::vector<int> planar_hull(const std::vector<Vec3>& points, const Vec3& normal) {
  const Vec3 ex = (std::abs(normal.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY()).cross(normal).normalized();
  const Vec3 ey = normal.cross(ex);
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  auto coord = [&](int i) { return std::pair<double, double>(points[i].dot(ex), points[i].dot(ey)); };
  std::sort(order.begin(), order.end(), [&](int a, int b) { return coord(a) < coord(b); });
  auto turn = [&](int o, int a, int b) {  // > 0: counter-clockwise about `normal`
    return (points[a] - points[o]).cross(points[b] - points[o]).dot(normal);
  };
  // Andrew's monotone chain; a turn <= tolerance drops collinear points.
  double scale = 0.0;
  for (const Vec3& p : points) scale = std::max(scale, (p - points[order[0]]).norm());
  const double tolerance = kCollinearSine * scale * scale;
  std::vector<int> hull(2 * points.size());
  size_t k = 0;
  for (size_t pass = 0; pass < 2; ++pass) {
    const size_t base = k;
    for (size_t j = 0; j < order.size(); ++j) {
      const int i = pass == 0 ? order[j] : order[order.size() - 1 - j];
      while (k >= base + 2 && turn(hull[k - 2], hull[k - 1], i) <= tolerance) --k;
      hull[k++] = i;
    }
    --k;  // the last point starts the other chain
  }
  hull.resize(k);
  return hull;
}

void drop_non_corners(std::vector<Vec3>& vertices, std::vector<std::vector<int>>& faces) {
  for (auto& f : faces) {
    std::vector<int> kept;
    for (size_t i = 0; i < f.size(); ++i) {
      const int prev = f[(i + f.size() - 1) % f.size()], next = f[(i + 1) % f.size()];
      if (!is_straight(vertices, prev, f[i], next)) kept.push_back(f[i]);
    }
    f = kept;
  }
  std::vector<int> new_index(vertices.size(), -1);
  std::vector<Vec3> used;
  for (auto& f : faces)
    for (int& i : f) {
      if (new_index[i] < 0) {
        new_index[i] = static_cast<int>(used.size());
        used.push_back(vertices[i]);
      }
      i = new_index[i];
    }
  vertices = used;
}

}  // namespace polydem
