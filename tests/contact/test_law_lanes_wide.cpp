// The four-lane law (steady_law<4>, law_lanes.hpp), as the AVX builds of the pair walk run it,
// against the one-lane law: on random sub-contacts of one pair and lone contacts of four pairs,
// each lane takes the same contacts with the same bits, and leaves the others untouched.
#include <catch2/catch.hpp>

#include "contact/law_lanes.hpp"
#include "law_lanes_draw.hpp"

using namespace polydem;
using namespace polydem::law_lanes_test;

namespace {

using law_lanes_test::same_bits;  // the overloads below add to them, not hide them
bool same_bits(const ContactForce& a, const ContactForce& b) {
  return same_bits(a.force, b.force) && same_bits(a.moment, b.moment) && same_bits(a.fn, b.fn) &&
         same_bits(a.dissipated, b.dissipated) && same_bits(a.patch, b.patch) && same_bits(a.sliding, b.sliding) &&
         same_bits(a.rolling, b.rolling);
}

// A pair's motions relative to i's centre, m_eff and nu (kg, N s/m), under a cube pile's law.
LaneConstants random_pair(Draw& d, const LawParams& law) {
  const double m_eff = d.uniform(1e-3, 3e-3);
  return LaneConstants{d.vec(0.1), d.vec(0.01), d.vec(1.0), d.vec(0.01), d.vec(1.0), m_eff,
                       pair_damping(law, m_eff), law.kn, law.kt, law.mu, 6.6e-6};
}

// steady_law<4> compiled as the walk's AVX copy runs it (where the CPU has AVX), within a pair or across pairs.
template <bool kAcross>
[[gnu::target("avx"), gnu::flatten, gnu::noinline]] unsigned four_lanes_avx(
    const LaneConstants* const pc[4], const ContactPoint* const g[4], const double w[4], ContactHistory* const h[4],
    ContactForce out[4], Vec3 torque[4]) {
  return steady_law<4, kAcross>(pc, g, w, h, out, torque);
}
template <bool kAcross>
unsigned four_lanes(const LaneConstants* const pc[4], const ContactPoint* const g[4], const double w[4],
                    ContactHistory* const h[4], ContactForce out[4], Vec3 torque[4]) {
  if (cpu_has_avx()) return four_lanes_avx<kAcross>(pc, g, w, h, out, torque);
  return steady_law<4, kAcross>(pc, g, w, h, out, torque);
}

// Lane by lane against steady_law<1> on `trials` draws of four lanes; counts the lanes taken.
template <bool kAcross>
int compare_four(int trials) {
  const LawParams law = pile_law();
  Draw d{45};
  int steady = 0;
  for (int trial = 0; trial < trials; ++trial) {
    LaneConstants p[4];
    for (int l = 0; l < 4; ++l) p[l] = kAcross || l == 0 ? random_pair(d, law) : p[0];
    ContactPoint g[4];
    double w[4];
    ContactHistory h0[4], h[4];
    for (int l = 0; l < 4; ++l) {
      g[l] = random_point(d);
      w[l] = kAcross || d.chance(0.3) ? 1.0 : d.chance(0.05) ? 0.0 : d.uniform(0.0, 1.0);  // lone contacts weigh 1
      h[l] = h0[l] = random_history(d, w[l]);
    }
    const LaneConstants* const pc[4] = {&p[0], &p[1], &p[2], &p[3]};
    const ContactPoint* const gp[4] = {&g[0], &g[1], &g[2], &g[3]};
    ContactHistory* const hp[4] = {&h[0], &h[1], &h[2], &h[3]};
    ContactForce f[4];
    Vec3 torque[4];
    const unsigned done = four_lanes<kAcross>(pc, gp, w, hp, f, torque);
    for (int l = 0; l < 4; ++l) {
      ContactHistory h_one = h0[l];
      ContactForce f_one;
      Vec3 torque_one;
      const bool one = steady_alone(p[l], g[l], w[l], h_one, f_one, torque_one);
      REQUIRE(one == bool(done & (1u << l)));  // a lane's fate is its own
      REQUIRE(same_bits(h[l], h_one));         // advanced alike, or both left as they were
      if (!one) {
        REQUIRE(same_bits(h[l], h0[l]));
        continue;
      }
      ++steady;
      REQUIRE(same_bits(f[l], f_one));
      REQUIRE(same_bits(torque[l], torque_one));
    }
  }
  return steady;
}

}  // namespace

TEST_CASE("law lanes: four sub-contacts of a pair have the one-lane law's bits, lane by lane", "[law]") {
  const int steady = compare_four<false>(10000);
  CHECK(steady > 15000);  // of 40,000 lanes (19,079 drawn): many rest and stick, the rest exercise every way out
  CHECK(steady < 35000);
}

TEST_CASE("law lanes: four pairs' lone contacts have the one-lane law's bits, lane by lane", "[law]") {
  const int steady = compare_four<true>(10000);
  CHECK(steady > 15000);  // 23,347 drawn
  CHECK(steady < 35000);
}
