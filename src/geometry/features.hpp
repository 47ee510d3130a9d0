#pragma once
// Contact geometry between spheropolyhedra: closest-feature queries (vertex, edge, face) on the
// core polyhedra, with the Minkowski radii added apart (SPEC "Contact geometry").
#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "polydem/math.hpp"
#include "polydem/shape.hpp"

namespace polydem {

enum class PairType : std::uint8_t { vertex_vertex, vertex_edge, edge_vertex, vertex_face, face_vertex, edge_edge };
inline constexpr int kPairTypeCount = 6;

// Feature index in body A and in body B (vertex, edge or face index, by type).
struct FeaturePair {
  PairType type;
  std::uint16_t a;
  std::uint32_t b;  // 32 bits: a driver mesh may have more than 65,535 features
};

// A body placed in the world for one step; vertices are precomputed once per step by the caller.
struct PosedBody {
  const Shape* shape;
  const Vec3* vertices;  // m, world positions of the scaled vertices: position + R * (scale * v)
  Mat3 rotation;         // principal -> world
  Vec3 position;         // m, centre of mass
  double radius;         // m, scaled Minkowski radius
  double scale;          // size factor: the shape's edge planes lie at scale * offset in the body frame
};

struct ContactPoint {
  Vec3 normal;  // unit, from B to A (the force on A is +fn * normal)
  Vec3 point;   // m, world, middle of the overlap: ((cA - rA n) + (cB + rB n)) / 2
  double gap;   // m, distance between features - rA - rB; negative = overlap
};

// World positions of the scaled vertices: out[i] = position + q * (scale * shape.vertices[i]).
void pose_vertices(const Shape& shape, double scale, const Vec3& position, const Quat& q, Vec3* out);
// The same with q's rotation matrix, for a caller that keeps it (the same bits).
void pose_vertices(const Shape& shape, double scale, const Vec3& position, const Mat3& rotation, Vec3* out);

// Evaluates one feature pair. Returns false when the closest points do not lie strictly inside
// the features (the lower-dimensional pair covers the boundary), when edges are parallel
// (edge_edge), or when gap >= max_gap. On true fills `out`; on false sets out.gap to 1 where
// rejection_allowance has an allowance for the rejection, else 0.
// Between convex cores (centre inside): pairs whose normal points into a body as seen from its
// centre (cores passed through each other) are rejected, never inverted. Vertex-face uses the
// signed distance along the face body's outward normal, so the normal never inverts: a vertex
// below the face plane (cores interpenetrating) keeps pushing out through the face it is least
// deep under, down to a depth rA + rB, past which the pair is rejected (Rockable instead takes
// |distance| and flips the normal, pushing the vertex deeper). A pair with a non-convex body
// has no such rule, and the faces of a non-convex body are two-sided (|distance|, as Rockable).
// One kernel per PairType (kernels.cpp), called through the table: inline, the per-step loop
// makes one call per candidate, not two.
// The table is one of two builds of the same kernels, chosen at start-up: AVX's where the CPU has
// it (fewer instructions), else SSE2's; they give the same bits.
using FeatureKernel = bool (*)(const PosedBody&, const PosedBody&, int, int, double, ContactPoint&);
extern const std::array<FeatureKernel, kPairTypeCount> kFeatureKernels;
extern const std::array<FeatureKernel, kPairTypeCount> kSse2Kernels, kAvxKernels;
bool cpu_has_avx();  // and the OS saves its registers: kAvxKernels may run
extern const bool kHasAvx;  // cpu_has_avx() at start-up: the hot loops' AVX builds run
inline bool feature_contact(const PosedBody& A, const PosedBody& B, FeaturePair pair, double max_gap,
                            ContactPoint& out) {
  return kFeatureKernels[static_cast<std::size_t>(pair.type)](A, B, pair.a, pair.b, max_gap, out);
}

// m, >= 0, for a pair feature_contact rejected with out.gap 1 (a vertex outside a face's polygon,
// edges whose lines' closest points lie beyond an edge's end): it rejects the same way while the two
// bodies' displacement bounds (rebuild_trigger.hpp) at that step and at a later one add up to less.
// 0 where no such bound is made.
double rejection_allowance(const PosedBody& A, const PosedBody& B, FeaturePair pair);

// Verlet candidates: appends every feature pair whose features (as point sets, boundary
// included, no interior rule) are closer than rA + rB + range, in a deterministic order
// (by type, then index in A, then index in B). Used at neighbour-list rebuilds. Returns the
// smallest gap (m, core distance - rA - rB) among the appended pairs, +inf when none: until
// the bodies have moved that far, no feature pair of theirs can touch. With `distances2`, also
// appends each kept pair's core distance^2 (m^2).
double candidate_features(const PosedBody& A, const PosedBody& B, double range, std::vector<FeaturePair>& out,
                          std::vector<double>* distances2 = nullptr);

// m^2, the core distance^2 of candidate f as candidate_features finds it with this cutoff^2 (the
// same arithmetic, so the same bits): to keep a remembered candidate only when it would be found.
double candidate_distance_sq(const PosedBody& A, const PosedBody& B, FeaturePair f, double cutoff2);

// Reference: every feature pair of the two bodies evaluated with feature_contact(max_gap = 0).
std::vector<std::pair<FeaturePair, ContactPoint>> brute_force_contacts(const PosedBody& A, const PosedBody& B);

}  // namespace polydem
