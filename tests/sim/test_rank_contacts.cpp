// The distributed step without MPI: ranks as threads joined by an in-process link. The pile
// of 150 cubes and spheres (walls, fast spins, many rebuilds) stepped over 2 and 3 ranks ends
// on the bits of one process on every rank: bodies, driver reactions, the energy ledger, the
// contact count and a CSV row's energies (each rank's part, summed exactly: no state gathered),
// each rank keeping only the scene's constants after its first cut; the same with drag and
// fluid forces (each rank's on its own bodies, their work summed exactly over the ranks). The
// thread link leaves a parcel's bytes NaN until its finish (thread_link.hpp), and a rank poses
// its owned bodies between post and finish: a ghost read or posed before its parcel lands fails
// here (both checked: unpacked before finish, the run stops on a non-finite position; ghosts
// posed before it, 90 of 148 assertions fail).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <map>
#include <thread>
#include <tuple>

#include "pile.hpp"
#include "sim/contact_table.hpp"
#include "thread_link.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

using polydem::test::same_bits;  // the arrays' (sim_fixtures.hpp), beside this one
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A pair across the cut as one rank holds it at one step: its active slots in global ids
// (append_pair_slots: histories, the pair's pending energy, records).
struct HeldPair {
  int step;
  std::uint32_t i, j;
  bool answers;  // this rank owns i
  std::vector<TableSlot> slots;
};

template <class T>
bool same_bytes(const T& a, const T& b) { return std::memcmp(&a, &b, sizeof(T)) == 0; }

// Field by field (their padding aside), each double's bits.
bool same_slot(const TableSlot& a, const TableSlot& b) {
  const ContactHistory &x = a.slot.history, &y = b.slot.history;
  const EnergyParts &e = a.slot.pending, &f = b.slot.pending;
  return a.key.type == b.key.type && a.key.a == b.key.a && a.key.b == b.key.b && same_bytes(x.ft, y.ft) &&
         same_bits(x.fd, y.fd) && same_bits(x.gap, y.gap) && same_bits(x.weight, y.weight) && x.slipping == y.slipping &&
         x.rolling_slipping == y.rolling_slipping && same_bytes(x.mr, y.mr) && same_bits(e.net, f.net) &&
         same_bits(e.sliding, f.sliding) && same_bits(e.rolling, f.rolling) && same_bits(e.patch, f.patch) &&
         same_bytes(a.record.point, b.record.point) && same_bytes(a.record.force, b.record.force) &&
         same_bits(a.record.fn, b.record.fn);
}

bool same_slots(const std::vector<TableSlot>& a, const std::vector<TableSlot>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t s = 0; s < a.size(); ++s)
    if (!same_slot(a[s], b[s])) return false;
  return true;
}

// The pairs across the cut this rank's lists hold at `step`, answering or not.
std::vector<HeldPair> across(const RankContacts& rank, int step) {
  std::vector<HeldPair> out;
  const PairList& list = rank.lists()->body_pairs();
  const LocalStore& store = rank.store();
  for (std::size_t k = 0; k < list.size(); ++k) {
    const BodyPair p = list.pairs[k];
    if (store.ghost[p.i] == store.ghost[p.j]) continue;  // both owned here
    HeldPair& h = out.emplace_back(HeldPair{step, store.global_id[p.i], store.global_id[p.j], !store.ghost[p.i], {}});
    append_pair_slots(list, k, store.global_id, false, h.slots);
  }
  return out;
}

struct Outcome {
  Bodies bodies;
  EnergyLedger ledger;
  EnergyRow energy;
  std::vector<Vec3> driver_force, driver_torque;
  std::size_t rebuilds = 0;
  std::size_t owned = 0, ghosts = 0;  // held by the rank at the last rebuild
  std::size_t cuts = 0;               // rebuilds that cut the domain again
  double share = 0.0;                 // of the weight, at the last rebuild
  std::size_t scene_bytes = 0;        // the scene's arrays (Bodies) before the gather
  std::size_t outside = 0;            // bodies outside the fluid grid (drag and fluid scenes)
  std::vector<double> alpha;          // the void fraction per cell, from the gathered bodies
  std::vector<HeldPair> across;       // every kAcrossEvery steps, the pairs across the cut the rank lists
};

