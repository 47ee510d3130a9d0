#pragma once
// The steady sub-contacts of body pairs two at a time through the lanes' law: a pair whose
// sub-contacts would take law_in_lanes runs them in steady_law<2> two at a time, and an odd last
// one waits (parked) for the next such pair's, the two side by side in steady_law<2, kAcross>,
// each lane with its own pair's motions (pair_loop.hpp's lone_paired_pairs). Each lane does the lone code's operations in its order, and each pair's
// totals are made as apply_law makes them, its contacts added in its order: the same bits.
// Issue 19: a lone contact cost 268 + 81 instructions in one lane, a contact of a lane pair about
// 225; a pair of two or more ~230 of set-up (PairLaw's copy, the splats).
#include <utility>

#include "contact/law_lanes.hpp"
#include "contact/pair_kernel.hpp"

namespace polydem {

// a's contact ca beside b's contact cb, each lane with its own pair's values; settle(pair, c,
// steady, force, torque) takes each lane's result, a's first.
template <class Settle>
[[gnu::always_inline]] inline void lanes_across(LonePair& a, std::uint32_t ca, LonePair& b, std::uint32_t cb,
                                                const Settle& settle) {
  const LaneConstants* const pc[2] = {&a.lc, &b.lc};
  const ContactPoint* const g[2] = {&a.found[ca].geometry, &b.found[cb].geometry};
  const double w[2] = {a.weight[ca], b.weight[cb]};
  ContactHistory* const h[2] = {&a.found[ca].state->history, &b.found[cb].state->history};
  ContactForce f[2];
  Vec3 torque[2];
  const unsigned steady = steady_law<2, true>(pc, g, w, h, f, torque);
  settle(a, ca, (steady & 1u) != 0, f[0], torque[0]);
  settle(b, cb, (steady & 2u) != 0, f[1], torque[1]);
}

// b's sub-contacts two at a time through the lanes (one pair's values); an odd last one beside the
// waiting pair a's last (lanes_across), where one waits. Each lane's result to settle in its
// pair's order: b's lanes first, then its last.
template <class Settle>
[[gnu::always_inline]] inline Streamed stream_lanes(LonePair* a, LonePair& b, const Settle& settle) {
  std::uint32_t c = 0;
  for (; c + 1 < b.n; c += 2) {
    ContactForce f[2];
    Vec3 torque[2];
    const unsigned steady = steady_lanes(b.lc, b.found[c].geometry, b.found[c + 1].geometry, b.weight[c],
                                         b.weight[c + 1], b.found[c].state->history,
                                         b.found[c + 1].state->history, f, torque);
    settle(b, c, (steady & 1u) != 0, f[0], torque[0]);
    settle(b, c + 1, (steady & 2u) != 0, f[1], torque[1]);
  }
  if (c == b.n) return Streamed::kDone;
  if (!a) return Streamed::kWaits;
  lanes_across(*a, a->n - 1, b, c, settle);
  return Streamed::kBoth;
}

// A waiting pair a without a partner: its last contact in one lane, to settle.
template <class Settle>
inline void stream_last(LonePair& a, const Settle& settle) {
  const std::uint32_t c = a.n - 1;
  ContactForce f;
  Vec3 torque;
  const bool steady = steady_alone(a.lc, a.found[c].geometry, a.weight[c], a.found[c].state->history, f, torque);
  settle(a, c, steady, f, torque);
}

// The pair loop's kernel for body pairs under a law with lanes (lanes_law): pair_forces for
// pair k, or its sub-contacts left in a LonePair, and their law two at a time.
template <class Parts, class Partner>
struct LonePairKernel {
  static constexpr bool kLonePairs = true;
  using Lone = LonePair;
  const LawParams& law;
  double band, dt;  // m, s
  const BodyView& bodies;
  const Partner& partner;
  PairList& list;

  PairTotals operator()(std::uint32_t k, PairScratch& scratch) const {
    return pair_forces<Parts>(law, band, dt, bodies, partner, list, k, scratch);
  }
  // Pair k's totals (true), or false with its sub-contacts left in `lone` (in the scratch).
  [[gnu::always_inline]] bool forces(std::uint32_t k, PairScratch& scratch, PairTotals& totals, LonePair& lone) const {
    return pair_forces_into<Parts, true>(law, band, dt, bodies, partner, list, k, scratch, totals, &lone);
  }
  // b's sub-contacts (in the scratch) through the lanes, its odd last one beside the waiting pair
  // a's last where a waits (stream_lanes); b's totals made, or b parked out of the scratch to wait.
  [[gnu::always_inline]] Streamed lanes(LonePair* a, LonePair& b, PairScratch& scratch) const {
    const Streamed s = stream_lanes(a, b, settle(scratch));
    if (s == Streamed::kBoth) finish(*a);
    if (s == Streamed::kWaits) park(b, scratch);
    else finish(b);
    return s;
  }
  // A waiting pair without a partner: its last contact in one lane.
  void alone(LonePair& a, PairScratch& scratch) const {
    stream_last(a, settle(scratch));
    finish(a);
  }

 private:
  // A lane's contact c of pair a added from its force f and torque (steady), else through contact_force.
  [[gnu::always_inline]] auto settle(PairScratch& scratch) const {
    return [this, &scratch](LonePair& a, std::uint32_t c, bool steady, const ContactForce& f, const Vec3& torque)
               __attribute__((always_inline)) {
                 if (steady) add_to_totals<true>(a.found[c], a.totals, f, torque);
                 else by_law(a, c, scratch);
               };
  }
  // a's totals complete: the torque about j's centre and the count, as apply_law's.
  [[gnu::always_inline]] void finish(LonePair& a) const {
    const Vec3& xi = a.lc.xi;  // m
    a.totals.torque_j = -(a.totals.torque_i + (xi - partner.center(list.pairs[a.k].j)).cross(a.totals.force_i));
    a.totals.contacts = int(a.n);
  }
  // b waits: its sub-contacts out of the scratch, which the next pairs fill. A lone one is copied,
  // a larger set's vectors swapped with the spare ones (its pointers stay valid).
  [[gnu::always_inline]] void park(LonePair& b, PairScratch& scratch) const {
    if (b.n == 1) {
      b.one = b.found[0];
      b.one_weight = b.weight[0];
      b.found = &b.one;
      b.weight = &b.one_weight;
      return;
    }
    std::swap(scratch.found, scratch.waiting_found);
    std::swap(scratch.weight, scratch.waiting_weight);
  }
  // a's contact c that is not steady: contact_force through a's PairLaw, which reads the scratch;
  // a parked pair's contacts are lent to it (its vectors swapped in, a lone one copied into them).
  [[gnu::noinline]] void by_law(LonePair& a, std::uint32_t c, PairScratch& scratch) const {
    const bool parked = a.found != scratch.found.data();
    if (parked) {
      std::swap(scratch.found, scratch.waiting_found);
      std::swap(scratch.weight, scratch.waiting_weight);
      if (a.found == &a.one) {
        scratch.found.assign(1, a.one);
        scratch.weight.assign(1, a.one_weight);
      }
    }
    scratch.onsets = scratch.pushes = false;  // a waits only without them (apply_law)
    const PairLaw<Partner> pl{law, bodies, partner, list, scratch, a.k, list.pairs[a.k], a.r_star, a.lc,
                              a.nu_t, a.exact_step, a.totals};
    contact_by_law<Parts>(pl, c);
    if (parked) {
      std::swap(scratch.found, scratch.waiting_found);
      std::swap(scratch.weight, scratch.waiting_weight);
    }
  }
};

}  // namespace polydem
