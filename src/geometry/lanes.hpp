#pragma once
// N doubles in one register (GCC vector extension): two (SSE2) for kernels that run two
// independent evaluations side by side (contact/law_lanes.hpp), four (AVX's 256 bits) for the
// same in the AVX builds only (lowered to SSE2 halves they cost more), one (a plain double) for a
// lone evaluation through the same code. Each lane does the scalar code's IEEE operations
// in its order (no FMA: the build has none, POLYDEM_NATIVE turns contraction off), so the same bits.
#include <cmath>
#include <type_traits>
#if defined(__SSE2__)
#include <emmintrin.h>  // _mm_movemask_pd (all)
#endif

#include "polydem/math.hpp"

namespace polydem::lanes {

// Types<4> runs only inlined into the AVX builds' copies (contact/law_lanes.hpp): no call passes
// a 256-bit vector, so GCC's note on their ABI without AVX does not apply. GCC inlines them all
// into the flatten copies; clang under UBSan left gather out of line, built for SSE2, which returns
// a 256-bit vector in memory where the AVX caller reads ymm0 (lanes 2 and 3 were garbage), so
// always_inline under clang (for GCC it cost +0.37% on the cubes). app/simd_builds.sh checks both.
#if defined(__clang__)
#define POLYDEM_LANE_INLINE [[gnu::always_inline]] inline
#define POLYDEM_LANE_LAMBDA __attribute__((always_inline))
#else
#define POLYDEM_LANE_INLINE inline
#define POLYDEM_LANE_LAMBDA
#endif
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"

template <int N>
struct Types;
template <>
struct Types<2> {
  using V = double __attribute__((vector_size(16)));
  using Mask = long long __attribute__((vector_size(16)));  // a comparison's lanes: all ones or 0
};
template <>
struct Types<4> {
  using V = double __attribute__((vector_size(32)));
  using Mask = long long __attribute__((vector_size(32)));
};
// One lane: a plain double and bool, so a comparison is a branch or a max, not a mask and its
// and/andn/or blend, and a lane's test a flag.
template <>
struct Types<1> {
  using V = double;
  using Mask = bool;
};
template <class V>
constexpr int kWidth = int(sizeof(V) / sizeof(double));

// Lane l of v (a vector, a mask or one lane's scalar).
template <class T>
POLYDEM_LANE_INLINE auto at(const T& v, int l) {
  if constexpr (std::is_arithmetic_v<T>) return v;
  else return v[l];
}

// Lane l of the result is get(l).
template <class V, class Get>
POLYDEM_LANE_INLINE V gather(const Get& get) {
  if constexpr (kWidth<V> == 4) return V{get(0), get(1), get(2), get(3)};
  else if constexpr (kWidth<V> == 2) return V{get(0), get(1)};
  else return V{get(0)};
}
template <class V>
POLYDEM_LANE_INLINE V splat(double x) {
  return gather<V>([&](int) { return x; });
}
template <class V>
POLYDEM_LANE_INLINE V max0(V a) { return a < splat<V>(0.0) ? splat<V>(0.0) : a; }  // std::max(a, 0.0), lane by lane
template <class V>
POLYDEM_LANE_INLINE V sqrt(V a) { return gather<V>([&](int l) { return std::sqrt(at(a, l)); }); }

// Whether every lane of m is set (a mask of two or four lanes, or one lane's bool).
template <class M>
POLYDEM_LANE_INLINE bool all(M m) {
  if constexpr (std::is_same_v<M, bool>) {
    return m;
  } else if constexpr (sizeof(M) == 32) {  // both halves' lanes
    using Half = long long __attribute__((vector_size(16)));
    return all(Half(__builtin_shufflevector(m, m, 0, 1) & __builtin_shufflevector(m, m, 2, 3)));
  } else {
#if defined(__SSE2__)
    return _mm_movemask_pd((__m128d)m) == 3;
#else
    return m[0] && m[1];
#endif
  }
}

template <class V>
struct Vec3Of {
  V x, y, z;
};
// Lane l holds get(l), a Vec3.
template <class V, class Get>
POLYDEM_LANE_INLINE Vec3Of<V> load(const Get& get) {
  return {gather<V>([&](int l) { return get(l).x(); }), gather<V>([&](int l) { return get(l).y(); }),
          gather<V>([&](int l) { return get(l).z(); })};
}
template <class V>
POLYDEM_LANE_INLINE Vec3Of<V> splat(const Vec3& a) { return {splat<V>(a.x()), splat<V>(a.y()), splat<V>(a.z())}; }
template <class V>
POLYDEM_LANE_INLINE Vec3 lane(const Vec3Of<V>& a, int l) { return Vec3(at(a.x, l), at(a.y, l), at(a.z, l)); }
template <class V>
POLYDEM_LANE_INLINE Vec3Of<V> operator+(const Vec3Of<V>& a, const Vec3Of<V>& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
template <class V>
POLYDEM_LANE_INLINE Vec3Of<V> operator-(const Vec3Of<V>& a, const Vec3Of<V>& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
template <class V>
POLYDEM_LANE_INLINE Vec3Of<V> operator*(V s, const Vec3Of<V>& a) { return {s * a.x, s * a.y, s * a.z}; }
template <class V, class M>
POLYDEM_LANE_INLINE Vec3Of<V> select(M m, const Vec3Of<V>& a, const Vec3Of<V>& b) {
  return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z};
}
// Eigen's orders for 3-vectors: dot and squaredNorm (x + y) + z, cross as in OrthoMethods.h.
template <class V>
POLYDEM_LANE_INLINE V dot(const Vec3Of<V>& a, const Vec3Of<V>& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }
template <class V>
POLYDEM_LANE_INLINE Vec3Of<V> cross(const Vec3Of<V>& a, const Vec3Of<V>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

#pragma GCC diagnostic pop

}  // namespace polydem::lanes
