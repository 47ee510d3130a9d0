// The ghost exchange's plan and parcels without MPI: over 400 random centres cut in 2, 3 and 4
// boxes (recursive bisection, equal weights), every body is owned by one rank, each rank's
// ghosts are exactly the bodies owned elsewhere within the halo of its box, rank p's send list to q is q's receive list from p
// (so a parcel is bare state in an order both know), and body state crosses a parcel bit for bit,
// a motion parcel with the receiver's drift as the owner's drift; a rebuild's store, made of runs of
// increasing id, is merged into id order bit for bit. A motion parcel narrowed to the pairs
// across the cut (paired_across) holds, on both sides, the bodies within pair range of the other
// rank's owned bodies, and leaves out the ghosts no pair reads.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <random>

#include "integrate/integrate.hpp"
#include "sim/body_exchange.hpp"
#include "sim/body_rows.hpp"
#include "sim/ghost_plan.hpp"

using namespace polydem;

namespace {

std::vector<Vec3> random_centres(std::size_t n, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Vec3> x(n);
  for (Vec3& c : x) c = Vec3(2.0 * u(rng), u(rng), 0.5 * u(rng));  // m: the longest side along x
  return x;
}

}  // namespace

TEST_CASE("Ghost plans partition the bodies and pair each send list with its receive list") {
  const std::vector<Vec3> x = random_centres(400, 7);
  const double halo = 0.12;  // m
  for (int ranks : {2, 3, 4}) {
    INFO(ranks << " ranks");
    const DomainCut cut = cut_domain(x, std::vector<double>(x.size(), 1.0), ranks);
    std::vector<GhostPlan> plans;
    for (int p = 0; p < ranks; ++p) plans.push_back(plan_ghosts(cut, p, x, halo));
    std::vector<int> owners(x.size(), 0);
    for (int p = 0; p < ranks; ++p) {
      for (std::uint32_t b : plans[p].owned) ++owners[b];
      CHECK(plans[p].owned.size() >= x.size() / std::size_t(ranks));  // equal counts, within one body
      CHECK(plans[p].owned.size() <= x.size() / std::size_t(ranks) + 1);
      for (std::size_t k = 0; k < plans[p].local.size(); ++k) {
        const std::uint32_t b = plans[p].local[k];
        CHECK(bool(plans[p].ghost[k]) == (cut.owner(x[b]) != p));
        if (plans[p].ghost[k]) CHECK(cut.distance(p, x[b]) < halo);
      }
      std::size_t ghosts = 0;
      for (std::uint8_t g : plans[p].ghost) ghosts += g;
      std::size_t expected = 0;  // every body owned elsewhere within the halo
      for (const Vec3& c : x) expected += cut.owner(c) != p && cut.distance(p, c) < halo;
      CHECK(ghosts == expected);
      CHECK(ghosts > 0);
      CHECK(plans[p].local.size() < x.size());
      for (int q = 0; q < ranks; ++q) {
        CHECK(plans[p].send[q] == plans[q].receive[p]);
        if (q == p) CHECK(plans[p].send[q].empty());
        for (std::uint32_t b : plans[p].send[q]) CHECK(cut.distance(q, x[b]) < halo);  // the boxes near it only
      }
    }
    for (int n : owners) CHECK(n == 1);
  }
}

