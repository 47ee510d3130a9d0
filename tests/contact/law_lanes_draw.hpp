#pragma once
// What the law-lanes tests draw and compare: random sub-contacts and histories of a resting pile,
// its linear law, and bit-for-bit equality of the law's values.
#include <cstdint>
#include <cstring>
#include <random>

#include "contact/law_lanes.hpp"

namespace polydem::law_lanes_test {

inline bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }
inline bool same_bits(const Vec3& a, const Vec3& b) {
  return same_bits(a.x(), b.x()) && same_bits(a.y(), b.y()) && same_bits(a.z(), b.z());
}
inline bool same_bits(const ContactHistory& a, const ContactHistory& b) {
  return same_bits(a.ft, b.ft) && same_bits(a.mr, b.mr) && same_bits(a.fd, b.fd) && same_bits(a.gap, b.gap) &&
         same_bits(a.weight, b.weight) && a.slipping == b.slipping;
}

struct Draw {
  std::mt19937_64 rng;
  explicit Draw(std::uint64_t seed) : rng(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  Vec3 vec(double scale) { return Vec3(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale)); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
};

// A sub-contact of a resting pile, now and then one that starts, ends, slips or sits at the band edge.
inline ContactPoint random_point(Draw& d) {
  ContactPoint g;
  g.normal = d.vec(1.0).normalized();
  g.point = d.vec(0.01);
  g.gap = d.chance(0.1) ? d.uniform(0.0, 1e-5) : d.uniform(-1e-4, 0.0);
  return g;
}
inline ContactHistory random_history(Draw& d, double weight) {
  ContactHistory h;
  if (d.chance(0.05)) return h;  // starts now
  h.ft = d.chance(0.1) ? Vec3::Zero() : d.vec(d.chance(0.2) ? 10.0 : 0.5);  // N: some slip under mu fn
  h.fd = d.uniform(-2.0, 2.0);
  h.gap = d.chance(0.1) ? d.uniform(0.0, 1e-5) : d.uniform(-1e-4, 0.0);
  h.weight = d.chance(0.5) ? weight : d.uniform(0.0, 1.0);
  h.slipping = d.chance(0.3);  // capped at the last step: a sticking lane clears it
  return h;
}

// The linear law of a cube pile (kn, kt in N/m).
inline LawParams pile_law() {
  ContactParams params;
  params.kn = 1e5;
  params.kt = 0.8e5;
  params.mu = 0.5;
  params.en = 0.3;
  return prepare_law(params);
}

}  // namespace polydem::law_lanes_test
