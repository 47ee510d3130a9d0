#pragma once
// The parallel loop over the pairs of a list, shared by the contact engine and the sphere fast
// path (sphere_loop.cpp: its own translation unit, so GCC's unit growth limit leaves every call
// in the sphere kernel inlined).
#include <algorithm>
#include <cassert>
#include <type_traits>

#include "contact/pair_kernel.hpp"
#include "polydem/parallel.hpp"

namespace polydem {

// Runs `kernel(k, scratch) -> PairTotals` over every pair, keeps the per-pair forces in the list,
// adds each pair's energy to its own list.pending[k] (in step order: the same bits whatever
// thread runs it), keeps each block's contact count in list.block_contacts and flags in
// list.block_ended the blocks where a pair's contact ended (sized by resize_results).
// kNoWait: the threads go on without meeting at the loop's end (the next loop reads none of
// this list's results; a later barrier comes before anything that does).
// With `direct` (body pairs) and a team of one thread, each pair's force and torques are added
// to its bodies' sums instead (in pair order: the bits of the closing pass's sum, none of its
// reads of the pairs' results at random); direct->on says which was done.
template <bool kNoWait = false, class Kernel>
void all_pair_forces(PairList& list, const Kernel& kernel, DirectSums* direct = nullptr) {
  const std::size_t n = list.size(), blocks = (n + kPairBlock - 1) / kPairBlock;
  assert(list.block_contacts.size() == blocks && list.block_ended.size() == blocks);
  assert(list.pending.size() == n);
  auto one_block = [&](std::size_t b, PairScratch& scratch, auto to_bodies) {
    std::uint32_t contacts = 0;
    bool ended = false;
    BodySum* const sums = to_bodies ? direct->sums.data() : nullptr;
    for (std::size_t k = b * kPairBlock; k < std::min(n, (b + 1) * kPairBlock); ++k) {
      const PairTotals t = kernel(std::uint32_t(k), scratch);
      if constexpr (decltype(to_bodies)::value) {  // a pair out of reach adds +0: no sum's bits change
        const BodyPair p = list.pairs[k];
        sums[p.i].force += t.force_i;
        sums[p.i].torque += t.torque_i;
        sums[p.j].force -= t.force_i;
        sums[p.j].torque += t.torque_j;
      } else {
        list.force_i[k] = t.force_i;
        list.torque_i[k] = t.torque_i;
        list.torque_j[k] = t.torque_j;
      }
      ended |= (list.touching[k] != 0) & (t.contacts == 0);  // touching at the last step, not now
      list.touching[k] = std::uint16_t(t.contacts);
      list.pending[k] += t.energy;
      contacts += std::uint32_t(t.contacts);
    }
    list.block_contacts[b] = contacts;
    list.block_ended[b] = ended;
  };
  // Small scenes (one block) wake no thread; inside a team the blocks are shared (parallel.hpp).
  in_team(blocks >= 2, [&] {
    PairScratch scratch;
    if (direct && omp_get_num_threads() == 1) {  // this thread alone: no other reads or writes `direct`
      direct->on = true;
      std::fill(direct->sums.begin(), direct->sums.end(), BodySum{});
      for (std::size_t b = 0; b < blocks; ++b) one_block(b, scratch, std::true_type{});
      return;
    }
    if (direct) {
#pragma omp master
      direct->on = false;  // read after the barrier that ends the contact stage
    }
    if constexpr (kNoWait) {
#pragma omp for schedule(dynamic, 1) nowait
      for (std::size_t b = 0; b < blocks; ++b) one_block(b, scratch, std::false_type{});
    } else {
#pragma omp for schedule(dynamic, 1)
      for (std::size_t b = 0; b < blocks; ++b) one_block(b, scratch, std::false_type{});
    }
  });
}

// Calls run(flag), flag a std::bool_constant<on>: a run-time switch made a compile-time one.
template <class Run>
void with_flag(bool on, const Run& run) {
  if (on)
    run(std::true_type{});
  else
    run(std::false_type{});
}

// Calls run(parts), parts a LawParts naming the law's parts at compile time: the pair loops
// are compiled once per combination and chosen here, once per step (law.hpp). The alternative,
// one loop testing LawParams' flags per contact, costs a branch per part and contact.
template <class Run>
void with_law(const LawParams& law, const Run& run) {
  with_flag(law.normal == NormalModel::hertz, [&](auto hertz) {
    using Normal = std::conditional_t<decltype(hertz)::value, NormalHertz, NormalLinear>;
    with_flag(law.cohesion, [&](auto cohesion) {
      with_flag(law.rolling, [&](auto rolling) {
        with_flag(law.tangential_damping, [&](auto dashpot) {
          run(LawParts<Normal, decltype(cohesion)::value, decltype(rolling)::value, decltype(dashpot)::value>{});
        });
      });
    });
  });
}

}  // namespace polydem
