// Feature-pair candidates for the Verlet lists, and vertex posing.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "geometry/features.hpp"
#include "geometry/segment.hpp"

namespace polydem {
namespace {

// Axis-aligned box of an edge (world, m): the distance between two boxes bounds the distance
// between their edges from below.
struct Box {
  Vec3 lo, hi;
};

// Features of one body that may come within `cutoff` of the other body's core, with their
// reach towards it: the largest (x - own centre) . u over the feature's vertices, u the unit
// vector from the own centre to the other's. Two features are at least
// L - reach_a - reach_b apart (L the distance between the centres: both project on the line
// of centres), an exact lower bound as cheap as a subtraction.
struct NearFeatures {
  std::vector<std::uint16_t> vertices, edges, faces;
  std::vector<double> vertex_reach, edge_reach, face_reach;  // m, one per entry
  std::vector<Box> edge_box;       // one per entry of `edges`
  std::vector<Vec3> face_normals;  // world, outward, one per entry of `faces`
  std::vector<double> projection;  // m, (vertex - own centre) . u per vertex of the body (scratch)
  // Per vertex of the body, bit f set when it lies beyond the other body's face f (one of its
  // first 64) by more than the cutoff: no point of the other's convex core is that near it.
  std::vector<std::uint64_t> beyond;
  double support = 0.0;  // m, largest projection: the body's reach towards the other
};

// Relative margin on the projection bound: round-off must never drop a true candidate.
constexpr double kProjectionMargin = 1e-9;
// Relative margin of the box and line bounds (of cutoff^2): a pair is dropped by them only when
// its exact distance would drop it too, so the candidates and their distances keep their bits.
constexpr double kBoxMargin = 1e-6;

// m^2, the squared distance between boxes a and b (0 when they overlap): at most the squared
// distance between any point of a and any point of b.
inline double box_gap2(const Box& a, const Box& b) {
  double g2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double g = std::max(std::max(a.lo[k] - b.hi[k], b.lo[k] - a.hi[k]), 0.0);  // m
    g2 += g * g;
  }
  return g2;
}
inline double box_gap2(const Vec3& p, const Box& b) { return box_gap2(Box{p, p}, b); }

// m, radius of the sphere about the centre of mass holding the core (unrounded) polyhedron.
double core_bounding_radius(const PosedBody& body) {
  double r2 = 0.0;
  for (std::size_t i = 0; i < body.shape->vertices.size(); ++i)
    r2 = std::max(r2, (body.vertices[i] - body.position).squaredNorm());
  return std::sqrt(r2);
}

// Squared distance from point p to a face (interior and boundary), skipping the edges when the
// face plane alone is already farther than the cutoff.
double face_distance_sq(const Vec3& p, const PosedBody& body, int face, const Vec3& n, double cutoff2) {
  const std::vector<int>& f = body.shape->faces[face];
  const double d = (p - body.vertices[f[0]]).dot(n);
  if (d * d >= cutoff2) return d * d;
  return point_polygon_distance_sq(p, body.vertices, f, n);
}

// Projections of the body's vertices on u (towards the other body) and their largest.
void project(const PosedBody& body, const Vec3& u, NearFeatures& near) {
  const std::size_t n = body.shape->vertices.size();
  near.projection.resize(n);
  near.support = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    near.projection[i] = (body.vertices[i] - body.position).dot(u);
    near.support = std::max(near.support, near.projection[i]);
  }
}

// The face-plane test: fills near.beyond for the vertices of `body` against the planes of the
// other body's faces that look towards it (`towards`: unit, from the other's centre to body's).
// A feature whose vertices all lie beyond one plane by more than `limit` is at least that far
// from a convex core, which lies behind every face plane: the exact distances would drop all
// its pairs. With the early end below, the settled cube pile's search went from 268e6 to 223e6
// instructions in 5 rebuilds (README, Benchmarks). Faces of a non-convex or open body bound
// nothing: no bits.
// Returns the planes the whole body lies beyond (a separating plane: no candidate at all).
std::uint64_t mark_beyond(const PosedBody& body, const PosedBody& other, const Vec3& towards, double limit,
                          NearFeatures& near) {
  const std::size_t n = body.shape->vertices.size();
  near.beyond.assign(n, 0);
  const Shape& s = *other.shape;
  if (!s.convex || s.surface) return 0;
  const std::size_t faces = std::min<std::size_t>(s.faces.size(), 64);
  const Vec3 towards_local = other.rotation.transpose() * towards;  // in the other's frame: one rotation
  for (std::size_t f = 0; f < faces; ++f) {
    if (s.face_normals[f].dot(towards_local) <= 0.0) continue;  // looks away: it rarely separates
    const Vec3 normal = other.rotation * s.face_normals[f];  // world, outward
    const Vec3& on_plane = other.vertices[s.faces[f][0]];
    for (std::size_t i = 0; i < n; ++i)
      if ((body.vertices[i] - on_plane).dot(normal) > limit) near.beyond[i] |= std::uint64_t(1) << f;
  }
  std::uint64_t all = ~std::uint64_t(0);
  for (std::uint64_t bits : near.beyond) all &= bits;
  return all;
}