namespace {

// Twelve bodies, every field different per body (constants too), all owned by a store.
LocalStore twelve_owned() {
  const std::vector<Vec3> x = random_centres(12, 3);
  Bodies from;
  from.resize(x.size());
  for (std::size_t b = 0; b < x.size(); ++b) {
    from.position[b] = x[b];
    from.orientation[b] = Quat(0.5, 0.5 + 0.1 * double(b), -0.5, 0.5).normalized();
    from.velocity[b] = 3.0 * x[b];
    from.angular_velocity[b] = -x[b] / 7.0;
    from.velocity_end[b] = x[b] / 3.0;
    from.angular_velocity_end[b] = x[b] * 1e-9;
    from.angular_momentum[b] = x[b] * 11.0;
    from.force[b] = x[b] / 13.0;
    from.torque[b] = -x[b];
    from.shape[b] = int(b % 3);
    from.scale[b] = 1.0 + x[b].x();
    from.mass[b] = 1e-3 * x[b].y();
    from.inertia[b] = x[b] * 1e-7;
    from.group[b] = int(20 - b);
    from.id[b] = std::uint32_t(1000 + 7 * b);
  }
  std::vector<std::uint32_t> all(x.size());
  for (std::uint32_t b = 0; b < all.size(); ++b) all[b] = b;
  LocalStore store;
  store.select(from, all, std::vector<std::uint8_t>(all.size(), 0));
  return store;
}

// The store's arrays hold the same bytes as `want`'s, field for field.
void check_bit_equal(LocalStore& got, const LocalStore& want) {
  got.with_arrays(want, [](const auto& g, const auto& w) {
    REQUIRE(g.size() == w.size());
    CHECK(std::memcmp(g.data(), w.data(), g.size() * sizeof(g[0])) == 0);
  });
}

}  // namespace

TEST_CASE("A mover's parcel lands in its new owner's store bit for bit, constants included") {
  const LocalStore from = twelve_owned();
  const std::vector<std::uint32_t> rows{1, 4, 5, 11};
  const std::vector<char> bytes = pack_movers(from, rows);
  CHECK(bytes.size() == rows.size() * kMoverBytes);
  LocalStore landed;
  landed.append(from, {0});  // a body kept: the movers land after it
  unpack_movers(bytes, landed);
  LocalStore want;
  want.append(from, {0, 1, 4, 5, 11});
  check_bit_equal(landed, want);
}

TEST_CASE("Ghost and owned parcels carry body state bit for bit") {
  const LocalStore from = twelve_owned();
  const std::vector<std::uint32_t> ids{1, 4, 5, 11};  // = their rows
  const std::vector<char> ghosts = pack_ghosts(from, ids);
  CHECK(ghosts.size() == ids.size() * kGhostBytes);
  LocalStore to;
  unpack_ghosts(ghosts, ids, to);
  REQUIRE(to.size() == ids.size());
  Bodies owned;
  owned.resize(from.size());
  unpack_owned(pack_owned(rows_of(from, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}), ids), owned);
  for (std::size_t k = 0; k < ids.size(); ++k) {
    const std::uint32_t b = ids[k];
    CHECK(to.global_id[k] == b);
    CHECK(to.ghost[k] == 1);
    CHECK(std::memcmp(to.position[k].data(), from.position[b].data(), sizeof(Vec3)) == 0);
    CHECK(to.orientation[k].coeffs() == from.orientation[b].coeffs());
    CHECK(to.velocity_end[k] == from.velocity_end[b]);
    CHECK(to.angular_velocity_end[k] == from.angular_velocity_end[b]);
    CHECK(to.shape[k] == from.shape[b]);
    CHECK(to.scale[k] == from.scale[b]);
    CHECK(to.mass[k] == from.mass[b]);
    CHECK(to.group[k] == from.group[b]);
    CHECK(to.id[k] == from.id[b]);
    CHECK(to.angular_momentum[k] == Vec3::Zero());  // a ghost carries no integration state
    CHECK(to.inertia[k] == Vec3::Zero());
    CHECK(owned.angular_momentum[b] == from.angular_momentum[b]);
    CHECK(owned.force[b] == from.force[b]);
    CHECK(owned.torque[b] == from.torque[b]);
    CHECK(owned.velocity[b] == from.velocity[b]);
  }
  CHECK(owned.position[0] == Vec3::Zero());  // bodies not in the parcel are left alone
}

