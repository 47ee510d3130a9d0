#pragma once
// What the sphere lanes' tests share (test_sphere_lanes, test_sphere_wall_lanes): bitwise
// comparisons, random draws, the bed's law and step, spheres of a bed and a slot's random last step.
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

#include "contact/pair_kernel.hpp"

namespace polydem::test {

template <class T>
inline bool same_bits(const T& a, const T& b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }
inline bool same_bits(const ContactHistory& a, const ContactHistory& b) {
  return same_bits(a.ft, b.ft) && same_bits(a.mr, b.mr) && same_bits(a.fd, b.fd) && same_bits(a.gap, b.gap) &&
         same_bits(a.weight, b.weight) && a.slipping == b.slipping;
}
inline bool same_bits(const EnergyParts& a, const EnergyParts& b) {
  return same_bits(a.net, b.net) && same_bits(a.sliding, b.sliding) && same_bits(a.rolling, b.rolling) &&
         same_bits(a.patch, b.patch);
}

struct Draw {
  std::mt19937_64 rng{15};
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); }
  Vec3 vec(double scale) { return Vec3(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale)); }
  bool chance(double p) { return uniform(0.0, 1.0) < p; }
};

inline LawParams bed_law() {  // tools/bench/peers/spheres.yaml's, with the exact step
  ContactParams params;
  params.kn = 1e5;
  params.kt = 0.8e5;
  params.mu = 0.5;
  params.en = 0.3;
  LawParams law = prepare_law(params);
  law.exact_step = true;
  return law;
}
constexpr double kDt = 1e-5;  // s

// Bodies of a sphere bed: radius about 5 mm, density 2700, moving and spinning a little.
struct Spheres {
  std::vector<Vec3> position, velocity, spin, velocity_end, spin_end;
  std::vector<double> radius, mass;
  void add(Draw& d, const Vec3& x, double r) {
    position.push_back(x);
    radius.push_back(r);
    mass.push_back(2700.0 * 4.0 / 3.0 * M_PI * r * r * r);
    velocity.push_back(d.vec(0.05));
    spin.push_back(d.vec(5.0));
    velocity_end.push_back(velocity.back() + d.vec(0.005));
    spin_end.push_back(spin.back() + d.vec(0.5));
  }
  BodyView view() const {
    return {nullptr, position.data(), radius.data(), velocity.data(), spin.data(), velocity_end.data(),
            spin_end.data(), mass.data(), true};
  }
};

// A slot's last step: mostly a lasting overlap that sticks, now and then one that slips, starts or ends.
inline ContactHistory random_history(Draw& d) {
  ContactHistory h;
  h.ft = d.chance(0.05) ? Vec3::Zero() : d.vec(d.chance(0.15) ? 10.0 : 0.5);  // N: some slip under mu fn
  h.fd = d.uniform(-0.5, 0.5);
  h.gap = d.chance(0.1) ? d.uniform(0.0, 1e-5) : d.uniform(-1e-4, 0.0);
  h.slipping = d.chance(0.2);
  return h;
}

}  // namespace polydem::test
