// Steady sphere-wall pairs two at a time and one alone (sphere_wall_lanes.hpp) against
// sphere_wall_forces, the reference: a lane it takes has the pair's bits (totals, history, record),
// one it leaves is untouched; and the driver loop with the lanes ends with the bits of the loop
// without them (forces, torques, pending energies, states, block counts).
#include <catch2/catch.hpp>

#include "contact/pair_loop.hpp"
#include "contact/sphere_wall_lanes.hpp"
#include "sphere_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

bool same_bits(const SlotRecord& a, const SlotRecord& b) {
  return test::same_bits(a.point, b.point) && test::same_bits(a.force, b.force) && test::same_bits(a.fn, b.fn);
}
bool same_bits(const PairTotals& a, const PairTotals& b) {
  return test::same_bits(a.force_i, b.force_i) && test::same_bits(a.torque_i, b.torque_i) &&
         test::same_bits(a.torque_j, b.torque_j) && test::same_bits(a.energy, b.energy) && a.contacts == b.contacts;
}

// A floor, a tilted wall and a floor that moves (not at rest: never in a lane).
Drivers three_walls() {
  std::vector<DriverSettings> settings(3);
  settings[0].kind = WallSettings{Vec3(0.0, 0.0, 0.0), Vec3(0.0, 0.0, 1.0), std::nullopt};
  settings[1].kind = WallSettings{Vec3(0.1, 0.0, 0.0), Vec3(-1.0, 0.2, 0.1).normalized(), std::nullopt};
  settings[2].kind = WallSettings{Vec3(0.0, 0.0, -0.2), Vec3(0.0, 0.0, 1.0), std::nullopt};
  Drivers drivers(settings);
  drivers[2].velocity = Vec3(0.0, 0.0, 0.01);  // m/s
  return drivers;
}

// Sphere i touching (or about to touch) wall j: its centre above the wall's point by ri + gap.
void add_on_wall(Draw& d, Spheres& s, const DriverState& wall) {
  const double r = d.uniform(4e-3, 6e-3);                                          // m
  const double gap = d.chance(0.1) ? d.uniform(0.0, 2e-5) : d.uniform(-1e-4, 0.0);  // m
  const Vec3 along = d.vec(0.05);
  s.add(d, wall.point + along - along.dot(wall.normal) * wall.normal + (r + gap) * wall.normal, r);
}

// A sparse driver list of `pairs` (sorted), one slot each, a random last step on the ~95% active.
PairList random_wall_list(Draw& d, const std::vector<BodyPair>& pairs, const LawParams& law, const Spheres& s) {
  PairList list;
  list.pairs = pairs;
  list.sparse = true;  // before resize_results: a sparse list keeps its pairs' energies apart
  list.resize_results();
  list.state_of.assign(pairs.size(), kNoState);
  list.rolls = law.rolling;
  list.states.reset(pairs.size(), list.rolls, list.recording);
  list.features.resize(pairs.size());
  list.slot_begin.push_back(0);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    list.slot_begin.push_back(std::uint32_t(k + 1));
    list.active.push_back(!d.chance(0.05));
    list.touching[k] = list.active.back();
    if (list.active.back()) list.set_history(std::uint32_t(k), random_history(d));
    if (list.touching[k]) list.pending[k] = {d.uniform(0.0, 1e-6), 0.0, 0.0, 0.0};  // J; +0 while not touching
    if (!d.chance(0.05)) list.linear_steps[k] = linear_step(law.kn, law.alpha_n, s.mass[pairs[k].i], kDt);
  }
  return list;
}

WallSpheres sizes_of(const Spheres& s, PairList& list) {
  return {s.radius.data(), s.mass.data(), list.linear_steps.data(), ~0u};
}

}  // namespace