TEST_CASE("A motion parcel and the receiver's drift give the owner's drifted state bit for bit") {
  const std::vector<Vec3> x = random_centres(12, 5);
  const double dt = 3.7e-5;  // s
  // Spheres without their spin's prediction, spheres with it, turning bodies: 72, 96, 128 bytes a body.
  for (const MotionFields fields : {MotionFields{false, false}, MotionFields{false, true}, MotionFields{true, true}}) {
    const bool turning = fields.orientation;
    INFO("orientation " << fields.orientation << ", spin_end " << fields.spin_end);
    CHECK(motion_bytes(fields) == (turning ? 128u : fields.spin_end ? 96u : 72u));
    Bodies owner;
    owner.resize(x.size());
    for (std::size_t b = 0; b < x.size(); ++b) {
      owner.position[b] = x[b];
      owner.inertia[b] = Vec3(1.0, 2.0 + double(b), 3.0) * 1e-6;  // kg m^2: asymmetric
      owner.angular_momentum[b] = x[b] * 1e-5;
    }
    Bodies held = owner;  // the receiver's copies as of the last step
    const std::vector<std::uint32_t> ids{0, 3, 4, 9};
    LocalStore store;
    store.select(held, ids, std::vector<std::uint8_t>(ids.size(), 1));
    std::vector<Vec3> drifted;
    for (std::uint32_t b : ids) drifted.push_back(held.position[b]);
    for (std::size_t b = 0; b < x.size(); ++b) {  // the owner's step: new velocities, then its drift
      owner.velocity[b] = Vec3(0.3, -1.1, 2.9) * x[b].norm();
      owner.velocity_end[b] = owner.velocity[b] / 3.0;
      owner.angular_velocity_end[b] = x[b] * 1e-9;
    }
    if (turning) drift(owner, dt);
    else for (std::size_t b = 0; b < x.size(); ++b) owner.position[b] += owner.velocity[b] * dt;
    LocalStore sender;  // the owner's store: the bodies `ids` owned
    sender.select(owner, ids, std::vector<std::uint8_t>(ids.size(), 0));
    std::vector<char> bytes(ids.size() * motion_bytes(fields));
    const std::vector<std::uint32_t> local{0, 1, 2, 3};
    pack_motion(sender, local, fields, bytes.data());
    unpack_motion(bytes.data(), {local, drifted.data()}, fields, dt, store);
    for (std::size_t k = 0; k < ids.size(); ++k) {
      const std::uint32_t b = ids[k];
      CHECK(std::memcmp(store.position[k].data(), owner.position[b].data(), sizeof(Vec3)) == 0);
      CHECK(store.velocity[k] == owner.velocity[b]);
      CHECK(store.angular_velocity[k] == owner.angular_velocity[b]);
      CHECK(store.velocity_end[k] == owner.velocity_end[b]);
      CHECK(store.angular_velocity_end[k] == (fields.spin_end ? owner : held).angular_velocity_end[b]);  // not sent: left
      CHECK(store.orientation[k].coeffs() == owner.orientation[b].coeffs());  // not sent when not turning: both the identity
    }
  }
}

TEST_CASE("A rebuild's store goes into id order from its runs, bit for bit, and stays put when in order") {
  const LocalStore from = twelve_owned();
  LocalStore want;
  want.append(from, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
  LocalStore runs;  // kept rows, then two parcels' rows: three increasing runs
  runs.append(from, {0, 2, 7, 9});
  runs.append(from, {1, 4, 11});
  runs.append(from, {3, 5, 6, 8, 10});
  runs.sort_by_id();
  check_bit_equal(runs, want);
  const Vec3* kept = want.position.data();
  want.sort_by_id();  // in order already: no array is made again
  CHECK(want.position.data() == kept);
}

TEST_CASE("id_order merges a few increasing runs and sorts many, as a sort of the ids would") {
  std::mt19937_64 rng(7);
  for (std::size_t runs : {1, 2, 5, 64, 65, 400}) {
    std::vector<std::uint32_t> ids(400);
    for (std::uint32_t k = 0; k < ids.size(); ++k) ids[k] = 3 * k + 1;
    std::shuffle(ids.begin(), ids.end(), rng);
    for (std::size_t r = 0; r < runs; ++r) {  // runs of ids.size() / runs, each increasing
      const auto lo = ids.begin() + std::ptrdiff_t(r * ids.size() / runs);
      std::sort(lo, ids.begin() + std::ptrdiff_t((r + 1) * ids.size() / runs));
    }
    std::vector<std::uint32_t> want(ids.size());
    for (std::uint32_t k = 0; k < want.size(); ++k) want[k] = k;
    std::sort(want.begin(), want.end(), [&](std::uint32_t a, std::uint32_t b) { return ids[a] < ids[b]; });
    CHECK(id_order(ids) == want);
  }
}

TEST_CASE("A rebuild's store merges its kept rows with the movers, then the ghosts in place, bit for bit") {
  const LocalStore from = twelve_owned();
  LocalStore want;
  want.append(from, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11});
  LocalStore movers, ghosts;
  movers.append(from, {1, 4, 11});
  ghosts.append(from, {0, 5, 6, 10});
  LocalStore store;
  store.merge_of(from, {2, 3, 7, 8, 9}, movers, ghosts.size());
  CHECK(store.global_id == std::vector<std::uint32_t>{1, 2, 3, 4, 7, 8, 9, 11});
  const Vec3* held = store.position.data();
  store.merge_in(ghosts);
  check_bit_equal(store, want);
  CHECK(store.position.data() == held);  // within the room kept: no reallocation
  LocalStore none;
  store.merge_in(none);  // nothing lands: nothing moves
  check_bit_equal(store, want);
  LocalStore first;
  first.merge_of(from, {}, movers, 0);  // no kept row: the movers alone
  LocalStore only;
  only.append(from, {1, 4, 11});
  check_bit_equal(first, only);
}

