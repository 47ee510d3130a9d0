// Steady sphere pairs two at a time and one alone (sphere_lanes.hpp) against sphere_pair_forces, the
// reference: a lane it takes has the pair's bits (totals, history), one it leaves is untouched; the
// one-lane kernel takes the same pairs with the same bits; and the whole
// sphere loop with the lanes ends with the bits of the loop without them (sums in list order).
#include <catch2/catch.hpp>

#include "contact/sphere_lanes.hpp"
#include "sphere_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// A list of `pairs` (sorted), each with one slot of random history but the ~5% out of reach at the build.
PairList random_list(Draw& d, const std::vector<BodyPair>& pairs, const LawParams& law, const Spheres& s,
                     bool pair_steps) {
  PairList list;
  list.pairs = pairs;
  list.resize_results(pair_steps);
  list.slot_begin.push_back(0);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const bool slot = !d.chance(0.05);
    list.slot_begin.push_back(list.slot_begin.back() + slot);
    if (!slot) continue;
    list.slots.push_back({random_history(d), {}});
    list.active.push_back(!d.chance(0.05));
    if (!list.active.back()) list.slots.back().history = ContactHistory{};
    list.touching[k] = list.active.back();
    if (list.touching[k]) list.slots.back().pending = {d.uniform(0.0, 1e-6), 0.0, 0.0, 0.0};  // J; +0 while not touching
    const double mi = s.mass[pairs[k].i], mj = s.mass[pairs[k].j];
    if (pair_steps && !d.chance(0.05)) list.linear_steps[k] = linear_step(law.kn, law.alpha_n, mi * mj / (mi + mj), kDt);
  }
  list.features.resize(list.slots.size());
  list.set_recording(false);
  return list;
}

}  // namespace

TEST_CASE("sphere lanes: a steady pair has sphere_pair_forces' bits, another is left to it", "[contact]") {
  const LawParams law = bed_law();
  using Parts = SteadyParts;
  Draw d;
  int steady = 0, left = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Spheres s;  // pairs (0, 1) and (2, 3), each touching or about to
    for (int pair = 0; pair < 2; ++pair) {
      const double ri = d.uniform(4e-3, 6e-3), rj = d.uniform(4e-3, 6e-3);  // m
      const double gap = d.chance(0.1) ? d.uniform(0.0, 2e-5) : d.uniform(-1e-4, 0.0);  // m
      const Vec3 xi = d.vec(0.1), n = d.vec(1.0).normalized();
      s.add(d, xi, ri);
      s.add(d, xi - (ri + rj + gap) * n, rj);
    }
    const BodyView bodies = s.view();
    PairList list = random_list(d, {{0, 1}, {2, 3}}, law, s, true);
    const EachSphere sizes{bodies, list};
    if (!steady_candidate(list, 0, sizes) || !steady_candidate(list, 1, sizes)) continue;
    PairList reference = list, alone = list;
    const EachSphere reference_sizes{bodies, reference}, alone_sizes{bodies, alone};
    const std::uint32_t two[2] = {0, 1};
    bool taken[2] = {false, false};
    PairTotals in_lane[2];
    steady_sphere_pairs<2>(law, 0.0, kDt, bodies, list, two, sizes, [&](int l, const PairTotals* t) {
      const ContactHistory& h = list.slots[l].history;
      taken[l] = t != nullptr;
      if (!t) {
        ++left;
        REQUIRE(same_bits(h, reference.slots[l].history));
        return;
      }
      ++steady;
      in_lane[l] = *t;
      const PairTotals ref = sphere_pair_forces<Parts>(law, 0.0, kDt, bodies, reference, two[l], reference_sizes);
      REQUIRE(same_bits(h, reference.slots[l].history));
      REQUIRE(same_bits(t->force_i, ref.force_i));
      REQUIRE(same_bits(t->torque_i, ref.torque_i));
      REQUIRE(same_bits(t->torque_j, ref.torque_j));
      REQUIRE(same_bits(t->energy, ref.energy));
      REQUIRE(t->contacts == ref.contacts);
    });
    // Each pair alone through the one-lane kernel: the same choice and the same bits as in its lane.
    for (int l = 0; l < 2; ++l) {
      const std::uint32_t one[1] = {two[l]};
      steady_sphere_pairs<1>(law, 0.0, kDt, bodies, alone, one, alone_sizes, [&](int, const PairTotals* t) {
        REQUIRE((t != nullptr) == taken[l]);
        REQUIRE(same_bits(alone.slots[l].history, list.slots[l].history));
        if (!t) return;
        REQUIRE(same_bits(t->force_i, in_lane[l].force_i));
        REQUIRE(same_bits(t->torque_i, in_lane[l].torque_i));
        REQUIRE(same_bits(t->torque_j, in_lane[l].torque_j));
        REQUIRE(same_bits(t->energy, in_lane[l].energy));
      });
    }
  }
  CHECK(steady > 15000);  // most draws rest and stick
  CHECK(left > 3000);     // and the rest exercise every way out
}

TEST_CASE("sphere lanes: the sphere loop two pairs at a time ends with the bits of one at a time", "[contact]") {
  const LawParams law = bed_law();
  Draw d;
  for (const bool equal : {false, true}) {
    // A jittered cubic lattice of 6^3 spheres a little closer than touching, listed with their
    // neighbours and the next ones across a face's diagonal (out of reach).
    Spheres s;
    const double r = 5e-3, spacing = 2.0 * r - 4e-5;  // m
    for (int i = 0; i < 216; ++i)
      s.add(d, spacing * Vec3(i % 6, i / 6 % 6, i / 36) + d.vec(2e-5), equal ? r : r * d.uniform(0.995, 1.005));
    std::vector<BodyPair> pairs;
    for (std::uint32_t i = 0; i < s.position.size(); ++i)
      for (std::uint32_t j = i + 1; j < s.position.size(); ++j)
        if ((s.position[i] - s.position[j]).norm() < 1.5 * spacing) pairs.push_back({i, j});
    const BodyView bodies = s.view();
    PairList one = random_list(d, pairs, law, s, !equal), two = one;
    DirectSums sums_one, sums_two;
    sums_one.reset(s.position.size());
    sums_two.reset(s.position.size());
    const EqualSpheres same{r, s.mass[0]};
    sphere_pair_loop(law, 0.0, kDt, bodies, one, sums_one, equal ? &same : nullptr, false);
    sphere_pair_loop(law, 0.0, kDt, bodies, two, sums_two, equal ? &same : nullptr, true);
    for (std::size_t b = 0; b < s.position.size(); ++b) {
      REQUIRE(same_bits(sums_one.sums[b].force, sums_two.sums[b].force));
      REQUIRE(same_bits(sums_one.sums[b].torque, sums_two.sums[b].torque));
    }
    std::size_t contacts = 0;
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      REQUIRE(same_bits(one.open_energy_or_zero(k), two.open_energy_or_zero(k)));
      REQUIRE(one.touching[k] == two.touching[k]);
      contacts += one.touching[k];
    }
    for (std::size_t t = 0; t < one.slots.size(); ++t) {
      REQUIRE(one.active[t] == two.active[t]);
      REQUIRE(same_bits(one.slots[t].history, two.slots[t].history));
    }
    REQUIRE(one.block_contacts == two.block_contacts);
    REQUIRE(one.block_ended == two.block_ended);
    CHECK(contacts > 400);             // most lattice neighbours touch
    CHECK(pairs.size() > contacts + 600);  // and the diagonal ones do not
  }
}