// Fills `near` with the features of `body` that reach at least `floor` towards the other body
// (the slab test), lie beyond none of the other's face planes (near.beyond) and, for vertices
// and faces, closer than `reach` to its centre `centre` (the sphere test; for a face, its plane:
// the polygon's distance cost more than the pairs it spared), in index order. Edges take no
// sphere test: after the plane test it cost more than the pairs it spared (a cube pour: 1.0%).
// The slab test is cheap and runs first.
void collect_near(const PosedBody& body, const Vec3& centre, double reach, double floor, NearFeatures& near) {
  const Shape& s = *body.shape;
  const double reach2 = reach * reach;
  const std::vector<double>& proj = near.projection;
  near.vertices.clear();
  near.edges.clear();
  near.faces.clear();
  near.vertex_reach.clear();
  near.edge_reach.clear();
  near.face_reach.clear();
  near.face_normals.clear();
  near.edge_box.clear();
  const std::vector<std::uint64_t>& beyond = near.beyond;
  for (std::size_t i = 0; i < s.vertices.size(); ++i)
    if (proj[i] >= floor && !beyond[i] && (body.vertices[i] - centre).squaredNorm() < reach2) {
      near.vertices.push_back(static_cast<std::uint16_t>(i));
      near.vertex_reach.push_back(proj[i]);
    }
  for (std::size_t i = 0; i < s.edges.size(); ++i) {
    const double edge_reach = std::max(proj[s.edges[i][0]], proj[s.edges[i][1]]);
    if (edge_reach < floor || (beyond[s.edges[i][0]] & beyond[s.edges[i][1]])) continue;
    const Vec3& p0 = body.vertices[s.edges[i][0]];
    const Vec3& p1 = body.vertices[s.edges[i][1]];
    near.edges.push_back(static_cast<std::uint16_t>(i));
    near.edge_reach.push_back(edge_reach);
    near.edge_box.push_back({p0.cwiseMin(p1), p0.cwiseMax(p1)});
  }
  for (std::size_t i = 0; i < s.faces.size(); ++i) {
    double face_reach = -std::numeric_limits<double>::infinity();
    std::uint64_t face_beyond = ~std::uint64_t(0);  // planes every vertex of the face lies beyond
    for (int v : s.faces[i]) {
      face_reach = std::max(face_reach, proj[v]);
      face_beyond &= beyond[v];
    }
    if (face_reach < floor || face_beyond) continue;
    const Vec3 n = body.rotation * s.face_normals[i];
    const double d = (centre - body.vertices[s.faces[i][0]]).dot(n);  // m, the centre above the face plane
    if (d * d < reach2) {
      near.faces.push_back(static_cast<std::uint16_t>(i));
      near.face_reach.push_back(face_reach);
      near.face_normals.push_back(n);
    }
  }
}

// Where candidates go: the pairs, their core distances^2 (when asked) and the smallest of them.
struct CandidateSink {
  std::vector<FeaturePair>& pairs;
  std::vector<double>* distances2;  // m^2, or null
  double slab;                      // m, two features whose reaches sum below it are too far apart
  double box_limit2;                // m^2, edge boxes farther apart than its root hold no candidate
  double nearest2 = std::numeric_limits<double>::infinity();
};

// Keeps `pair` when its core distance^2 d2 is below cutoff2.
inline void keep_if_near(FeaturePair pair, double d2, double cutoff2, CandidateSink& out) {
  if (d2 >= cutoff2) return;
  out.pairs.push_back(pair);
  if (out.distances2) out.distances2->push_back(d2);
  out.nearest2 = std::min(out.nearest2, d2);
}

void append_vertex_pairs(const PosedBody& A, const PosedBody& B, const NearFeatures& na, const NearFeatures& nb,
                         double cutoff2, CandidateSink& out) {
  for (std::size_t i = 0; i < na.vertices.size(); ++i)
    for (std::size_t j = 0; j < nb.vertices.size(); ++j) {
      if (na.vertex_reach[i] + nb.vertex_reach[j] < out.slab) continue;
      const std::uint16_t va = na.vertices[i], vb = nb.vertices[j];
      keep_if_near({PairType::vertex_vertex, va, vb}, (A.vertices[va] - B.vertices[vb]).squaredNorm(), cutoff2, out);
    }
}

