#pragma once
// Two doubles in one SSE2 register (GCC vector extension), for kernels that run two independent
// evaluations in the two lanes (contact/law_lanes.hpp), each lane doing the scalar code's IEEE
// operations in its order (no FMA: the build has none, POLYDEM_NATIVE turns contraction off), so
// the same bits.
#include <cmath>

#include "polydem/math.hpp"

namespace polydem::lanes {

using V2 = double __attribute__((vector_size(16)));
using Mask = long long __attribute__((vector_size(16)));  // a comparison's lanes: all ones or 0

inline V2 splat(double x) { return V2{x, x}; }
inline V2 max0(V2 a) { return a < splat(0.0) ? splat(0.0) : a; }  // std::max(a, 0.0), lane by lane
inline V2 sqrt(V2 a) { return V2{std::sqrt(a[0]), std::sqrt(a[1])}; }

struct V3 {
  V2 x, y, z;
};
inline V3 load(const Vec3& a, const Vec3& b) { return {V2{a.x(), b.x()}, V2{a.y(), b.y()}, V2{a.z(), b.z()}}; }
inline V3 splat(const Vec3& a) { return {splat(a.x()), splat(a.y()), splat(a.z())}; }
inline Vec3 lane(const V3& a, int l) { return Vec3(a.x[l], a.y[l], a.z[l]); }
inline V3 operator+(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(const V3& a, const V3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator*(V2 s, const V3& a) { return {s * a.x, s * a.y, s * a.z}; }
inline V3 select(Mask m, const V3& a, const V3& b) { return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z}; }
// Eigen's orders for 3-vectors: dot and squaredNorm (x + y) + z, cross as in OrthoMethods.h.
inline V2 dot(const V3& a, const V3& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
inline V3 cross(const V3& a, const V3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

}  // namespace polydem::lanes
