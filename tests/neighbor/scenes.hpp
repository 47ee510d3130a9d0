#pragma once
// Random test scenes for the broad phase: centres and bounding radii, seeded for repeatability.
#include <cstdint>
#include <random>
#include <vector>

#include "polydem/math.hpp"

namespace polydem::test {

struct Scene {
  std::vector<Vec3> centers;  // m
  std::vector<double> radii;  // m
};

// n bodies uniform in a cube of side `side`, radii uniform in [r_min, r_max].
inline Scene uniform_scene(std::size_t n, double side, double r_min, double r_max,
                           std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(0.0, side);
  std::uniform_real_distribution<double> rad(r_min, r_max);
  Scene s;
  for (std::size_t i = 0; i < n; ++i) {
    s.centers.emplace_back(pos(rng), pos(rng), pos(rng));
    s.radii.push_back(rad(rng));
  }
  return s;
}

// n bodies in `clusters` Gaussian blobs of width `spread` scattered in a cube of side `side`.
inline Scene clustered_scene(std::size_t n, std::size_t clusters, double side, double spread,
                             double r_min, double r_max, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> pos(0.0, side);
  std::normal_distribution<double> blob(0.0, spread);
  std::uniform_real_distribution<double> rad(r_min, r_max);
  std::uniform_int_distribution<std::size_t> pick(0, clusters - 1);
  std::vector<Vec3> seeds;
  for (std::size_t c = 0; c < clusters; ++c) seeds.emplace_back(pos(rng), pos(rng), pos(rng));
  Scene s;
  for (std::size_t i = 0; i < n; ++i) {
    s.centers.push_back(seeds[pick(rng)] + Vec3(blob(rng), blob(rng), blob(rng)));
    s.radii.push_back(rad(rng));
  }
  return s;
}

}  // namespace polydem::test
