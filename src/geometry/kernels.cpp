// Feature-pair contact kernels and their dispatch table (the hot inner loop of the contact stage).
// Every kernel works on differences from one vertex of a feature (a local frame there), so its
// round-off scales with the feature size rather than with the world coordinates.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdlib>

#include "geometry/features.hpp"
#include "geometry/segment.hpp"

namespace polydem {
namespace {

// Distance between core edges, relative to the longer edge, under which the cores count as
// crossing and the edge-edge normal comes from the centres instead of the closest points.
constexpr double kCrossingTolerance = 1e-12;

// Every kernel's `return false` goes through here: out.gap 1 where rejection_allowance makes an
// allowance for it (features.hpp), else 0. A constant: the kernel keeps nothing alive for it.
inline bool rejected(ContactPoint& out, bool allowed = false) {
  out.gap = allowed ? 1.0 : 0.0;
  return false;
}

// Fills `out` from the closest core points ca (on A), cb (on B) and the unit normal from B to A.
// kFlip: the kernel runs with the bodies swapped (swapped<K>) and stores the normal turned back, from
// the caller's B to its A: -n is exact, the same bits as turning the stored one after.
template <bool kFlip = false>
inline void fill(const PosedBody& A, const PosedBody& B, const Vec3& ca, const Vec3& cb, const Vec3& n,
                 double gap, ContactPoint& out) {
  out.normal = kFlip ? Vec3(-n) : n;
  out.gap = gap;
  out.point = 0.5 * ((ca - A.radius * n) + (cb + B.radius * n));
}

// Unit vector along u with the part along axis removed (zero axis: keep u); a fixed
// perpendicular of the axis when nothing is left, so the result is always unit and deterministic.
inline Vec3 perpendicular_direction(Vec3 u, const Vec3& axis) {
  const double a2 = axis.squaredNorm();
  if (a2 > 0.0) u -= (u.dot(axis) / a2) * axis;
  const double n2 = u.squaredNorm();
  if (n2 > 0.0) return u / std::sqrt(n2);
  return a2 > 0.0 ? Vec3(axis.unitOrthogonal()) : Vec3::UnitZ();
}

// True when the core distance d (>= 0) gives gap >= max_gap, decided on squares (no sqrt).
inline bool too_far_sq(double d2, double radius_sum, double max_gap) {
  const double limit = radius_sum + max_gap;
  return limit <= 0.0 || d2 >= limit * limit;
}

// True when u.w < 0 beyond round-off (relative to |w|): flat cores hold their centre in a face.
inline bool clearly_negative(double uw, const Vec3& w) {
  return uw < 0.0 && uw * uw > kInteriorMargin * kInteriorMargin * w.squaredNorm();
}

// True when the normal n (from B to A) points into A or into B as seen from their centres, so
// that it cannot be a normal of either core at its closest point: the closest-point direction
// turned over because the cores pass through each other. A closest pair of separated convex
// cores always passes: n.(cb - xB) >= 0 and n.(ca - xA) <= 0.
// Only convex cores are judged so: a non-convex body's centre may lie outside its core (a bent
// polyline) or behind a feature it touches with (the inside of a hook), so the rule does not
// hold there; their cores are thin sets, whose closest points do not turn over.
inline bool points_into(const Vec3& n, const Vec3& ca, const Vec3& cb, const PosedBody& A, const PosedBody& B) {
  const Vec3 wb = cb - B.position;
  const Vec3 wa = A.position - ca;
  return (clearly_negative(n.dot(wb), wb) || clearly_negative(n.dot(wa), wa)) && A.shape->convex &&
         B.shape->convex;  // read last: the rule rarely fires
}

// For a vertex p inside B's core at signed depth d < 0 below face f: true when f is the face it
// is least deep under (ties to the lowest index), the face it will leave through. Other faces
// would give a sideways push; only called for interpenetrating cores, O(faces).
bool is_exit_face(const PosedBody& B, int f, const Vec3& p, double d) {
  const Shape& s = *B.shape;
  for (int g = 0; g < static_cast<int>(s.faces.size()); ++g) {
    if (g == f) continue;
    const double dg = (p - B.vertices[s.faces[g][0]]).dot(B.rotation * s.face_normals[g]);
    if (dg > d || (dg == d && g < f)) return false;
  }
  return true;
}

bool vertex_vertex(const PosedBody& A, const PosedBody& B, int a, int b, double max_gap, ContactPoint& out) {
  const Vec3& ca = A.vertices[a];
  const Vec3& cb = B.vertices[b];
  const Vec3 u = ca - cb;
  const double rsum = A.radius + B.radius;
  const double d2 = u.squaredNorm();
  if (too_far_sq(d2, rsum, max_gap)) return rejected(out);
  const double d = std::sqrt(d2);
  // Coincident cores (a sphere centred on a vertex): fall back on the line of centres.
  const Vec3 n = d > 0.0 ? Vec3(u / d) : perpendicular_direction(A.position - B.position, Vec3::Zero());
  if (points_into(n, ca, cb, A, B)) return rejected(out);
  fill(A, B, ca, cb, n, d - rsum, out);
  return true;
}

template <bool kFlip = false>
bool vertex_edge(const PosedBody& A, const PosedBody& B, int a, int b, double max_gap, ContactPoint& out) {
  const std::array<int, 2>& edge = B.shape->edges[b];
  const Vec3& p0 = B.vertices[edge[0]];
  const Vec3 e = B.vertices[edge[1]] - p0;
  const Vec3& ca = A.vertices[a];
  const Vec3 w = ca - p0;
  const double len2 = e.squaredNorm();
  const double tl = w.dot(e);  // t * len2, t the parameter of the projection on the edge
  if (!inside_segment(tl, len2)) return rejected(out);
  const Vec3 foot = (tl / len2) * e;
  const Vec3 u = w - foot;
  const double rsum = A.radius + B.radius;
  const double d2 = u.squaredNorm();
  if (too_far_sq(d2, rsum, max_gap)) return rejected(out);
  const double d = std::sqrt(d2);
  const Vec3 n = d > 0.0 ? Vec3(u / d) : perpendicular_direction(A.position - B.position, e);
  const Vec3 cb = p0 + foot;
  if (points_into(n, ca, cb, A, B)) return rejected(out);
  fill<kFlip>(A, B, ca, cb, n, d - rsum, out);
  return true;
}

// True when the vertex p projects strictly inside B's face f (projects_inside_polygon), tested
// in B's principal frame against the face's edge planes (face_planes.hpp): one rotation of p,
// then a dot product per edge, where the world-frame test takes a cross product per edge.
inline bool inside_face(const PosedBody& B, int f, const Vec3& p) {
  const Shape& s = *B.shape;
  const Vec3 q = B.rotation.transpose() * (p - B.position);  // m, p in B's frame (scaled)
  const Plane* edge = s.edge_planes.data() + s.edge_plane_begin[f];
  const Plane* end = s.edge_planes.data() + s.edge_plane_begin[f + 1];
  const auto within = [&](const Plane& e) { return !(e.normal.dot(q) <= B.scale * e.offset); };  // planes at scale 1
  // A quadrilateral (every face of the cubes' calls): the same tests in the same order, without the
  // loop's count and step (~10 of vertex_face's 180 instructions).
  if (end - edge == 4) return within(edge[0]) && within(edge[1]) && within(edge[2]) && within(edge[3]);
  for (; edge != end; ++edge)
    if (!within(*edge)) return false;
  return true;
}

// The rejections' allowances (features.hpp). A body's displacement bound d since the build
// (rebuild_trigger.hpp) covers its points within its core reach R, so between steps n and n' a core
// point moves by at most d(n) + d(n'), the body turns by a chord of at most (d(n) + d(n')) / R, and
// the body's frame under a point at y from its centre moves by at most max(1, |y| / R) times that.
// M below is the pair's sum of both bodies' bounds at n and n'. The guards, 1e-12 of the terms'
// sizes, cover both steps' round-off (~1e-16 relative) in the kernels' tests.
constexpr double kAllowanceGuard = 1e-12;
constexpr double kAllowanceShrink = 1.0 - 1e-9;  // the reach's and the allowance's own round-off

// m, at most B's core reach: the distance of its core vertex v from its centre.
inline double reach_below(const PosedBody& B, int v) { return (B.vertices[v] - B.position).norm() * kAllowanceShrink; }

// m: vertex p (of A) projects outside B's face f. It stays beyond the edge plane it is farthest
// beyond (by h, m) while its place in B's frame moves less than h, at most max(1, |p - xB| / R_B) M.
double outside_face_allowance(const PosedBody& B, int f, const Vec3& p) {
  const Shape& s = *B.shape;
  const Vec3 y = p - B.position;  // m
  const Vec3 q = B.rotation.transpose() * y;
  double beyond = 0.0;  // m
  for (int e = s.edge_plane_begin[f]; e < s.edge_plane_begin[f + 1]; ++e)
    beyond = std::max(beyond, B.scale * s.edge_planes[e].offset - s.edge_planes[e].normal.dot(q));
  const double reach = reach_below(B, s.faces[f][0]), y_norm = y.norm();  // m
  beyond -= kAllowanceGuard * (y_norm + reach);
  if (!(beyond > 0.0) || !(reach > 0.0)) return 0.0;
  return kAllowanceShrink * beyond / std::max(1.0, y_norm / reach);
}

// m: one edge's side of an edge-edge rejection. On its line, g(s) = d . P (p + s d - p_other)
// (P removes the other edge's direction) grows with s and is 0 at the lines' closest point, so the
// point lies before its start where g(0) = -x_c2 / len2_other > 0 and past its end where
// g(1) = (c2 - x_c2) / len2_other < 0 (x_c2 its parameter times c2, `guard` their round-off). In the
// other body's frame its ends move by at most lambda M and d turns by at most M / reach, so g changes
// by less than |d| M (2 lambda + rho / reach) for M <= reach, rho >= |P (its end - p_other)|.
double edge_end_allowance(double x_c2, double c2, double len2_other, double guard, double d_len, double lambda,
                          double rho, double reach) {
  const double margin = std::max(-x_c2 - guard, x_c2 - c2 - guard) / len2_other;  // m^2, |g| less the guard
  if (!(margin > 0.0) || !(reach > 0.0)) return 0.0;
  return kAllowanceShrink * std::min(reach, margin / (d_len * (2.0 * lambda + rho / reach)));
}

// m: edges a (of A) and b (of B) whose lines' closest points lie beyond an end of either edge,
// its terms made again as edge_edge makes them.
double beyond_ends_allowance(const PosedBody& A, const PosedBody& B, int a, int b) {
  const std::array<int, 2>& edge_a = A.shape->edges[a];
  const std::array<int, 2>& edge_b = B.shape->edges[b];
  const Vec3& pa = A.vertices[edge_a[0]];
  const Vec3& pb = B.vertices[edge_b[0]];
  const Vec3 da = A.vertices[edge_a[1]] - pa, db = B.vertices[edge_b[1]] - pb, r = pa - pb;
  const double aa = da.squaredNorm(), bb = db.squaredNorm(), ab = da.dot(db), ra = da.dot(r), rb = db.dot(r);
  const double c2 = da.cross(db).squaredNorm();
  const double s_c2 = ab * rb - ra * bb, t_c2 = aa * rb - ab * ra;
  const double la = std::sqrt(aa), lb = std::sqrt(bb), lr = r.norm();  // m
  const double reach_a = reach_below(A, edge_a[0]), reach_b = reach_below(B, edge_b[0]);
  const double reach = std::min(reach_a, reach_b);  // m, for the turn
  if (!(reach > 0.0)) return 0.0;
  const double lambda_a = std::max(1.0, ((pa - B.position).norm() + la) / reach_b);  // A's edge in B's frame
  const double lambda_b = std::max(1.0, ((pb - A.position).norm() + lb) / reach_a);  // B's edge in A's frame
  const double guard_s = 2.0 * kAllowanceGuard * la * bb * (lr + la), guard_t = 2.0 * kAllowanceGuard * lb * aa * (lr + lb);
  return std::max(edge_end_allowance(s_c2, c2, bb, guard_s, la, lambda_a, lr + la, reach),
                  edge_end_allowance(t_c2, c2, aa, guard_t, lb, lambda_b, lr + lb, reach));
}

// A vertex at signed distance d < 0 of a face of a non-convex body: its faces are two-sided
// (an open surface, a plate, a facet of a hollow), so the vertex touches the back side, with the
// normal reversed (as Rockable and exaDEM take |d|).
template <bool kFlip>
bool back_side(const PosedBody& A, const PosedBody& B, const Vec3& ca, const Vec3& n, double d, double max_gap,
               ContactPoint& out) {
  const double gap = -d - A.radius - B.radius;
  if (gap >= max_gap) return rejected(out);
  fill<kFlip>(A, B, ca, ca - d * n, -n, gap, out);
  return true;
}

// The polygon test first: it rejects a quarter of the calls on a cube pile, the depth test few.
// Depth, normal and gap are then made in the world, as before the edge planes: the same bits.
template <bool kFlip = false>
bool vertex_face(const PosedBody& A, const PosedBody& B, int a, int b, double max_gap, ContactPoint& out) {
  const Vec3& ca = A.vertices[a];
  if (!inside_face(B, b, ca)) return rejected(out, true);
  const Vec3 n = B.rotation * B.shape->face_normals[b];  // outward normal of B's face, world
  const double d = (ca - B.vertices[B.shape->faces[b][0]]).dot(n);  // signed: negative below the face plane
  const double rsum = A.radius + B.radius;
  if (d < 0.0 && !B.shape->convex) return back_side<kFlip>(A, B, ca, n, d, max_gap, out);
  if (d <= -rsum || d - rsum >= max_gap) return rejected(out);
  if (d < 0.0 && !is_exit_face(B, b, ca, d)) return rejected(out);
  fill<kFlip>(A, B, ca, ca - d * n, n, d - rsum, out);
  return true;
}

bool edge_edge(const PosedBody& A, const PosedBody& B, int a, int b, double max_gap, ContactPoint& out) {
  const std::array<int, 2>& edge_a = A.shape->edges[a];
  const std::array<int, 2>& edge_b = B.shape->edges[b];
  const Vec3& pa = A.vertices[edge_a[0]];
  const Vec3& pb = B.vertices[edge_b[0]];
  const Vec3 da = A.vertices[edge_a[1]] - pa;
  const Vec3 db = B.vertices[edge_b[1]] - pb;
  const Vec3 c = da.cross(db);
  const double c2 = c.squaredNorm();
  const double aa = da.squaredNorm();
  const double bb = db.squaredNorm();
  if (c2 <= kParallelSin2 * aa * bb) return rejected(out);
  const Vec3 r = pa - pb;
  const double rc = r.dot(c);  // line-line distance times |c|
  const double rsum = A.radius + B.radius;
  const double limit = rsum + max_gap;  // m
  if (limit <= 0.0 || rc * rc >= limit * limit * c2) return rejected(out);  // too far: no division, no sqrt
  const double ab = da.dot(db);
  const double ra = da.dot(r);
  const double rb = db.dot(r);
  const double s_c2 = ab * rb - ra * bb;  // s c2 and t c2: the interior test needs no division
  const double t_c2 = aa * rb - ab * ra;
  if (!inside_segment(s_c2, c2) || !inside_segment(t_c2, c2))
    return rejected(out, true);
  const double s = s_c2 / c2, t = t_c2 / c2;
  const double inv_c = 1.0 / std::sqrt(c2);
  const double signed_d = rc * inv_c;  // line-line distance along the common normal
  if (std::abs(signed_d) - rsum >= max_gap) return rejected(out);
  Vec3 n = c * inv_c;
  // Crossing cores: the closest-point direction is noise, orient the common normal from B's centre to A's.
  const bool crossing = std::abs(signed_d) <= kCrossingTolerance * std::sqrt(std::max(aa, bb));
  const double side = crossing ? n.dot(A.position - B.position) : signed_d;
  if (side < 0.0) n = -n;
  const Vec3 ca = pa + s * da;
  const Vec3 cb = pb + t * db;
  if (points_into(n, ca, cb, A, B)) return rejected(out);
  fill(A, B, ca, cb, n, std::abs(signed_d) - rsum, out);
  return true;
}

// Evaluates kernel K (its kFlip build, which stores the normal turned back to point from B to A)
// with the bodies swapped: edge_vertex from vertex_edge, face_vertex from vertex_face; gap and point
// are symmetric.
template <FeatureKernel K>
[[gnu::flatten]] bool swapped(const PosedBody& A, const PosedBody& B, int a, int b, double max_gap, ContactPoint& out) {
  return K(B, A, b, a, max_gap, out);
}

// Kernel K compiled for AVX: its VEX three-operand forms need none of SSE2's register copies
// (the settled cubes' kernels ~22% fewer instructions). The same IEEE operations in the same
// order, none fused (the target has no FMA): the same bits, checked by kernel_builds_test.cpp.
template <FeatureKernel K>
[[gnu::target("avx"), gnu::flatten]] bool avx(const PosedBody& A, const PosedBody& B, int a, int b, double max_gap,
                                               ContactPoint& out) {
  return K(A, B, a, b, max_gap, out);
}

}  // namespace

double rejection_allowance(const PosedBody& A, const PosedBody& B, FeaturePair pair) {
  switch (pair.type) {
    case PairType::vertex_face: return outside_face_allowance(B, int(pair.b), A.vertices[pair.a]);
    case PairType::face_vertex: return outside_face_allowance(A, int(pair.a), B.vertices[pair.b]);
    case PairType::edge_edge: return beyond_ends_allowance(A, B, int(pair.a), int(pair.b));
    default: return 0.0;
  }
}

// Indexed by PairType; no virtual call per contact.
const std::array<FeatureKernel, kPairTypeCount> kSse2Kernels = {
    vertex_vertex, vertex_edge, swapped<vertex_edge<true>>, vertex_face, swapped<vertex_face<true>>, edge_edge};
const std::array<FeatureKernel, kPairTypeCount> kAvxKernels = {
    avx<vertex_vertex>, avx<vertex_edge>, avx<swapped<vertex_edge<true>>>,
    avx<vertex_face>,   avx<swapped<vertex_face<true>>>, avx<edge_edge>};

bool cpu_has_avx() {
  if (std::getenv("POLYDEM_SSE2")) return false;  // the SSE2 builds asked for: to compare (README "The AVX builds")
  __builtin_cpu_init();  // this may run in a static initializer before libgcc's own
  return __builtin_cpu_supports("avx");
}

// Chosen once at start-up: every thread and rank of a run on one machine takes the same build.
const bool kHasAvx = cpu_has_avx();
const std::array<FeatureKernel, kPairTypeCount> kFeatureKernels = kHasAvx ? kAvxKernels : kSse2Kernels;

}  // namespace polydem