namespace {

// Rank p's pairs within `range` (m) of its local bodies, one owned at least, in local rows (i < j).
std::vector<BodyPair> pairs_in_range(const GhostPlan& plan, const std::vector<Vec3>& x, double range) {
  std::vector<BodyPair> pairs;
  for (std::uint32_t i = 0; i < plan.local.size(); ++i)
    for (std::uint32_t j = i + 1; j < plan.local.size(); ++j)
      if ((!plan.ghost[i] || !plan.ghost[j]) && (x[plan.local[i]] - x[plan.local[j]]).norm() < range)
        pairs.push_back({i, j});
  return pairs;
}

}  // namespace

TEST_CASE("Motion parcels narrowed to the pairs across the cut agree on both sides and drop unread ghosts") {
  const std::vector<Vec3> x = random_centres(1000, 11);
  const double halo = 0.15, range = 0.1;  // m: pairs within range, ghosts within the halo
  for (int ranks : {2, 3}) {
    INFO(ranks << " ranks");
    const DomainCut cut = cut_domain(x, std::vector<double>(x.size(), 1.0), ranks);
    std::vector<GhostPlan> plans;
    std::vector<PairedRows> paired;
    std::vector<int> owner_of(x.size());
    for (std::uint32_t b = 0; b < x.size(); ++b) owner_of[b] = cut.owner(x[b]);
    for (int p = 0; p < ranks; ++p) {
      plans.push_back(plan_ghosts(cut, p, x, halo));
      std::vector<int> owner(plans[p].local.size(), -1);
      for (std::size_t k = 0; k < owner.size(); ++k)
        if (plans[p].ghost[k]) owner[k] = owner_of[plans[p].local[k]];
      paired.push_back(paired_across(pairs_in_range(plans[p], x, range), owner, ranks));
    }
    std::size_t sent = 0, planned = 0;
    for (int p = 0; p < ranks; ++p)
      for (int q = 0; q < ranks; ++q) {
        if (q == p) continue;
        std::vector<std::uint32_t> sends, receives, expected;
        for (std::uint32_t k : paired[p].send[q]) sends.push_back(plans[p].local[k]);
        for (std::uint32_t k : paired[q].receive[p]) receives.push_back(plans[q].local[k]);
        for (std::uint32_t a : plans[p].owned)  // p's bodies within range of one of q's
          for (std::uint32_t b = 0; b < x.size(); ++b)
            if (owner_of[b] == q && (x[a] - x[b]).norm() < range) {
              expected.push_back(a);
              break;
            }
        CHECK(sends == expected);
        CHECK(receives == expected);  // entry for entry: bare state in an order both know
        for (std::uint32_t k : paired[p].send[q]) CHECK(!plans[p].ghost[k]);
        sent += sends.size();
        planned += plans[p].send[q].size();
      }
    CHECK(sent > 0);
    CHECK(sent < planned);  // the halo's outer ghosts pair with none
  }
}