constexpr int kAcrossEvery = 5;  // steps

Outcome outcome(Simulation& sim) {
  sim.sum_energy();  // a CSV row's energies from each rank's own bodies and pairs: no state gathered
  const EnergyRow row = sim.energy();
  const std::size_t scene_bytes = sim.bodies.held_bytes();
  const std::size_t outside = sim.bodies_outside_grid();  // a collective
  sim.gather_state(true);
  Outcome o{sim.bodies, sim.ledger, row, {}, {}, sim.rebuilds(), sim.owned_bodies(), sim.ghost_bodies()};
  o.scene_bytes = scene_bytes;
  o.outside = outside;
  if (sim.external())
    if (const auto vf = sim.external()->void_fraction(sim.bodies)) o.alpha = vf->alpha;
  if (const RankContacts* r = sim.rank_contacts()) o.cuts = r->cuts(), o.share = r->load_share();
  for (std::size_t j = 0; j < sim.drivers.size(); ++j) {
    o.driver_force.push_back(sim.drivers[j].force);
    o.driver_torque.push_back(sim.drivers[j].torque);
  }
  return o;
}

// `open_kicks`: each step but the last leaves its closing kick to the next step's opening pass.
// A rank's run keeps the pairs across its cut (Outcome::across) where `keep_across`.
Outcome run(const Pile& p, int steps, const RankLink* link, bool open_kicks = false, bool keep_across = false) {
  Simulation sim(p.scene, p.lib, p.specs, link);
  std::vector<HeldPair> held;
  for (int s = 1; s <= steps; ++s) {
    sim.step(open_kicks && s < steps);
    if (keep_across && s % kAcrossEvery == 0)
      for (HeldPair& h : across(*sim.rank_contacts(), s)) held.push_back(std::move(h));
  }
  Outcome o = outcome(sim);
  o.across = std::move(held);
  return o;
}

// Steps of one process until the pile holds `contacts` contacts, then `more`.
int steps_to_contacts(const Pile& p, std::size_t contacts, int more) {
  Simulation sim(p.scene, p.lib, p.specs);
  int s = 0;
  for (; s < 100000 && sim.contacts() < contacts; ++s) sim.step();
  return s + more;
}

void require_same(const Outcome& a, const Outcome& b) {
  CHECK(same_bits(a.bodies.position, b.bodies.position));
  CHECK(same_bits(a.bodies.orientation, b.bodies.orientation));
  CHECK(same_bits(a.bodies.velocity, b.bodies.velocity));
  CHECK(same_bits(a.bodies.angular_momentum, b.bodies.angular_momentum));
  CHECK(same_bits(a.bodies.force, b.bodies.force));
  CHECK(same_bits(a.driver_force, b.driver_force));
  CHECK(same_bits(a.driver_torque, b.driver_torque));
  CHECK(same_bits(a.ledger.dissipated, b.ledger.dissipated));
  CHECK(same_bits(a.ledger.sliding, b.ledger.sliding));
  CHECK(same_bits(a.ledger.patch_work, b.ledger.patch_work));
  CHECK(same_bits(a.ledger.driver_work, b.ledger.driver_work));
  CHECK(same_bits(a.energy.dissipated, b.energy.dissipated));  // the ledger and what is still open in the pairs
  CHECK(same_bits(a.energy.dissipated_sliding, b.energy.dissipated_sliding));
  CHECK(a.energy.contacts == b.energy.contacts);
  CHECK(same_bits(a.energy.elastic, b.energy.elastic));
  CHECK(same_bits(a.energy.elastic_parts.tangential, b.energy.elastic_parts.tangential));
  CHECK(same_bits(a.energy.kinetic, b.energy.kinetic));
  CHECK(same_bits(a.energy.rotational, b.energy.rotational));
  CHECK(same_bits(a.energy.gravity_work, b.energy.gravity_work));
  CHECK(same_bits(a.ledger.external_work, b.ledger.external_work));
  CHECK(a.outside == b.outside);
  CHECK(same_bits(a.alpha, b.alpha));
}