// Vertices of V against edges of E; `type` says which body is A.
void append_vertex_edge(const PosedBody& V, const PosedBody& E, const NearFeatures& nv, const NearFeatures& ne,
                        double cutoff2, PairType type, CandidateSink& out) {
  const bool v_is_a = type == PairType::vertex_edge;
  const std::size_t outer_count = v_is_a ? nv.vertices.size() : ne.edges.size();
  const std::size_t inner_count = v_is_a ? ne.edges.size() : nv.vertices.size();
  for (std::size_t oi = 0; oi < outer_count; ++oi)
    for (std::size_t ij = 0; ij < inner_count; ++ij) {
      const std::size_t iv = v_is_a ? oi : ij, ie = v_is_a ? ij : oi;
      if (nv.vertex_reach[iv] + ne.edge_reach[ie] < out.slab) continue;
      const std::uint16_t v = nv.vertices[iv], e = ne.edges[ie];
      if (box_gap2(V.vertices[v], ne.edge_box[ie]) > out.box_limit2) continue;
      const std::uint16_t i = v_is_a ? v : e, j = v_is_a ? e : v;
      const Vec3& p0 = E.vertices[E.shape->edges[e][0]];
      keep_if_near({type, i, j}, point_segment_distance_sq(V.vertices[v], p0, E.vertices[E.shape->edges[e][1]] - p0),
                   cutoff2, out);
    }
}

// Vertices of V against faces of F; `type` says which body is A.
void append_vertex_face(const PosedBody& V, const PosedBody& F, const NearFeatures& nv, const NearFeatures& nf,
                        double cutoff2, PairType type, CandidateSink& out) {
  const bool v_is_a = type == PairType::vertex_face;
  const std::size_t outer_count = v_is_a ? nv.vertices.size() : nf.faces.size();
  const std::size_t inner_count = v_is_a ? nf.faces.size() : nv.vertices.size();
  for (std::size_t i = 0; i < outer_count; ++i)
    for (std::size_t j = 0; j < inner_count; ++j) {
      const std::size_t iv = v_is_a ? i : j;
      const std::size_t jf = v_is_a ? j : i;
      if (nv.vertex_reach[iv] + nf.face_reach[jf] < out.slab) continue;
      const std::uint16_t v = nv.vertices[iv];
      const std::uint16_t f = nf.faces[jf];
      keep_if_near(v_is_a ? FeaturePair{type, v, f} : FeaturePair{type, f, v},
                   face_distance_sq(V.vertices[v], F, f, nf.face_normals[jf], cutoff2), cutoff2, out);
    }
}

// sin^2 of the angle above which two edges' common normal is trusted for the line test.
constexpr double kSkewSin2 = 1e-6;

// True when the lines of two skew edges (r = pa - pb, directions da, db) are farther apart than
// sqrt(limit2): the segments then are too. Decided on squares: no division, no square root.
inline bool lines_apart(const Vec3& r, const Vec3& da, const Vec3& db, double limit2) {
  const Vec3 c = da.cross(db);
  const double c2 = c.squaredNorm();
  if (c2 <= kSkewSin2 * da.squaredNorm() * db.squaredNorm()) return false;  // near parallel: no verdict
  const double rc = r.dot(c);  // m^3, line distance times |c|
  return rc * rc > limit2 * c2;
}

void append_edge_edge(const PosedBody& A, const PosedBody& B, const NearFeatures& na, const NearFeatures& nb,
                      double cutoff2, CandidateSink& out) {
  for (std::size_t i = 0; i < na.edges.size(); ++i) {
    const std::uint16_t ea = na.edges[i];
    const Vec3& pa = A.vertices[A.shape->edges[ea][0]];
    const Vec3 da = A.vertices[A.shape->edges[ea][1]] - pa;
    for (std::size_t j = 0; j < nb.edges.size(); ++j) {
      if (na.edge_reach[i] + nb.edge_reach[j] < out.slab) continue;
      if (box_gap2(na.edge_box[i], nb.edge_box[j]) > out.box_limit2) continue;
      const std::uint16_t eb = nb.edges[j];
      const Vec3& pb = B.vertices[B.shape->edges[eb][0]];
      const Vec3 db = B.vertices[B.shape->edges[eb][1]] - pb;
      if (lines_apart(pa - pb, da, db, out.box_limit2)) continue;
      keep_if_near({PairType::edge_edge, ea, eb}, segment_segment_distance_sq(pa, da, pb, db), cutoff2, out);
    }
  }
}

}  // namespace

