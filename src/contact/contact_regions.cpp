#include "contact/contact_regions.hpp"

#include <algorithm>
#include <array>

namespace polydem {
namespace {

// The vertices of one feature (a vertex, an edge, a face) of a shape, at most kMax of them.
struct FeatureVertices {
  static constexpr int kMax = 64;
  std::array<int, kMax> ids;
  int count = 0;
  void add(int v) {
    for (int i = 0; i < count; ++i)
      if (ids[i] == v) return;
    if (count < kMax) ids[count++] = v;
  }
};

enum class Kind { vertex, edge, face };

void add_feature(const Shape& s, Kind kind, int index, FeatureVertices& out) {
  if (kind == Kind::vertex) {
    out.add(index);
  } else if (kind == Kind::edge) {
    out.add(s.edges[index][0]);
    out.add(s.edges[index][1]);
  } else {
    for (int v : s.faces[index]) out.add(v);
  }
}

// Kind of the feature on side A (first) or B (second) of a pair type.
Kind kind_on(PairType t, bool side_a) {
  switch (t) {
    case PairType::vertex_vertex: return Kind::vertex;
    case PairType::vertex_edge: return side_a ? Kind::vertex : Kind::edge;
    case PairType::edge_vertex: return side_a ? Kind::edge : Kind::vertex;
    case PairType::vertex_face: return side_a ? Kind::vertex : Kind::face;
    case PairType::face_vertex: return side_a ? Kind::face : Kind::vertex;
    case PairType::edge_edge: return Kind::edge;
  }
  return Kind::vertex;
}

bool contains_all(const std::vector<int>& face, const FeatureVertices& v) {
  for (int i = 0; i < v.count; ++i)
    if (std::find(face.begin(), face.end(), v.ids[i]) == face.end()) return false;
  return true;
}

// True when the vertices of both features lie on one feature of s: one vertex, an edge, a face.
bool on_common_feature(const Shape& s, Kind kx, int x, Kind ky, int y) {
  if (kx == ky && x == y) return true;
  FeatureVertices v;
  add_feature(s, kx, x, v);
  add_feature(s, ky, y, v);
  if (v.count == 1) return true;
  if (v.count == 2)
    for (const auto& e : s.edges)
      if ((e[0] == v.ids[0] && e[1] == v.ids[1]) || (e[0] == v.ids[1] && e[1] == v.ids[0])) return true;
  for (const auto& f : s.faces)
    if (contains_all(f, v)) return true;
  return false;
}

}  // namespace

bool same_region(const Shape& a, const Shape* b, FeaturePair x, FeaturePair y) {
  if (!a.convex && !on_common_feature(a, kind_on(x.type, true), x.a, kind_on(y.type, true), y.a)) return false;
  if (b && !b->convex && !on_common_feature(*b, kind_on(x.type, false), int(x.b), kind_on(y.type, false), int(y.b)))
    return false;
  return true;
}

}  // namespace polydem