// The rebuild's hand-over keeps a rank's own copy of a pair across the cut it lists again
// (kept_table): that copy must be the answering rank's, bit for bit, at every step (histories,
// the pair's pending energy, records), and the other body's owner must list every such pair.
void check_copies(const std::vector<Outcome>& got) {
  std::map<std::tuple<int, std::uint32_t, std::uint32_t>, const HeldPair*> copies;  // (step, i, j): the other side's
  for (const Outcome& o : got)
    for (const HeldPair& h : o.across)
      if (!h.answers) copies[{h.step, h.i, h.j}] = &h;
  std::size_t answered = 0, matched = 0, touching = 0, differ = 0;
  for (const Outcome& o : got)
    for (const HeldPair& a : o.across) {
      if (!a.answers) continue;
      ++answered;
      const auto b = copies.find({a.step, a.i, a.j});
      if (b == copies.end()) continue;
      ++matched;
      touching += !a.slots.empty();
      differ += !same_slots(a.slots, b->second->slots);
    }
  INFO(answered << " pairs across the cut answered (a step's), " << touching << " touching");
  CHECK(matched == answered);  // the other body's owner lists each pair too
  CHECK(touching > 20);
  CHECK(differ == 0);
}

// Each of n thread ranks' outcome of `steps` steps of the pile.
std::vector<Outcome> over_ranks(const Pile& p, int steps, int n, bool keep_across = false) {
  ThreadRanks all(n);
  std::vector<Outcome> got(n);
  std::vector<std::thread> ranks;
  for (int r = 0; r < n; ++r)
    ranks.emplace_back([&, r] {
      const ThreadLink link(all, r);
      got[r] = run(p, steps, &link, n == 3, keep_across);  // 3 ranks: kicks left open, as the run loop leaves them
    });
  for (std::thread& t : ranks) t.join();
  CHECK_FALSE(all.mismatch);
  return got;
}

}  // namespace

TEST_CASE("A pile stepped over 2 and 3 thread ranks ends on one process's bits on every rank") {
  const Pile p;
  const int kSteps = steps_to_contacts(p, 150, 300);  // through the pour into a settling pile
  const Outcome one = run(p, kSteps, nullptr);
  REQUIRE(one.energy.contacts > 50);  // a pile: 86 at the end (e9e841f: springs start at the touch; 100+ before)
  REQUIRE(one.rebuilds > 5);
  REQUIRE(one.scene_bytes >= 272 * one.bodies.size());
  for (int n : {2, 3}) {
    const std::vector<Outcome> got = over_ranks(p, kSteps, n, true);
    check_copies(got);
    std::size_t owned = 0, held = 0, fewest = one.bodies.size();
    double shares = 0.0;
    for (int r = 0; r < n; ++r) {
      INFO(n << " ranks, rank " << r);
      require_same(one, got[r]);
      // The ranks join their owned bodies' pair-rule margins (pair_rule_exceeded) and list with one
      // process's per-body skins: its rebuilds at its steps (the walls stand still: no driver shift).
      CHECK(got[r].rebuilds == one.rebuilds);
      owned += got[r].owned;
      held += got[r].owned + got[r].ghosts;
      fewest = std::min(fewest, got[r].owned + got[r].ghosts);
      CHECK(got[r].cuts >= 2);                   // by body counts at the first rebuild, then by the work
      CHECK(got[r].cuts < got[r].rebuilds);      // a balanced cut is kept
      CHECK(got[r].share * n < 1.1);             // no rank's share of the work 10% over the mean
      // Nothing gathers the state (no probe, drag or fluid): after its first cut a rank keeps the
      // scene's constants alone (shape, scale, mass, inertia, group, id: 52 bytes a body), its
      // bodies' state in its store; one process keeps the state too (272 bytes a body).
      CHECK(got[r].scene_bytes <= 52 * one.bodies.size());
      shares += got[r].share;
    }
    CHECK(owned == one.bodies.size());  // every body moved by exactly one rank
    CHECK(shares == Approx(1.0).epsilon(1e-12));
    CHECK(held < std::size_t(n) * one.bodies.size());  // 272 of 300 at 2 ranks, 361 of 450 at 3: not replicated
    CHECK(fewest < one.bodies.size());  // an end box holds its share and the ghosts near its cut
  }
}