void pose_vertices(const Shape& shape, double scale, const Vec3& position, const Mat3& rotation, Vec3* out) {
  const Mat3 rs = rotation * scale;
  const Vec3* local = shape.vertices.data();
  const std::size_t n = shape.vertices.size();  // read once: `out` might alias the shape for all the compiler knows
  for (std::size_t i = 0; i < n; ++i) out[i] = position + rs * local[i];
}

void pose_vertices(const Shape& shape, double scale, const Vec3& position, const Quat& q, Vec3* out) {
  pose_vertices(shape, scale, position, q.toRotationMatrix(), out);
}

double candidate_distance_sq(const PosedBody& A, const PosedBody& B, FeaturePair f, double cutoff2) {
  const auto on_edge = [](const PosedBody& P, const PosedBody& E, std::uint32_t v, std::uint32_t e) {  // m^2
    const Vec3& p0 = E.vertices[E.shape->edges[e][0]];
    return point_segment_distance_sq(P.vertices[v], p0, E.vertices[E.shape->edges[e][1]] - p0);
  };
  const auto on_face = [&](const PosedBody& P, const PosedBody& F, std::uint32_t v, std::uint32_t face) {  // m^2
    const Vec3 n = F.rotation * F.shape->face_normals[face];  // as collect_near's: the same bits
    return face_distance_sq(P.vertices[v], F, int(face), n, cutoff2);
  };
  switch (f.type) {
    case PairType::vertex_vertex: return (A.vertices[f.a] - B.vertices[f.b]).squaredNorm();
    case PairType::vertex_edge: return on_edge(A, B, f.a, f.b);
    case PairType::edge_vertex: return on_edge(B, A, f.b, f.a);
    case PairType::vertex_face: return on_face(A, B, f.a, f.b);
    case PairType::face_vertex: return on_face(B, A, f.b, f.a);
    case PairType::edge_edge: break;
  }
  const Vec3& pa = A.vertices[A.shape->edges[f.a][0]];
  const Vec3& pb = B.vertices[B.shape->edges[f.b][0]];
  return segment_segment_distance_sq(pa, A.vertices[A.shape->edges[f.a][1]] - pa, pb,
                                     B.vertices[B.shape->edges[f.b][1]] - pb);
}

double candidate_features(const PosedBody& A, const PosedBody& B, double range, std::vector<FeaturePair>& pairs,
                          std::vector<double>* distances2) {
  const double cutoff = A.radius + B.radius + range;
  const double cutoff2 = cutoff * cutoff;
  constexpr double kNone = std::numeric_limits<double>::infinity();
  // Reused per thread: rebuilds visit many body pairs, one allocation each would dominate.
  thread_local NearFeatures na, nb;
  const Vec3 axis = B.position - A.position;  // m
  const double length = axis.norm();
  // Slab: features of A and B reaching less than `slab` together along the line of centres are
  // farther apart than the cutoff (margin for round-off; no slab for coincident centres).
  const Vec3 u = length > 0.0 ? Vec3(axis / length) : Vec3::UnitZ();
  const double slab = length > 0.0 ? length - cutoff - kProjectionMargin * (length + cutoff)
                                   : -std::numeric_limits<double>::infinity();
  project(A, u, na);
  project(B, -u, nb);
  if (na.support + nb.support < slab) return kNone;  // the bodies' own supports are too far apart
  const double core_a = core_bounding_radius(A), core_b = core_bounding_radius(B);  // m
  // m, beyond a face plane by more than this, a vertex is out of reach (margin for round-off,
  // on the scale of the lengths the plane distances are made of).
  const double plane_limit = cutoff + kProjectionMargin * (length + cutoff + core_a + core_b);
  // A face plane that one whole body lies beyond separates them.
  if (mark_beyond(A, B, -u, plane_limit, na) || mark_beyond(B, A, u, plane_limit, nb)) return kNone;
  collect_near(A, B.position, core_b + cutoff, slab - nb.support, na);
  if (na.vertices.empty() && na.edges.empty() && na.faces.empty()) return kNone;
  collect_near(B, A.position, core_a + cutoff, slab - na.support, nb);
  CandidateSink out{pairs, distances2, slab, cutoff2 * (1.0 + kBoxMargin)};
  append_vertex_pairs(A, B, na, nb, cutoff2, out);
  append_vertex_edge(A, B, na, nb, cutoff2, PairType::vertex_edge, out);
  append_vertex_edge(B, A, nb, na, cutoff2, PairType::edge_vertex, out);
  append_vertex_face(A, B, na, nb, cutoff2, PairType::vertex_face, out);
  append_vertex_face(B, A, nb, na, cutoff2, PairType::face_vertex, out);
  append_edge_edge(A, B, na, nb, cutoff2, out);
  return std::sqrt(out.nearest2) - A.radius - B.radius;
}

}  // namespace polydem
