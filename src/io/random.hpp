#pragma once
// Reproducible random numbers for scene generators: the same seed gives the same bodies with
// every compiler and standard library (std::mt19937_64 is fully specified; the standard
// distributions are not, so the conversions below are our own).
#include <cmath>
#include <cstdint>
#include <random>

#include "polydem/math.hpp"

namespace polydem {

// SplitMix64 finalizer (Steele, Lea, Flood 2014): spreads nearby seeds over the state space.
inline std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

// The stream of generator number `index` of a scene seeded with `seed`.
inline std::mt19937_64 generator_rng(std::uint64_t seed, std::uint64_t index) {
  return std::mt19937_64(splitmix64(seed ^ splitmix64(index)));
}

// Uniform in [0, 1): the top 53 bits of one draw, exact in a double.
inline double uniform01(std::mt19937_64& rng) {
  return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

// Uniform on SO(3) (Shoemake, "Uniform random rotations", Graphics Gems III, 1992).
inline Quat uniform_quaternion(std::mt19937_64& rng) {
  const double u1 = uniform01(rng);  // three statements: argument order is unspecified in C++
  const double u2 = uniform01(rng);
  const double u3 = uniform01(rng);
  const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
  return Quat(b * std::cos(2.0 * kPi * u3), a * std::sin(2.0 * kPi * u2),
              a * std::cos(2.0 * kPi * u2), b * std::sin(2.0 * kPi * u3));
}

}  // namespace polydem