TEST_CASE("A pile of spheres over 2 and 3 thread ranks rebuilds at one process's steps: the pair rule over points") {
  Pile p;
  for (BodySpec& b : p.specs) b.shape = "sphere";  // points: each rank's pass tests skin/2, the rule measured after
  const int kSteps = steps_to_contacts(p, 120, 400);
  const Outcome one = run(p, kSteps, nullptr);
  REQUIRE(one.rebuilds > 5);
  for (int n : {2, 3}) {
    const std::vector<Outcome> got = over_ranks(p, kSteps, n);
    for (int r = 0; r < n; ++r) {
      INFO(n << " ranks, rank " << r);
      require_same(one, got[r]);
      CHECK(got[r].rebuilds == one.rebuilds);  // skin/2 a point on the ranks rebuilt more often
    }
  }
}

TEST_CASE("A pile of spheres with a tangential dashpot over 2 thread ranks: the ghosts' spin predictions travel") {
  // The dashpot reads both spheres' angular_velocity_end (sphere_kernel.hpp): the motion parcels
  // carry it here, and leave it out without the dashpot (the test above).
  Pile p(0.5);
  for (BodySpec& b : p.specs) b.shape = "sphere";
  const int kSteps = steps_to_contacts(p, 120, 200);
  const Outcome one = run(p, kSteps, nullptr);
  for (const Outcome& got : over_ranks(p, kSteps, 2)) require_same(one, got);
}

TEST_CASE("Drag and fluid forces over 2 and 3 thread ranks act on each rank's bodies with one process's bits") {
  // The pile in air drag and a water grid over its lower half (friction against a slow flow,
  // buoyancy, the void fraction): bodies leave and enter the grid, some straddle its faces.
  Pile p;
  p.scene.forces.quadratic = ForceSettings::Quadratic{0.38, 0.05};
  ForceSettings::FluidField f;
  f.grid_min = Vec3(-0.05, -0.05, 0.0);
  f.grid_max = Vec3(0.05, 0.05, 0.05);
  f.cells = Eigen::Vector3i(5, 5, 3);
  f.velocity = Vec3(0.2, 0.0, 0.0);
  f.rho = 1000.0;
  f.nu = 1e-6;
  p.scene.forces.fluid = f;
  p.scene.forces.fluid_friction = ForceSettings::FluidFriction{"", 50.0};
  p.scene.forces.archimedes = true;
  p.scene.forces.void_fraction = ForceSettings::VoidFraction{0.3, 4};
  const int kSteps = 400;
  const Outcome one = run(p, kSteps, nullptr);
  REQUIRE(one.ledger.external_work < 0.0);  // the drag takes energy out: the exact sum has terms
  REQUIRE(one.outside > 0);
  REQUIRE(one.outside < one.bodies.size());
  REQUIRE(one.rebuilds > 5);
  for (int n : {2, 3}) {
    const std::vector<Outcome> got = over_ranks(p, kSteps, n);
    for (int r = 0; r < n; ++r) {
      INFO(n << " ranks, rank " << r);
      require_same(one, got[r]);
      // The forces read no other rank's body: after its first cut a rank keeps the scene's
      // constants alone (52 bytes a body), as where nothing acts but gravity.
      CHECK(got[r].scene_bytes <= 52 * one.bodies.size());
    }
  }
}

