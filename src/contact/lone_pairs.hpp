#pragma once
// Body pairs of one sub-contact two at a time through the lanes' law: a pair whose lone contact
// would take steady_law<1> (law_lanes.hpp) waits for the next such pair (pair_loop.hpp's
// lone_paired_pairs), and the two contacts run side by side in steady_law<2>, each lane with
// its own pair's motions. Each lane does the lone code's operations in its order, and each
// pair's totals are made as apply_law makes them: the same bits. Issue 19: a lone contact cost
// 268 + 81 instructions in one lane, a contact of a lane pair about 225.
#include "contact/law_lanes.hpp"
#include "contact/pair_kernel.hpp"

namespace polydem {

// The pair loop's kernel for body pairs under a law with lanes (lanes_law): pair_forces for
// pair k, or its lone contact left in a LonePair, and the law of one or two such pairs.
// kLanes: the law's lanes within a pair (apply_law); wide() is the AVX builds' kernel, of four.
template <class Parts, class Partner, int kLanes = 2>
struct LonePairKernel {
  static constexpr bool kLonePairs = true;
  using Lone = LonePair;
  const LawParams& law;
  double band, dt;  // m, s
  const BodyView& bodies;
  const Partner& partner;
  PairList& list;

  LonePairKernel<Parts, Partner, 4> wide() const { return {law, band, dt, bodies, partner, list}; }
  PairTotals operator()(std::uint32_t k, PairScratch& scratch) const {
    return pair_forces<Parts, kLanes>(law, band, dt, bodies, partner, list, k, scratch);
  }
  // Pair k's totals (true), or false with its lone contact waiting in `lone`.
  [[gnu::always_inline]] bool forces(std::uint32_t k, PairScratch& scratch, PairTotals& totals, LonePair& lone) const {
    return pair_forces_into<Parts, true, kLanes>(law, band, dt, bodies, partner, list, k, scratch, totals, &lone);
  }
  // The pair made last leaves the scratch to wait: its contact copied out.
  [[gnu::always_inline]] void park(LonePair& a, const PairScratch& scratch) const { a.contact = scratch.found[0]; }
  // The waiting pair a's contact beside b's, still in the scratch: each one's totals made.
  [[gnu::always_inline]] void lanes(LonePair& a, LonePair& b, PairScratch& scratch) const {
    const FoundContact* bc = &scratch.found[0];
    const LaneConstants* const pc[2] = {&a.lc, &b.lc};
    const ContactPoint* const g[2] = {&a.contact.geometry, &bc->geometry};
    const double w[2] = {1.0, 1.0};  // a lone contact's patch weight
    SlotState* const h[2] = {a.contact.state, bc->state};
    ContactForce f[2];
    Vec3 torque[2];
    const unsigned steady = steady_law<2, true>(pc, g, w, h, f, torque);
    if (steady != 3u) [[unlikely]] {  // by_law takes the scratch: b's contact copied out first
      b.contact = *bc;
      bc = &b.contact;
    }
    finish(a, a.contact, (steady & 1u) != 0, f[0], torque[0], scratch);
    finish(b, *bc, (steady & 2u) != 0, f[1], torque[1], scratch);
  }
  // A waiting pair without a partner: its contact in one lane.
  void alone(LonePair& a, PairScratch& scratch) const {
    ContactForce f;
    Vec3 torque;
    const bool steady = steady_alone(a.lc, a.contact.geometry, 1.0, *a.contact.state, f, torque);
    finish(a, a.contact, steady, f, torque, scratch);
  }

 private:
  // a's totals from its lane's force f and torque (steady) or contact_force, as apply_law's; its
  // contact c (a.contact, or b's in the scratch while it is steady).
  [[gnu::always_inline]] void finish(LonePair& a, const FoundContact& c, bool steady, const ContactForce& f,
                                     const Vec3& torque, PairScratch& scratch) const {
    if (steady) add_to_totals<true>(list, c, a.totals, f, torque);
    else by_law(a, scratch);
    const Vec3& xi = a.lc.xi;  // m
    a.totals.torque_j = -(a.totals.torque_i + (xi - partner.center(list.pairs[a.k].j)).cross(a.totals.force_i));
    a.totals.contacts = 1;
  }
  // A lane's contact that is not steady: contact_force through the pair's PairLaw, its contact
  // back in the (free) scratch.
  [[gnu::noinline]] void by_law(LonePair& a, PairScratch& scratch) const {
    scratch.found.assign(1, a.contact);
    scratch.weight.assign(1, 1.0);
    scratch.onsets = scratch.pushes = false;
    // No poses: a lane's law reads no contact mass (apply_law's `laned`).
    const PairLaw<Partner> pl{law,     bodies,  partner,  list, scratch, a.k,          list.pairs[a.k],
                              nullptr, nullptr, a.r_star, a.lc, a.nu_t,  a.exact_step, a.totals};
    contact_by_law<Parts>(pl, 0);
  }
};

}  // namespace polydem
