// The rebuild trigger must never let a contact escape the Verlet list, and not rebuild needlessly.
#include "neighbor/rebuild_trigger.hpp"

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "neighbor/broad_phase.hpp"
#include "scenes.hpp"

namespace polydem {
namespace {

Quat rotation(double angle, const Vec3& axis) {
  return Quat(Eigen::AngleAxisd(angle, axis.normalized()));
}

TEST_CASE("a trigger with no build asks for one", "[rebuild]") {
  RebuildTrigger trigger;
  REQUIRE(trigger.needs_rebuild({Vec3::Zero()}, {Quat::Identity()}, {1.0}, 0.1));
  trigger.mark_built({Vec3::Zero()}, {Quat::Identity()});
  REQUIRE(trigger.rebuilds() == 1);
  REQUIRE_FALSE(trigger.needs_rebuild({Vec3::Zero()}, {Quat::Identity()}, {1.0}, 0.1));
  // A different body count means the lists are stale.
  REQUIRE(trigger.needs_rebuild({Vec3::Zero(), Vec3::Ones()}, {Quat::Identity(), Quat::Identity()},
                                {1.0, 1.0}, 0.1));
}

TEST_CASE("translation just below and just above skin/2", "[rebuild]") {
  const double skin = 0.2;
  const std::vector<Vec3> x0{Vec3(1, 2, 3), Vec3(-4, 0, 1)};
  const std::vector<Quat> q0{Quat::Identity(), Quat::Identity()};
  const std::vector<double> radius{0.5, 0.5};
  RebuildTrigger trigger;
  trigger.mark_built(x0, q0);
  const Vec3 direction = Vec3(1, -2, 2) / 3.0;  // unit
  std::vector<Vec3> x = x0;
  x[1] += 0.5 * skin * (1 - 1e-9) * direction;
  REQUIRE_FALSE(trigger.needs_rebuild(x, q0, radius, skin));
  x[1] = x0[1] + 0.5 * skin * (1 + 1e-9) * direction;
  REQUIRE(trigger.needs_rebuild(x, q0, radius, skin));
}

TEST_CASE("one moving body among many is seen by the parallel check", "[rebuild]") {
  // 10^4 bodies (above the threshold for threads); only body k moves, by 0.4 then 0.6 skin.
  const double skin = 0.1;
  const test::Scene s = test::uniform_scene(10000, 30.0, 0.2, 0.5, 24);
  const std::vector<Quat> q(s.centers.size(), Quat::Identity());
  RebuildTrigger trigger;
  trigger.mark_built(s.centers, q);
  for (std::size_t k : {std::size_t{0}, std::size_t{5003}, s.centers.size() - 1}) {
    std::vector<Vec3> x = s.centers;
    x[k].z() += 0.4 * skin;
    REQUIRE_FALSE(trigger.needs_rebuild(x, q, s.radii, skin));
    x[k].z() += 0.2 * skin;
    REQUIRE(trigger.needs_rebuild(x, q, s.radii, skin));
  }
}

TEST_CASE("points (radius 0) need no orientation or bounds kept: the same answers, turning or not", "[rebuild]") {
  const double skin = 0.1;
  const test::Scene s = test::uniform_scene(2000, 10.0, 0.2, 0.5, 5);
  const std::vector<double> points(s.centers.size(), 0.0);
  std::vector<Quat> q0(s.centers.size()), q(s.centers.size());
  std::vector<Vec3> x = s.centers;
  for (std::size_t b = 0; b < x.size(); ++b) {
    q0[b] = rotation(0.1 * double(b), Vec3(1, 2, 3));
    q[b] = rotation(0.3 * double(b), Vec3(-1, 0, 2)) * q0[b];  // turned, which a point ignores
    x[b].x() += 0.049 * skin * double(b % 11);  // m: the last of each 11 near skin/2
  }
  RebuildTrigger kept, points_only;
  kept.mark_built(s.centers, q0);
  points_only.mark_built(s.centers, q0, true);
  REQUIRE_FALSE(kept.needs_rebuild(x, q, points, skin));
  REQUIRE_FALSE(points_only.needs_rebuild(x, q, points, skin));
  CHECK(points_only.displacement().empty());  // only polyhedra read the bounds
  x[7].y() += 0.5 * skin;
  CHECK(kept.needs_rebuild(x, q, points, skin));
  CHECK(points_only.needs_rebuild(x, q, points, skin));
}

TEST_CASE("a pass's watch of points reads x at the build in floats and answers as moved_past", "[rebuild]") {
  // Built at coordinates from 1 mm to 1 km (float rounding up to ~3e-5 m, against skin/2 = 0.1
  // m) and at one a float cannot hold; each point moved by skin/2 times 1 - 1e-3 ... 1 + 1e-3,
  // or exactly skin/2, in a random direction, or to a NaN.
  const double skin = 0.2, limit = move_limit(skin);  // m
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::vector<Vec3> x0;
  for (double scale : {1e-3, 1.0, 1e3})
    for (int k = 0; k < 300; ++k) x0.push_back(scale * Vec3(unit(rng), unit(rng), unit(rng)));
  x0.push_back(Vec3(1e39, 0.0, 0.0));  // m: no float holds it
  RebuildTrigger trigger;
  trigger.mark_built(x0, std::vector<Quat>(x0.size(), Quat::Identity()), true);
  PointWatch watch{};
  REQUIRE(trigger.watch_points(x0.size(), skin, watch));
  std::size_t past = 0, tests = 0;
  for (std::size_t i = 0; i < x0.size(); ++i) {
    for (double f : {1.0 - 1e-3, 1.0 - 1e-9, 1.0, 1.0 + 1e-9, 1.0 + 1e-3, std::nan("")}) {
      const Vec3 x = x0[i] + f * limit * Vec3(unit(rng), unit(rng), unit(rng)).normalized();
      std::atomic<bool> exceeded{false};
      PointWatch one = watch;
      one.exceeded = &exceeded;
      one(i, x);
      CHECK(exceeded.load() == moved_past(x, x0[i], limit));
      past += moved_past(x, x0[i], limit);
      ++tests;
    }
  }
  CHECK(past > tests / 4);  // both answers were asked
  CHECK(past < 3 * tests / 4);
}

TEST_CASE("a pass's watch of polyhedra keeps measure's bounds and answer, bit for bit", "[rebuild]") {
  // 2,000 turned and moved bodies, every one watched as the opening pass watches them, against
  // needs_rebuild's loop. Moves up to 0.46 skin: within the scene's skin/2, past some bodies' own
  // (per-body skins 0.5 to 1.3 skin), so each answer hangs on the skins read; then one body past all.
  const double skin = 0.1;  // m
  const test::Scene s = test::uniform_scene(2000, 10.0, 0.2, 0.5, 9);
  const std::size_t n = s.centers.size();
  std::vector<Quat> q0(n), q(n);
  std::vector<Vec3> x = s.centers;
  std::vector<double> skins(n);  // m
  for (std::size_t b = 0; b < n; ++b) {
    q0[b] = rotation(0.1 * double(b), Vec3(1, 2, 3));
    q[b] = rotation(1e-3 * double(b % 13), Vec3(-1, 0, 2)) * q0[b];  // rad: chords up to 6 mm
    x[b].x() += 0.4 * skin * double(b % 7) / 6.0;                      // m
    skins[b] = skin * (0.5 + 0.1 * double(b % 9));
  }
  for (bool per_body : {false, true}) {
    RebuildTrigger measured, watched;
    measured.mark_built(s.centers, q0);
    watched.mark_built(s.centers, q0);
    if (per_body) measured.set_skins(skins), watched.set_skins(skins);
    std::vector<Vec3> moved = x;
    for (bool far : {false, true}) {
      if (far) moved[3].y() += skin;  // m: past every half skin
      const bool answer = measured.needs_rebuild(moved, q, s.radii, skin);
      CHECK(answer == (far || per_body));
      BoundWatch watch{};
      REQUIRE(watched.watch_bounds(q, s.radii, skin, watch));
      for (std::size_t b = 0; b < n; ++b) watch(b, moved[b]);
      CHECK(watched.take_exceeded() == answer);
      CHECK(watched.displacement() == measured.displacement());  // every bound's bits
    }
  }
}

TEST_CASE("rotation of a body with a large bounding radius triggers", "[rebuild]") {
  // A point at distance R turned by theta moves along the chord 2 R sin(theta/2).
  const double skin = 0.2;
  const double big = 10.0;
  const double theta_limit = 2 * std::asin(0.5 * skin / (2 * big));
  const Vec3 axis(0.3, -1.0, 0.4);
  const std::vector<Vec3> x{Vec3::Zero()};
  RebuildTrigger trigger;
  trigger.mark_built(x, {rotation(0.7, Vec3::UnitX())});
  const auto turned = [&](double theta) {
    return rotation(theta, axis) * rotation(0.7, Vec3::UnitX());
  };
  REQUIRE_FALSE(trigger.needs_rebuild(x, {turned(theta_limit * (1 - 1e-6))}, {big}, skin));
  REQUIRE(trigger.needs_rebuild(x, {turned(theta_limit * (1 + 1e-6))}, {big}, skin));
  // The same turn of a small body is harmless; the sign of a quaternion is not a rotation.
  REQUIRE_FALSE(trigger.needs_rebuild(x, {turned(20 * theta_limit)}, {0.01}, skin));
  const Quat flipped(-turned(theta_limit * 0.5).coeffs());
  REQUIRE_FALSE(trigger.needs_rebuild(x, {flipped}, {big}, skin));
}

TEST_CASE("the displacement bound covers every surface point and is reached", "[rebuild]") {
  // Brute force: sample points of the bounding sphere, move them with the body, take the largest
  // move.
  std::mt19937_64 rng(21);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::uniform_real_distribution<double> angle(0.0, 2 * kPi);
  for (int trial = 0; trial < 50; ++trial) {
    const double radius = 2.0;
    const Vec3 dx(0.1 * gauss(rng), 0.1 * gauss(rng), 0.1 * gauss(rng));
    const Quat q0 = rotation(angle(rng), Vec3(gauss(rng), gauss(rng), gauss(rng)));
    const Quat q1 = rotation(angle(rng), Vec3(gauss(rng), gauss(rng), gauss(rng))) * q0;
    const double bound = displacement_bound(dx, q1, q0, radius);
    double largest = 0.0;
    for (int k = 0; k < 2000; ++k) {
      const Vec3 p = radius * Vec3(gauss(rng), gauss(rng), gauss(rng)).normalized();  // body frame
      largest = std::max(largest, (dx + q1 * p - q0 * p).norm());
    }
    REQUIRE(largest <= bound * (1 + 1e-12));
    // Sampled maximum within 5 % of the bound: the bound is not loose (|dx| small vs the chord).
    REQUIRE(largest > 0.95 * bound - dx.norm());
  }
}

// Random walk of bodies and orientations; the list is rebuilt only when the trigger asks.
TEST_CASE("no contact escapes the Verlet list between rebuilds", "[rebuild][safety]") {
  const double skin = 0.15;
  test::Scene s = test::uniform_scene(500, 9.0, 0.1, 0.6, 22);
  const std::size_t n = s.centers.size();
  std::vector<Quat> q(n, Quat::Identity());
  std::mt19937_64 rng(23);
  std::normal_distribution<double> gauss(0.0, 1.0);
  std::vector<Vec3> velocity(n);
  for (auto& v : velocity) v = 0.5 * Vec3(gauss(rng), gauss(rng), gauss(rng));  // m/s
  const double dt = 0.004;  // s, a body at 1 m/s crosses skin/2 in about 19 steps
  RebuildTrigger trigger;
  CellList cells;
  std::vector<BodyPair> verlet;
  std::vector<BodyPair> touching;
  const int steps = 300;
  std::size_t checked = 0;
  std::size_t missing = 0;  // contacts absent from the list: must stay 0
  for (int step = 0; step < steps; ++step) {
    if (trigger.needs_rebuild(s.centers, q, s.radii, skin)) {
      cells.build_pairs(s.centers, s.radii, skin, verlet);
      trigger.mark_built(s.centers, q);
    }
    brute_force_pairs(s.centers, s.radii, 0.0, touching);
    for (const BodyPair& p : touching) {
      const bool listed = std::binary_search(
          verlet.begin(), verlet.end(), p,
          [](const BodyPair& a, const BodyPair& b) { return a.i != b.i ? a.i < b.i : a.j < b.j; });
      if (!listed) ++missing;
    }
    checked += touching.size();
    for (std::size_t i = 0; i < n; ++i) {
      // m/s, random kicks with damping keep the speeds steady
      velocity[i] = 0.95 * velocity[i] + 0.15 * Vec3(gauss(rng), gauss(rng), gauss(rng));
      s.centers[i] += dt * velocity[i];
      q[i] =
          (rotation(dt * gauss(rng), Vec3(gauss(rng), gauss(rng), gauss(rng))) * q[i]).normalized();
    }
  }
  INFO("rebuilds " << trigger.rebuilds() << " in " << steps << " steps, " << checked
                   << " contacts checked");
  REQUIRE(missing == 0);
  // The check is only meaningful if the list was reused for many steps and contacts existed.
  REQUIRE(trigger.rebuilds() > 5);
  REQUIRE(trigger.rebuilds() < steps / 3);
  REQUIRE(checked > 1000);
}

TEST_CASE("the pair test: one body may move up to the skin while the others stay near", "[rebuild]") {
  const double skin = 0.1;  // m
  const std::vector<Vec3> x0{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  const std::vector<Quat> q0(3, Quat::Identity());
  const std::vector<double> radius{0.3, 0.3, 0.3};  // m, core reach
  for (bool points : {false, true}) {
    RebuildTrigger trigger;
    trigger.mark_built(x0, q0, points);
    std::vector<Vec3> x = x0;
    x[0].x() += 0.8 * skin;   // past skin/2: the half test asks
    x[2].y() += 0.15 * skin;  // d1 + d2 = 0.95 skin: no two bodies can have closed the skin
    REQUIRE(trigger.needs_rebuild(x, q0, radius, skin));
    CHECK_FALSE(trigger.pair_exceeded(x, skin, 0.0));
    CHECK(trigger.pair_exceeded(x, skin, 0.25 * skin));  // a driver moved 0.25 skin: d1 + shift > skin
    x[2].y() += 0.1 * skin;  // d2 = 0.25 skin: d1 + d2 > skin
    REQUIRE(trigger.needs_rebuild(x, q0, radius, skin));
    CHECK(trigger.pair_exceeded(x, skin, 0.0));
    x = x0;
    x[1].z() += 1.01 * skin;  // one body alone past the skin
    REQUIRE(trigger.needs_rebuild(x, q0, radius, skin));
    CHECK(trigger.pair_exceeded(x, skin, 0.0));
    x[1].z() = std::nan("");
    REQUIRE(trigger.needs_rebuild(x, q0, radius, skin));
    CHECK(trigger.pair_exceeded(x, skin, 0.0));
  }
  RebuildTrigger turned;  // a turn counts as its chord at the core reach
  turned.mark_built(x0, q0);
  std::vector<Quat> q = q0;
  q[0] = rotation(2.0 * std::asin(0.8 * skin / (2.0 * radius[0])), Vec3(0, 0, 1));  // chord 0.8 skin
  std::vector<Vec3> x = x0;
  x[1].x() += 0.25 * skin;
  REQUIRE(turned.needs_rebuild(x, q, radius, skin));
  CHECK(turned.pair_exceeded(x, skin, 0.0));
  x[1].x() = x0[1].x() + 0.15 * skin;
  REQUIRE(turned.needs_rebuild(x, q, radius, skin));
  CHECK_FALSE(turned.pair_exceeded(x, skin, 0.0));
}

TEST_CASE("per-body skins: each body watches its own half, a pair the mean of its two skins", "[rebuild]") {
  const double skin = 0.125;  // m, the scene's (binary fractions: the sums below are exact)
  const std::vector<Vec3> x0{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  const std::vector<Quat> q0(3, Quat::Identity());
  const std::vector<double> radius{0.25, 0.25, 0.25};  // m, core reach
  RebuildTrigger trigger;
  trigger.mark_built(x0, q0);
  trigger.set_skins({skin, 4.0 * skin, skin});  // body 1 fast at the build: its pairs reach (0.125 + 0.5) / 2
  const auto moved = [&](double d0, double d1) {  // m, bodies 0 and 1 moved along x
    std::vector<Vec3> x = x0;
    x[0].x() += d0;
    x[1].x() += d1;
    return x;
  };
  CHECK_FALSE(trigger.needs_rebuild(moved(0.0, 0.24), q0, radius, skin));  // under its half skin, 0.25
  REQUIRE(trigger.needs_rebuild(moved(0.0, 0.30), q0, radius, skin));
  CHECK_FALSE(trigger.pair_exceeded(moved(0.0, 0.30), skin, 0.0));  // 0.30 < 0.3125: no pair closed
  CHECK(trigger.pair_exceeded(moved(0.0, 0.30), skin, 0.25));       // 0.30 + 0.25 > its driver reach 0.5
  REQUIRE(trigger.needs_rebuild(moved(0.0, 0.32), q0, radius, skin));
  CHECK(trigger.pair_exceeded(moved(0.0, 0.32), skin, 0.0));  // alone past the pair's 0.3125
  REQUIRE(trigger.needs_rebuild(moved(0.02, 0.30), q0, radius, skin));
  CHECK(trigger.pair_exceeded(moved(0.02, 0.30), skin, 0.0));  // together 0.32: body 0 within its half too
  // A body slow at the build that speeds up: past its own half skin, the cheap test asks at once.
  CHECK(trigger.needs_rebuild(moved(0.07, 0.0), q0, radius, skin));
  std::vector<Vec3> nan = x0;
  nan[1].x() = std::nan("");
  REQUIRE(trigger.needs_rebuild(nan, q0, radius, skin));
  CHECK(trigger.pair_exceeded(nan, skin, 0.0));
  trigger.mark_built(x0, q0);  // a build without set_skins: the scene's skin for every body again
  CHECK(trigger.needs_rebuild(moved(0.0, 0.24), q0, radius, skin));
}


// A part's margins of the bodies `owner` gives it (the others its ghosts), from a trigger of its
// own built at x0 (`skins` empty: the scene's skin each) and measured at x.
PairMargins part_margins(const std::vector<Vec3>& x0, const std::vector<Vec3>& x, const std::vector<double>& skins,
                         const std::vector<int>& owner, int part, double skin, double shift, bool points = false) {
  const std::vector<Quat> q(x0.size(), Quat::Identity());
  RebuildTrigger t;
  t.mark_built(x0, q, points);
  if (!points) t.set_skins(skins);
  t.needs_rebuild(x, q, std::vector<double>(x0.size(), 0.25), skin);  // the step's measure: bounds kept
  std::vector<std::uint8_t> ghost(x0.size());
  for (std::size_t i = 0; i < ghost.size(); ++i) ghost[i] = owner[i] != part;
  return t.margins(x, skin, shift, ghost.data());
}

TEST_CASE("the pair rule over parts: bodies past skin/2 on two ranks keep the lists while no pair can close", "[rebuild]") {
  const double skin = 0.125;  // m (binary fractions: the sums below are exact)
  const std::vector<Vec3> x0{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  const std::vector<int> owner{0, 1, 1};  // body 0 on rank 0; bodies 1, 2 on rank 1
  const auto moved = [&](double d0, double d1, double d2) {  // m, along x
    std::vector<Vec3> x = x0;
    x[0].x() += d0, x[1].x() += d1, x[2].x() += d2;
    return x;
  };
  const auto exceeded = [&](const std::vector<Vec3>& x, const std::vector<double>& skins, double shift = 0.0) {
    const PairMargins parts[2] = {part_margins(x0, x, skins, owner, 0, skin, shift),
                                  part_margins(x0, x, skins, owner, 1, skin, shift)};
    const PairMargins swapped[2] = {parts[1], parts[0]};
    const bool answer = pair_rule_exceeded(parts, 2, skin);
    CHECK(pair_rule_exceeded(swapped, 2, skin) == answer);  // in any order
    RebuildTrigger one;  // one process over all three bodies
    const std::vector<Quat> q(3, Quat::Identity());
    one.mark_built(x0, q);
    one.set_skins(skins);
    one.needs_rebuild(x, q, std::vector<double>(3, 0.25), skin);
    CHECK(one.pair_exceeded(x, skin, shift) == answer);
    return answer;
  };
  // Uniform skins: body 0 past skin/2 (a rank's old rule rebuilt), body 1 far under: d1 + d2 = 0.875 skin.
  CHECK_FALSE(exceeded(moved(0.09375, 0.015625, 0.0), {}));
  CHECK(exceeded(moved(0.09375, 0.046875, 0.0), {}));          // 1.125 skin over two ranks
  CHECK(exceeded(moved(0.09375, 0.015625, 0.0), {}, 0.0625));  // d1 + the driver's shift
  CHECK(exceeded(moved(0.0, 0.078125, 0.0625), {}));           // both on rank 1: 1.125 skin
  // Per-body skins: body 0 fast at the build (4 skin), bodies 1 and 2 at the skin.
  const std::vector<double> own{0.5, skin, skin};
  CHECK_FALSE(exceeded(moved(0.1875, 0.09375, 0.0), own));  // margins -0.0625 + 0.03125: each past the scene's half
  CHECK(exceeded(moved(0.25, 0.09375, 0.0), own));           // 0 + 0.03125
  CHECK(exceeded(moved(0.0, 0.09375, 0.078125), own));       // 0.03125 + 0.015625, both on rank 1
  // Rank 1 with no per-body skins (its bodies all at the skin) reads as margins d - skin/2.
  const PairMargins mixed[2] = {part_margins(x0, moved(0.1875, 0.09375, 0.0), own, owner, 0, skin, 0.0),
                                part_margins(x0, moved(0.1875, 0.09375, 0.0), {}, owner, 1, skin, 0.0)};
  REQUIRE(mixed[1].uniform);
  CHECK_FALSE(pair_rule_exceeded(mixed, 2, skin));
  // A ghost is its owner's to measure: rank 0's copy of body 1, far off, does not count there.
  std::vector<Vec3> far = moved(0.0, 10.0, 0.0);
  CHECK_FALSE(part_margins(x0, far, {}, owner, 0, skin, 0.0).alone);
  CHECK(part_margins(x0, far, {}, owner, 1, skin, 0.0).alone);
  far[2].x() = std::nan("");
  CHECK(part_margins(x0, far, {}, owner, 1, skin, 0.0).alone);
}

TEST_CASE("the pair rule over parts answers as one process over all bodies, any split, any order", "[rebuild]") {
  const double skin = 0.125;  // m
  std::mt19937_64 rng(20);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int yes = 0, no = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const std::size_t n = 2 + trial % 9;
    const int parts = 1 + trial % 4;
    const bool points = trial % 5 == 0, own_skins = !points && trial % 3 != 0;
    std::vector<Vec3> x0(n), x(n);
    std::vector<double> skins;
    std::vector<int> owner(n);
    for (std::size_t i = 0; i < n; ++i) {
      x0[i] = Vec3(double(i), 0.0, 0.0);
      const double s = own_skins ? skin * (1.0 + 3.0 * unit(rng)) : skin;  // m
      if (own_skins) skins.push_back(s);
      x[i] = x0[i] + Vec3(0.0, 0.6 * s * unit(rng), 0.0);  // most bodies under their half, some past
      owner[i] = int(rng() % parts);
    }
    const double shift = trial % 7 == 0 ? 0.3 * skin * unit(rng) : 0.0;  // m
    std::vector<PairMargins> m;
    for (int p = 0; p < parts; ++p) m.push_back(part_margins(x0, x, skins, owner, p, skin, shift, points));
    std::shuffle(m.begin(), m.end(), rng);
    const std::vector<Quat> q(n, Quat::Identity());
    RebuildTrigger one;
    one.mark_built(x0, q, points);
    if (!points) one.set_skins(skins);
    one.needs_rebuild(x, q, std::vector<double>(n, 0.25), skin);
    const bool answer = one.pair_exceeded(x, skin, shift);
    INFO("trial " << trial);
    CHECK(pair_rule_exceeded(m.data(), m.size(), skin) == answer);
    (answer ? yes : no) += 1;
  }
  CHECK(yes > 100);  // both answers met often
  CHECK(no > 100);
}

TEST_CASE("a rank's measure keeps its owned margins in its own pass, ghosts left for once they land", "[rebuild]") {
  const double skin = 0.125;  // m
  std::mt19937_64 rng(35);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int yes = 0, no = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const std::size_t n = 1 + trial % 40;
    const bool own_skins = trial % 3 != 0;
    const int threads = 1 + trial % 2;
    std::vector<Vec3> x0(n), before(n), x(n);
    std::vector<Quat> q0(n, Quat::Identity()), q(n);
    std::vector<double> skins, radius(n);
    std::vector<std::uint8_t> ghost(n);
    for (std::size_t i = 0; i < n; ++i) {
      x0[i] = Vec3(double(i), 0.0, 0.0);
      const double s = own_skins ? skin * (1.0 + 3.0 * unit(rng)) : skin;  // m
      if (own_skins) skins.push_back(s);
      before[i] = x0[i] + Vec3(0.0, 0.1 * s * unit(rng), 0.0);
      x[i] = x0[i] + Vec3(0.45 * s * unit(rng), 0.0, 0.3 * s * unit(rng));  // some past their half
      q[i] = rotation(0.2 * s * unit(rng), Vec3(unit(rng), 1.0, unit(rng)));
      radius[i] = 0.25 * unit(rng);  // m
      ghost[i] = unit(rng) < 0.3;
    }
    const double shift = trial % 7 == 0 ? 0.3 * skin * unit(rng) : 0.0;  // m
    RebuildTrigger all, rank;  // all: the full measure, then margins' own pass
    for (RebuildTrigger* t : {&all, &rank}) {
      t->mark_built(x0, q0);
      t->set_skins(skins);
      t->needs_rebuild(before, q0, radius, skin);  // a step before: the ghosts' bounds as they were
    }
    const std::vector<double> was = all.displacement();  // m, the bounds a step before
    all.needs_rebuild(x, q, radius, skin);
    const PairMargins want = all.margins(x, skin, shift, ghost.data());
    const bool later = trial % 4 != 0;  // the ghosts a step old (a rank's folded word), else current
    const OwnedPart owned{ghost.data(), shift, later};
#pragma omp parallel num_threads(threads)
    rank.measure(x, q, radius, skin, {}, &owned);
    rank.take_exceeded();
    INFO("trial " << trial << ", " << threads << " threads");
    for (std::size_t i = 0; i < n; ++i)  // owned as the full measure; ghosts a step old untouched until they land
      CHECK(rank.displacement()[i] == (ghost[i] && later ? was[i] : all.displacement()[i]));
    const PairMargins got = rank.take_margins(x, skin, shift, ghost.data());
    CHECK(got.alone == want.alone);
    CHECK(got.uniform == want.uniform);
    CHECK(got.top[0] == want.top[0]);
    CHECK(got.top[1] == want.top[1]);
    std::vector<std::uint32_t> ghosts;
    for (std::size_t i = 0; i < n; ++i)
      if (ghost[i]) ghosts.push_back(std::uint32_t(i));
    rank.remeasure(x, q, radius, ghosts);
    CHECK(rank.displacement() == all.displacement());
    const PairMargins again = rank.take_margins(x, skin, shift, ghost.data());  // nothing kept: margins' own loop
    CHECK(again.top[0] == want.top[0]);
    CHECK(again.top[1] == want.top[1]);
    (pair_rule_exceeded(&got, 1, skin) ? yes : no) += 1;
  }
  INFO(yes << " rebuilds, " << no << " not");
  CHECK(yes > 50);  // both answers met often
  CHECK(no > 50);
}

TEST_CASE("points' margins kept on a team answer the pair rule as margins' own loop", "[rebuild]") {
  const double skin = 0.125;  // m
  std::mt19937_64 rng(36);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int yes = 0, no = 0, by_shift = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const std::size_t n = 1 + trial % 50;
    const int threads = 1 + trial % 3;
    std::vector<Vec3> x0(n), x(n);
    for (std::size_t i = 0; i < n; ++i) {
      x0[i] = Vec3(double(i), 0.5 * unit(rng), 0.0);
      x[i] = x0[i] + Vec3(0.0, 0.0, 0.55 * skin * unit(rng));  // most under skin/2, some past
    }
    if (trial % 37 == 0) x[rng() % n].z() = std::nan("");
    const double shift = trial % 3 == 0 ? 0.8 * skin * unit(rng) : 0.0;  // m, a driver's
    const std::vector<Quat> q(n, Quat::Identity());
    RebuildTrigger kept, loop;
    kept.mark_built(x0, q, true);
    loop.mark_built(x0, q, true);
    // A cut of the bodies into the threads' shares (the first region's), uneven, or none (static).
    std::vector<std::uint32_t> at{0};
    for (int t = 1; t < threads; ++t) at.push_back(std::max(at.back(), std::uint32_t(rng() % (n + 1))));
    at.push_back(std::uint32_t(n));
    const TeamCut cut = trial % 2 ? TeamCut{at.data(), threads} : TeamCut{};
#pragma omp parallel num_threads(threads)
    kept.keep_point_margins(x, cut);
    const bool answer = loop.pair_exceeded(x, skin, shift);
    INFO("trial " << trial << ", " << threads << " threads");
    CHECK(kept.pair_exceeded(x, skin, shift) == answer);
    const PairMargins m = loop.margins(x, skin, 0.0, nullptr);  // the shift alone decides: d1 + shift > skin
    by_shift += answer && !m.alone && m.top[0] + m.top[1] <= skin;
    kept.forget_point_margins();  // then margins' loop again
    CHECK(kept.pair_exceeded(x, skin, shift) == answer);
    (answer ? yes : no) += 1;
  }
  INFO(yes << " rebuilds, " << no << " not, " << by_shift << " by the shift");
  CHECK(yes > 100);  // both answers met often, and the driver's reach deciding some
  CHECK(no > 100);
  CHECK(by_shift > 10);
}

// A rank's part of points (a sphere scene's): measured margins (kept in its pass, or its serial
// loop) where `measured`, else only whether one of its bodies passed skin/2 (its pass's test).
PairMargins point_part(const std::vector<Vec3>& x0, const std::vector<Vec3>& x, const std::vector<int>& owner,
                       int part, double skin, double shift, bool measured, bool kept) {
  const std::vector<Quat> q(x0.size(), Quat::Identity());
  RebuildTrigger t;
  t.mark_built(x0, q, true);
  std::vector<std::uint8_t> ghost(x0.size());
  for (std::size_t i = 0; i < ghost.size(); ++i) ghost[i] = owner[i] != part;
  PairMargins m;
  if (measured && kept) t.keep_point_margins(x, {}, ghost.data());
  if (measured) m = t.point_margins(x, skin, shift, ghost.data());
  else m.exact = false;
  bool past_half = false;  // the pass's test of its owned bodies
  for (std::size_t i = 0; i < x.size(); ++i) past_half = past_half || (!ghost[i] && moved_past(x[i], x0[i], 0.5 * skin));
  m.past = past_half || shift > 0.5 * skin;
  return m;
}

TEST_CASE("ranks of points decide as one process: margins measured only once some point passed skin/2", "[rebuild]") {
  const double skin = 0.125;  // m
  std::mt19937_64 rng(40);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int keep = 0, rebuild = 0, measure = 0;
  for (int trial = 0; trial < 800; ++trial) {
    const std::size_t n = 2 + trial % 11;
    const int parts = 2 + trial % 3;
    std::vector<Vec3> x0(n), x(n);
    std::vector<int> owner(n);
    const double reach = trial % 2 ? 0.45 : 0.7;  // of the skin: half the trials every point under skin/2
    for (std::size_t i = 0; i < n; ++i) {
      x0[i] = Vec3(double(i), 0.0, 0.0);
      x[i] = x0[i] + Vec3(0.0, reach * skin * unit(rng), 0.0);
      owner[i] = int(rng() % parts);
    }
    if (trial % 13 == 0) x[rng() % n].z() = std::nan("");
    const double shift = trial % 7 == 0 ? 0.6 * skin * unit(rng) : 0.0;  // m
    std::vector<PairMargins> m;
    for (int p = 0; p < parts; ++p) m.push_back(point_part(x0, x, owner, p, skin, shift, trial % 3 == 0, trial % 2 == 0));
    const std::vector<Quat> q(n, Quat::Identity());
    RebuildTrigger one;  // one process: skin/2 first, then the pair rule (ContactEngine::lists_past_skin)
    one.mark_built(x0, q, true);
    const bool past = one.needs_rebuild(x, q, std::vector<double>(n, 0.0), skin) || shift > 0.5 * skin;
    const bool answer = past && one.pair_exceeded(x, skin, shift);
    INFO("trial " << trial);
    bool got = false;
    switch (rule_verdict(m.data(), m.size(), skin)) {
      case RuleVerdict::keep: ++keep; break;
      case RuleVerdict::rebuild: ++rebuild, got = true; break;
      case RuleVerdict::measure: {  // the second meeting: every part's margins measured
        ++measure;
        for (int p = 0; p < parts; ++p) m[p] = point_part(x0, x, owner, p, skin, shift, true, false);
        got = pair_rule_exceeded(m.data(), m.size(), skin);
      }
    }
    CHECK(got == answer);
  }
  CHECK(keep > 100);  // every path met often
  CHECK(rebuild > 100);
  CHECK(measure > 100);
}

}  // namespace
}  // namespace polydem
