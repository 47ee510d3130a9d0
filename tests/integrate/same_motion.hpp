#pragma once
// Bit-for-bit comparisons of the integrator's per-body arrays, for the integrate tests.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "integrate/integrate.hpp"

namespace polydem::testing {

inline bool same_bits(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(Vec3)) == 0;
}

// The arrays every pass writes for every body (positions, velocities and the predicted
// end-of-step ones): b against ref, bit for bit.
inline void check_same_motion(const Bodies& b, const Bodies& ref) {
  CHECK(same_bits(b.position, ref.position));
  CHECK(same_bits(b.velocity, ref.velocity));
  CHECK(same_bits(b.angular_velocity, ref.angular_velocity));
  CHECK(same_bits(b.velocity_end, ref.velocity_end));
  CHECK(same_bits(b.angular_velocity_end, ref.angular_velocity_end));
}

}  // namespace polydem::testing
