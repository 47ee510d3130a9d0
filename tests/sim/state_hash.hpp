#pragma once
// A hash of the bodies' dynamic state, bit for bit: equal hashes mean identical runs.
#include <cstdint>

#include "polydem/bodies.hpp"

namespace polydem::test {

inline std::uint64_t fnv(std::uint64_t h, const void* data, std::size_t n) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t k = 0; k < n; ++k) h = (h ^ p[k]) * 1099511628211ull;
  return h;
}

inline std::uint64_t state_hash(const Bodies& b) {
  std::uint64_t h = 1469598103934665603ull;
  h = fnv(h, b.position.data(), b.size() * sizeof(Vec3));
  h = fnv(h, b.orientation.data(), b.size() * sizeof(Quat));
  h = fnv(h, b.velocity.data(), b.size() * sizeof(Vec3));
  h = fnv(h, b.angular_momentum.data(), b.size() * sizeof(Vec3));
  return h;
}

}  // namespace polydem::test