TEST_CASE("sphere-wall lanes: a steady pair has sphere_wall_forces' bits, another is left to it", "[contact]") {
  const LawParams law = bed_law();
  using Parts = SteadyParts;
  REQUIRE(wall_lanes_fit<Parts>(law));
  const Drivers drivers = three_walls();
  const std::uint64_t at_rest = drivers_at_rest(drivers);
  REQUIRE(at_rest == 0b011);
  Draw d;
  int steady = 0, left = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    Spheres s;  // pairs (0, j0) and (1, j1)
    const std::uint32_t j0 = d.chance(0.5) ? 0 : 1, j1 = d.chance(0.5) ? 0 : 1;
    add_on_wall(d, s, drivers[j0]);
    add_on_wall(d, s, drivers[j1]);
    const BodyView bodies = s.view();
    PairList list = random_wall_list(d, {{0, j0}, {1, j1}}, law, s);
    const WallSpheres sizes = sizes_of(s, list);
    if (!steady_wall_candidate(drivers, list, 0, sizes, at_rest) || !steady_wall_candidate(drivers, list, 1, sizes, at_rest))
      continue;
    PairList reference = list, alone = list;
    const WallSpheres reference_sizes = sizes_of(s, reference), alone_sizes = sizes_of(s, alone);
    const std::uint32_t two[2] = {0, 1};
    bool taken[2] = {false, false};
    PairTotals in_lane[2];
    steady_wall_pairs<2>(law, 0.0, kDt, bodies, drivers, list, two, sizes, [&](int l, const PairTotals* t) {
      taken[l] = t != nullptr;
      if (!t) {
        ++left;
        REQUIRE(test::same_bits(list.history(l), reference.history(l)));
        REQUIRE(same_bits(list.record(l), reference.record(l)));
        return;
      }
      ++steady;
      in_lane[l] = *t;
      PairScratch scratch;
      const PairTotals ref = sphere_wall_forces<Parts>(law, 0.0, kDt, bodies, drivers, reference, two[l], scratch,
                                                       reference_sizes, at_rest);
      REQUIRE(test::same_bits(list.history(l), reference.history(l)));
      REQUIRE(same_bits(list.record(l), reference.record(l)));
      REQUIRE(same_bits(*t, ref));
    });
    // Each pair alone through the one-lane kernel: the same choice and the same bits as in its lane.
    for (std::uint32_t l = 0; l < 2; ++l) {
      const std::uint32_t one[1] = {l};
      steady_wall_pairs<1>(law, 0.0, kDt, bodies, drivers, alone, one, alone_sizes, [&](int, const PairTotals* t) {
        REQUIRE((t != nullptr) == taken[l]);
        REQUIRE(test::same_bits(alone.history(l), list.history(l)));
        REQUIRE(same_bits(alone.record(l), list.record(l)));
        if (t) REQUIRE(same_bits(*t, in_lane[l]));
      });
    }
  }
  CHECK(steady > 14000);  // most draws rest and stick
  CHECK(left > 2000);     // and the rest exercise every way out
}

TEST_CASE("sphere-wall lanes: the driver loop two pairs at a time ends with the bits of one at a time", "[contact]") {
  const LawParams law = bed_law();
  using Parts = SteadyParts;
  const Drivers drivers = three_walls();
  const std::uint64_t at_rest = drivers_at_rest(drivers);
  Draw d;
  // 600 spheres on the three walls, in body order, some out of reach (the loop's blocks of 64).
  Spheres s;
  std::vector<BodyPair> pairs;
  for (std::uint32_t i = 0; i < 600; ++i) {
    const std::uint32_t j = d.chance(0.1) ? 2 : d.chance(0.5) ? 0 : 1;
    add_on_wall(d, s, drivers[j]);
    pairs.push_back({i, j});
  }
  const BodyView bodies = s.view();
  PairList one = random_wall_list(d, pairs, law, s), two = one;
  const WallSpheres sizes_one = sizes_of(s, one), sizes_two = sizes_of(s, two);
  const auto scalar = [&](PairList& list, const WallSpheres& sizes) {
    return [&](std::uint32_t k, PairScratch& scratch) {
      return sphere_wall_forces<Parts>(law, 0.0, kDt, bodies, drivers, list, k, scratch, sizes, at_rest);
    };
  };
  const auto kernel_one = scalar(one, sizes_one), kernel_two = scalar(two, sizes_two);
  even_pair_forces(one, kernel_one);
  even_pair_forces(two, WallLanesKernel<decltype(kernel_two)>{kernel_two, law, 0.0, kDt, bodies, drivers, two,
                                                               sizes_two, at_rest});
  std::size_t contacts = 0, lanes = 0;
  for (std::uint32_t k = 0; k < pairs.size(); ++k) {
    REQUIRE(test::same_bits(one.force_i[k], two.force_i[k]));
    REQUIRE(test::same_bits(one.torque_i[k], two.torque_i[k]));
    REQUIRE(test::same_bits(one.torque_j[k], two.torque_j[k]));
    REQUIRE(test::same_bits(one.open_energy(k), two.open_energy(k)));
    REQUIRE(one.touching[k] == two.touching[k]);
    REQUIRE(one.active[k] == two.active[k]);
    REQUIRE((one.state_of[k] == kNoState) == (two.state_of[k] == kNoState));
    if (one.state_of[k] == kNoState) continue;
    REQUIRE(test::same_bits(one.history(k), two.history(k)));
    REQUIRE(same_bits(one.record(k), two.record(k)));
    contacts += one.touching[k];
    lanes += pairs[k].j != 2 && one.touching[k] && one.history(k).gap < 0.0;
  }
  REQUIRE(one.block_contacts == two.block_contacts);
  REQUIRE(one.block_ended == two.block_ended);
  CHECK(contacts > 400);  // most spheres touch
  CHECK(lanes > 300);     // and most of those on walls at rest
}