TEST_CASE("Driver reactions from ranks' sorted runs are summed in one process's (body, driver) order") {
  Pile p;  // its floor and four side walls
  Drivers drivers(p.scene.drivers), expect(p.scene.drivers);
  std::mt19937_64 rng(3);
  auto u = [&] { return double(rng() >> 11) * 0x1.0p-53 - 0.5; };
  std::vector<ReactionShare> sorted;  // (body, driver) increasing, as one process sums them
  for (std::uint32_t i = 0; i < 400; ++i)
    for (std::uint32_t j = 0; j < drivers.size(); ++j)
      if (rng() % 3 == 0) sorted.push_back({i, j, {u(), u() * 1e-9, u() * 1e6}, {u(), u(), u()}});
  for (std::size_t j = 0; j < expect.size(); ++j) expect[j].force = expect[j].torque = Vec3::Zero();
  for (const ReactionShare& r : sorted) {
    expect[r.j].force -= Vec3(r.force_i[0], r.force_i[1], r.force_i[2]);
    expect[r.j].torque += Vec3(r.torque_j[0], r.torque_j[1], r.torque_j[2]);
  }
  for (int ranks : {1, 2, 3, 7}) {
    std::vector<std::vector<ReactionShare>> runs(ranks);  // each rank's share keeps the order
    for (const ReactionShare& r : sorted) runs[rng() % ranks].push_back(r);
    std::vector<ReactionShare> joined;
    for (const auto& run : runs) joined.insert(joined.end(), run.begin(), run.end());
    add_reactions(joined, drivers);
    for (std::size_t j = 0; j < drivers.size(); ++j) {
      INFO(ranks << " ranks, driver " << j);
      CHECK(same_bits(std::vector<Vec3>{drivers[j].force}, std::vector<Vec3>{expect[j].force}));
      CHECK(same_bits(std::vector<Vec3>{drivers[j].torque}, std::vector<Vec3>{expect[j].torque}));
    }
  }
  std::shuffle(sorted.begin(), sorted.end(), rng);  // no runs at all: still the same sums
  add_reactions(sorted, drivers);
  CHECK(same_bits(std::vector<Vec3>{drivers[0].force}, std::vector<Vec3>{expect[0].force}));
}

TEST_CASE("The cut in time moves bodies to the rank whose instructions take fewer seconds, the bits kept") {
  const Pile p;
  const int kSteps = steps_to_contacts(p, 150, 300);
  const Outcome one = run(p, kSteps, nullptr);
  // Each rank's busy seconds as its counted instructions times `rate` (s an instruction), injected.
  const auto timed = [&](double slow_rate) {
    ThreadRanks all(2);
    std::vector<Outcome> got(2);
    std::vector<double> scale(2);
    std::vector<std::thread> ranks;
    for (int r = 0; r < 2; ++r)
      ranks.emplace_back([&, r] {
        const ThreadLink link(all, r);
        Simulation sim(p.scene, p.lib, p.specs, &link);
        RankContacts& mine = *sim.rank_contacts();
        const double rate = r == 1 ? slow_rate : 1e-9;
        mine.time_by([&mine, rate] { return rate * mine.counted_done(); });
        for (int s = 0; s < kSteps; ++s) sim.step();
        scale[r] = mine.time_scale();
        got[r] = outcome(sim);
      });
    for (std::thread& t : ranks) t.join();
    CHECK_FALSE(all.mismatch);
    for (const Outcome& o : got) require_same(one, o);  // the cut decides who computes, never a value
    return std::pair{got, scale};
  };
  const auto [even, even_scale] = timed(1e-9);
  const auto [slow, slow_scale] = timed(3e-9);
  CHECK(even_scale == std::vector<double>{1.0, 1.0});
  CHECK(slow_scale == std::vector<double>{0.5, 1.5});  // each rank's rate over the mean, 2e-9
  CHECK(slow[1].owned < even[1].owned);  // the slow rank's share moved to the other
  CHECK(slow[0].owned > even[0].owned);
  CHECK(slow[1].cuts > 1);
}
