#pragma once
// The SPEC's boundary rule across feature pairs: for a convex face body, a vertex whose projection
// falls inside a face and lies on its outer side has that projection as its unique closest
// point (p - q is in the face's normal cone), so the vertex-edge and vertex-vertex pairs of
// the same vertex against that body are duplicates of the vertex-face one. Without this, a
// vertex near a face's edge gets two springs, and one appears at full overlap (energy jumps).
#include <cstdint>

#include "geometry/features.hpp"

namespace polydem {

// True for the pair types that shadow the other contacts of their vertex.
inline bool shadows(PairType t) { return t == PairType::vertex_face || t == PairType::face_vertex; }

// True for the pair types mark_shadowed may drop: a vertex against an edge or a vertex.
inline bool may_be_shadowed(PairType t) {
  return t == PairType::vertex_vertex || t == PairType::vertex_edge || t == PairType::edge_vertex;
}

// The same for a set of types, bit t for PairType t.
inline bool shadows_any(unsigned types) {
  return (types & (1u << unsigned(PairType::vertex_face) | 1u << unsigned(PairType::face_vertex))) != 0;
}
inline bool may_be_shadowed_any(unsigned types) {
  return (types & (1u << unsigned(PairType::vertex_vertex) | 1u << unsigned(PairType::vertex_edge) |
                   1u << unsigned(PairType::edge_vertex))) != 0;
}

// Marks drop[k] = 1 for the contacts (keys[k], gaps[k]) of one body pair that a vertex-face or
// face-vertex contact of the same vertex shadows; `radii` = rA + rB (m). A face shadows only when
// its body is convex (`a_convex`, `b_convex`): over a non-convex core the projection need not
// be the closest point (a vertex over a face may be nearer an edge of another arm).
template <class KeyAt, class GapAt>
void mark_shadowed(std::size_t n, const KeyAt& key_at, const GapAt& gap_at, double radii, std::uint8_t* drop,
                   bool a_convex = true, bool b_convex = true) {
  constexpr int kMax = 64;  // vertices over a face per pair: more than any real contact patch
  std::uint32_t over_a[kMax], over_b[kMax];
  int na = 0, nb = 0;
  for (std::size_t k = 0; k < n; ++k) {
    const FeaturePair f = key_at(k);
    if (gap_at(k) < -radii) continue;  // the vertex is inside the other core: no unique closest point
    if (f.type == PairType::vertex_face && b_convex && na < kMax) over_a[na++] = f.a;
    if (f.type == PairType::face_vertex && a_convex && nb < kMax) over_b[nb++] = f.b;
  }
  auto listed = [](const std::uint32_t* v, int count, std::uint32_t x) {
    for (int i = 0; i < count; ++i)
      if (v[i] == x) return true;
    return false;
  };
  for (std::size_t k = 0; k < n; ++k) {
    const FeaturePair f = key_at(k);
    const bool a_vertex = f.type == PairType::vertex_edge || f.type == PairType::vertex_vertex;
    const bool b_vertex = f.type == PairType::edge_vertex || f.type == PairType::vertex_vertex;
    drop[k] = (a_vertex && listed(over_a, na, f.a)) || (b_vertex && listed(over_b, nb, f.b));
  }
}

}  // namespace polydem
