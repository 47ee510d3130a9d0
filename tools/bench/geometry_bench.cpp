// Micro-benchmark of the contact-geometry kernels: ns per feature_contact over Verlet candidates
// of touching body pairs, and ns per candidate_features rebuild. Prints CSV on stdout.
// Not built by CMake; from the repository root:
//   g++ -std=c++20 -O3 -DNDEBUG -Iinclude -Isrc -Itests/geometry -I/usr/include/eigen3
//       tools/bench/geometry_bench.cpp src/geometry/*.cpp -o /tmp/geometry_bench
//   /tmp/geometry_bench
#include <chrono>
#include <cstdio>
#include <random>
#include <vector>

#include "random_pairs.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

struct Scene {
  std::vector<Posed> a, b;
  std::vector<std::vector<FeaturePair>> candidates;
};

// `count` touching pairs of one shape kind, overlap up to rA + rB, with candidates for skin.
Scene make_scene(const Shape& shape, int count, double skin, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> frac(0.0, 1.0);
  Scene s;
  for (int k = 0; k < count; ++k) {
    PairPose p{&shape, &shape, 1.0, 1.0, random_rotation(rng), random_rotation(rng), random_unit(rng), Vec3::Zero()};
    const double along = touching_distance(p) - 2.0 * shape.radius * frac(rng);
    s.a.emplace_back(shape, 1.0, along * p.direction, p.qa);
    s.b.emplace_back(shape, 1.0, Vec3::Zero(), p.qb);
    s.candidates.emplace_back();
    candidate_features(s.a.back().body(), s.b.back().body(), skin, s.candidates.back());
  }
  return s;
}

template <typename F>
double seconds(F&& f) {
  const auto t0 = std::chrono::steady_clock::now();
  f();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void bench(const char* name, const Shape& shape, std::mt19937_64& rng) {
  const int pairs = 2000, repeats = 200;
  const double skin = 0.05;
  Scene s = make_scene(shape, pairs, skin, rng);
  std::vector<PosedBody> a, b;
  for (int k = 0; k < pairs; ++k) {
    a.push_back(s.a[k].body());
    b.push_back(s.b[k].body());
  }
  long calls = 0, contacts = 0;
  double gap_sum = 0.0;  // keeps the loop from being optimised away
  const double t_contact = seconds([&] {
    for (int r = 0; r < repeats; ++r)
      for (int k = 0; k < pairs; ++k)
        for (const FeaturePair& f : s.candidates[k]) {
          ContactPoint c;
          ++calls;
          if (feature_contact(a[k], b[k], f, 0.0, c)) {
            ++contacts;
            gap_sum += c.gap;
          }
        }
  });
  std::vector<FeaturePair> out;
  const double t_candidates = seconds([&] {
    for (int r = 0; r < repeats / 10; ++r)
      for (int k = 0; k < pairs; ++k) {
        out.clear();
        candidate_features(a[k], b[k], skin, out);
      }
  });
  std::printf("%s,%.2f,%.1f,%.2f,%.1f,%g\n", name, double(calls) / (double(pairs) * repeats),
              1e9 * t_contact / double(calls), double(contacts) / (double(pairs) * repeats),
              1e9 * t_candidates / (double(pairs) * (repeats / 10)), gap_sum);
}

}  // namespace

int main() {
  std::mt19937_64 rng(1);
  std::printf("shape,candidates_per_pair,ns_per_feature_contact,contacts_per_pair,ns_per_candidate_rebuild,checksum\n");
  bench("sphere", make_sphere(0.5), rng);
  bench("cube", make_cube(0.5, 0.05), rng);
  bench("octahedron", make_octahedron(0.6, 0.04), rng);
  bench("hex_prism", make_hex_prism(0.5, 0.3, 0.05), rng);
}
