// The two-lane law (law_lanes.hpp) and its one-lane form against contact_force, the reference: on
// random sub-contacts, a lane it takes has contact_force's bits (force, energies, history), one it
// leaves is untouched.
#include <catch2/catch.hpp>

#include <tuple>

#include "contact/law_lanes.hpp"
#include "law_lanes_draw.hpp"

using namespace polydem;
using namespace polydem::law_lanes_test;

TEST_CASE("law lanes: a steady lane, two or one, has contact_force's bits, another lane is left to it", "[law]") {
  const LawParams law = pile_law();
  using Parts = LawParts<NormalLinear, false, false, false>;
  Draw d{19};
  int steady = 0, left = 0, kept = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const double m_eff = d.uniform(1e-3, 3e-3), dt = 6.6e-6;  // kg, s
    const LaneConstants p{d.vec(0.1), d.vec(0.01), d.vec(1.0), d.vec(0.01), d.vec(1.0), m_eff,
                          pair_damping(law, m_eff), law.kn, law.kt, law.mu, dt};
    const ContactPoint g[2] = {random_point(d), random_point(d)};
    const double w[2] = {d.chance(0.3) ? 1.0 : d.uniform(0.0, 1.0), d.chance(0.05) ? 0.0 : d.uniform(0.0, 1.0)};
    const ContactHistory h0[2] = {random_history(d, w[0]), random_history(d, w[1])};
    ContactHistory h[2] = {h0[0], h0[1]};
    ContactForce f[2];
    Vec3 torque[2];
    const unsigned done = steady_lanes(p, g[0], g[1], w[0], w[1], h[0], h[1], f, torque);
    for (int l = 0; l < 2; ++l) {
      ContactHistory h_alone = h0[l];
      ContactForce f_alone;
      Vec3 torque_alone;
      const bool alone = steady_alone(p, g[l], w[l], h_alone, f_alone, torque_alone);
      REQUIRE(alone == bool(done & (1u << l)));  // a lane's fate is its own: the other lane plays no part
      if (!alone) {
        ++left;
        REQUIRE(same_bits(h[l], h0[l]));
        REQUIRE(same_bits(h_alone, h0[l]));
        continue;
      }
      ++steady;
      kept += h0[l].weight == w[l];  // steady_alone skips the patch terms then
      const SubContactMotion m = sub_contact_motion(g[l].point, p.xi, p.v_centre, p.w_rel, p.v_centre_end, p.w_rel_end);
      const ContactKinematics kin{g[l].normal, g[l].gap, m.v_rel, m.v_end, p.w_rel, m_eff, 0.0, w[l], p.nu, -1.0,
                                  0.0, false, nullptr};
      ContactHistory h_ref = h0[l];
      const ContactForce ref = contact_force<Parts>(law, kin, h_ref, dt);
      const Vec3 torque_ref = m.lever.cross(ref.force);
      for (const auto& [hl, fl, tl] : {std::tie(h[l], f[l], torque[l]), std::tie(h_alone, f_alone, torque_alone)}) {
        REQUIRE(same_bits(hl, h_ref));
        REQUIRE(same_bits(fl.force, ref.force));
        REQUIRE(same_bits(tl, torque_ref));
        REQUIRE(same_bits(fl.moment, ref.moment));
        REQUIRE(same_bits(fl.fn, ref.fn));
        REQUIRE(same_bits(fl.dissipated, ref.dissipated));
        REQUIRE(same_bits(fl.patch, ref.patch));
        REQUIRE(same_bits(fl.sliding, ref.sliding));
        REQUIRE(same_bits(fl.rolling, ref.rolling));
      }
    }
  }
  CHECK(steady > 15000);  // most draws rest and stick
  CHECK(left > 5000);     // and the rest exercise every way out
  CHECK(kept > 5000);     // a weight kept from the last step: no patch work (+0), as contact_force's
}

TEST_CASE("law lanes across pairs: each lane has its own pair's one-lane bits", "[law]") {
  const LawParams law = pile_law();
  Draw d{19};
  const auto random_pair = [&] {  // a pair's motions relative to i's centre, m_eff and nu (kg, N s/m)
    const double m_eff = d.uniform(1e-3, 3e-3);
    return LaneConstants{d.vec(0.1), d.vec(0.01), d.vec(1.0), d.vec(0.01), d.vec(1.0), m_eff,
                         pair_damping(law, m_eff), law.kn, law.kt, law.mu, 6.6e-6};
  };
  int steady = 0, left = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const LaneConstants p[2] = {random_pair(), random_pair()};  // two pairs' lone contacts (weight 1)
    const ContactPoint g[2] = {random_point(d), random_point(d)};
    const ContactHistory h0[2] = {random_history(d, 1.0), random_history(d, 1.0)};
    ContactHistory h[2] = {h0[0], h0[1]};
    const LaneConstants* const pc[2] = {&p[0], &p[1]};
    const ContactPoint* const gp[2] = {&g[0], &g[1]};
    const double w[2] = {1.0, 1.0};
    ContactHistory* const hp[2] = {&h[0], &h[1]};
    ContactForce f[2];
    Vec3 torque[2];
    const unsigned done = steady_law<2, true>(pc, gp, w, hp, f, torque);
    for (int l = 0; l < 2; ++l) {
      ContactHistory h_alone = h0[l];
      ContactForce f_alone;
      Vec3 torque_alone;
      const bool alone = steady_alone(p[l], g[l], 1.0, h_alone, f_alone, torque_alone);
      REQUIRE(alone == bool(done & (1u << l)));
      REQUIRE(same_bits(h[l], h_alone));  // advanced alike, or both left as they were
      if (!alone) {
        ++left;
        continue;
      }
      ++steady;
      REQUIRE(same_bits(f[l].force, f_alone.force));
      REQUIRE(same_bits(torque[l], torque_alone));
      REQUIRE(same_bits(f[l].fn, f_alone.fn));
      REQUIRE(same_bits(f[l].dissipated, f_alone.dissipated));
      REQUIRE(same_bits(f[l].patch, f_alone.patch));
    }
  }
  CHECK(steady > 15000);
  CHECK(left > 1000);
}
