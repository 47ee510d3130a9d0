// The cell list must find exactly the brute-force pairs, at O(N) cost, whatever the thread count.
#include "neighbor/broad_phase.hpp"

#include <omp.h>

#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "polydem/error.hpp"
#include "brute_force_check.hpp"
#include "scenes.hpp"

namespace polydem {
namespace {

using test::Scene;
using test::require_same_as_brute_force;

TEST_CASE("cell list equals brute force on uniform polydisperse scenes", "[broad_phase]") {
  // Radius ratio 1:10, packing fraction about 0.3 of the mean sphere volume.
  const Scene s = test::uniform_scene(3000, 16.0, 0.1, 1.0, 11);
  require_same_as_brute_force(s, 0.0);
  require_same_as_brute_force(s, 0.05);
  require_same_as_brute_force(s, 0.7);
}

TEST_CASE("cell list equals brute force on clustered scenes", "[broad_phase]") {
  const Scene s = test::clustered_scene(3000, 5, 50.0, 1.5, 0.05, 0.5, 12);
  require_same_as_brute_force(s, 0.1);
}

TEST_CASE("a body far away neither breaks the search nor allocates a giant grid", "[broad_phase]") {
  Scene s = test::uniform_scene(2000, 12.0, 0.2, 0.4, 13);
  s.centers.emplace_back(1e12, -3e11, 7e12);
  s.radii.push_back(0.3);
  CellList cells;
  std::vector<BodyPair> out;
  cells.build_pairs(s.centers, s.radii, 0.1, out);
  // Only occupied cells are stored: at most one per body.
  REQUIRE(cells.hashed());
  REQUIRE(cells.stored_cells() <= s.centers.size());
  require_same_as_brute_force(s, 0.1);

  // Extreme coordinates: the difference to the lower corner overflows to infinity.
  s.centers.emplace_back(-1e308, 1e308, 0.0);
  s.radii.push_back(0.3);
  require_same_as_brute_force(s, 0.1);
}

TEST_CASE("rounding of large cell coordinates loses no pair", "[broad_phase]") {
  // A body 1e12 m away makes the cell coordinates about 1e12, rounded to ~1e-4 cells. Couples
  // of unit spheres just inside the reach (2 + skin) along y, at random offsets in the cells,
  // far from each other: exactly the couples are pairs, whatever the rounding.
  const double skin = 0.1;
  const double gap = (2.0 + skin) * (1.0 - 1e-9);  // m, centre distance, within reach
  const std::uint32_t couples = 200000;
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<double> offset(0.0, 2.1);
  Scene s;
  std::vector<BodyPair> expected;
  for (std::uint32_t k = 0; k < couples; ++k) {
    const Vec3 a(10.0 * (k % 500), offset(rng), 10.0 * (k / 500));
    s.centers.push_back(a);
    s.centers.push_back(a + Vec3(0.0, gap, 0.0));
    s.radii.insert(s.radii.end(), {1.0, 1.0});
    expected.push_back({2 * k, 2 * k + 1});
  }
  s.centers.emplace_back(0.0, -1e12, 0.0);
  s.radii.push_back(1.0);
  CellList cells;
  std::vector<BodyPair> out;
  cells.build_pairs(s.centers, s.radii, skin, out);
  REQUIRE(out.size() == expected.size());
  REQUIRE(out == expected);
}

TEST_CASE("cell list handles 0, 1 and 2 bodies", "[broad_phase]") {
  require_same_as_brute_force(Scene{}, 0.1);
  require_same_as_brute_force(Scene{{Vec3(1, 2, 3)}, {0.5}}, 0.1);
  // Two unit spheres 2.05 apart: a pair with skin 0.1, none with skin 0.
  const Scene two{{Vec3(0, 0, 0), Vec3(2.05, 0, 0)}, {1.0, 1.0}};
  std::vector<BodyPair> out;
  CellList cells;
  cells.build_pairs(two.centers, two.radii, 0.1, out);
  REQUIRE(out == std::vector<BodyPair>{{0, 1}});
  cells.build_pairs(two.centers, two.radii, 0.0, out);
  REQUIRE(out.empty());
  // Point bodies with no skin: the reach is 0 and no distance is below it.
  cells.build_pairs({Vec3::Zero(), Vec3::Zero()}, {0.0, 0.0}, 0.0, out);
  REQUIRE(out.empty());
}

TEST_CASE("all bodies in one cell give all N(N-1)/2 pairs", "[broad_phase]") {
  const Scene s = test::uniform_scene(300, 0.5, 1.0, 1.0, 14);
  CellList cells;
  std::vector<BodyPair> out;
  cells.build_pairs(s.centers, s.radii, 0.0, out);
  REQUIRE(cells.stored_cells() == 1);
  REQUIRE(out.size() == 300 * 299 / 2);
  require_same_as_brute_force(s, 0.0);
}

TEST_CASE("bodies on cell faces and at exactly the reach distance", "[broad_phase]") {
  // Lattice spacing 1.25 = 2 R + skin = cell side: every centre sits on a cell boundary and
  // every lattice neighbour is at exactly the reach, which is excluded (strict <).
  Scene s;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int k = 0; k < 8; ++k) {
        s.centers.emplace_back(1.25 * i, 1.25 * j, 1.25 * k);
        s.radii.push_back(0.5);
      }
  require_same_as_brute_force(s, 0.25);
  require_same_as_brute_force(s, 0.2500001);
}

TEST_CASE("a reused cell list stays correct when the scene shrinks", "[broad_phase]") {
  CellList cells;
  std::vector<BodyPair> out;
  const Scene big = test::uniform_scene(5000, 20.0, 0.3, 0.6, 15);
  cells.build_pairs(big.centers, big.radii, 0.1, out);
  const Scene small = test::clustered_scene(400, 2, 5.0, 1.0, 0.1, 0.3, 16);
  cells.build_pairs(small.centers, small.radii, 0.1, out);
  std::vector<BodyPair> slow;
  brute_force_pairs(small.centers, small.radii, 0.1, slow);
  REQUIRE(out == slow);
}

TEST_CASE("candidate tests per body stay bounded as N grows at fixed density", "[broad_phase]") {
  // Monodisperse R = 0.5, skin 0.1: cell side h = 1.1. Number density rho = 0.3 / (4/3 pi R^3).
  // A cell holds m = rho h^3 bodies on average; each body is tested against half of its own
  // cell and all of 13 neighbour cells, so tests / N -> 13.5 m in the bulk, less at the walls.
  const double radius = 0.5;
  const double skin = 0.1;
  const double rho = 0.3 / (4.0 / 3.0 * kPi * radius * radius * radius);
  const double h = 2 * radius + skin;
  const double bulk_tests_per_body = 13.5 * rho * h * h * h;
  CellList cells;
  std::vector<BodyPair> out;
  double previous = 0.0;
  for (std::size_t n : {1000, 8000, 64000}) {
    const double side = std::cbrt(static_cast<double>(n) / rho);
    const Scene s = test::uniform_scene(n, side, radius, radius, 17 + n);
    cells.build_pairs(s.centers, s.radii, skin, out);
    const double per_body = static_cast<double>(cells.candidate_tests()) / static_cast<double>(n);
    INFO("N = " << n << ", tests per body " << per_body << ", bulk " << bulk_tests_per_body);
    REQUIRE(per_body < 1.05 * bulk_tests_per_body);
    // Fewer walls per body as N grows: the cost per body rises towards the bulk value only.
    REQUIRE(per_body > previous);
    previous = per_body;
  }
}

TEST_CASE("output is identical with 1, 2 and 3 threads", "[broad_phase][determinism]") {
  // A compact scene (one dense grid), a sparse clustered one (hashed cells) and a 1:10
  // polydisperse one (four size classes): every code path.
  const Scene compact = test::uniform_scene(20000, 35.0, 0.5, 1.0, 18);
  const Scene sparse = test::clustered_scene(20000, 8, 200.0, 3.0, 0.1, 1.0, 18);
  const Scene mixed = test::uniform_scene(20000, 35.0, 0.1, 1.0, 18);
  const int threads = omp_get_max_threads();
  CellList cells;
  bool used_hash[3] = {true, false, false};
  std::size_t levels[3] = {0, 0, 0};
  const Scene* scenes[3] = {&compact, &sparse, &mixed};
  for (int k = 0; k < 3; ++k) {
    std::vector<BodyPair> one;
    omp_set_num_threads(1);
    cells.build_pairs(scenes[k]->centers, scenes[k]->radii, 0.1, one);
    const std::size_t tests_one = cells.candidate_tests();
    REQUIRE(!one.empty());
    for (int team : {2, 3, 4}) {  // the levels, cells and rows shared by threads, each its run
      std::vector<BodyPair> more;
      omp_set_num_threads(team);
      cells.build_pairs(scenes[k]->centers, scenes[k]->radii, 0.1, more);
      REQUIRE(one == more);
      REQUIRE(tests_one == cells.candidate_tests());
    }
    omp_set_num_threads(threads);
    used_hash[k] = cells.hashed();
    levels[k] = cells.levels();
  }
  REQUIRE_FALSE(used_hash[0]);
  REQUIRE(levels[0] == 1);
  REQUIRE(used_hash[1]);
  REQUIRE(levels[2] == 3);
}

TEST_CASE("bad arguments and a blown-up state are reported", "[broad_phase]") {
  CellList cells;
  std::vector<BodyPair> out;
  const std::vector<Vec3> x{Vec3::Zero(), Vec3::Ones()};
  REQUIRE_THROWS_AS(cells.build_pairs(x, {1.0}, 0.1, out), std::invalid_argument);
  REQUIRE_THROWS_AS(cells.build_pairs(x, {1.0, -1.0}, 0.1, out), std::invalid_argument);
  REQUIRE_THROWS_AS(cells.build_pairs(x, {1.0, 1.0}, -0.1, out), std::invalid_argument);
  const std::vector<Vec3> nan{Vec3::Zero(), Vec3(0.0, std::nan(""), 0.0)};
  REQUIRE_THROWS_AS(cells.build_pairs(nan, {1.0, 1.0}, 0.1, out), RunError);
  // Enough bodies to bin on the team: each error names the first bad body, at any thread count.
  const int threads = omp_get_max_threads();
  for (int team : {1, 2, 3}) {
    omp_set_num_threads(team);
    const test::Scene s = test::uniform_scene(5000, 30.0, 0.5, 1.0, 19);
    std::vector<Vec3> blown = s.centers;
    blown[4321].y() = std::numeric_limits<double>::infinity();
    blown[2718].x() = std::nan("");
    REQUIRE_THROWS_WITH(cells.build_pairs(blown, s.radii, 0.1, out), Catch::Contains("body 2718 "));
    std::vector<double> radii = s.radii;
    radii[3999] = -1.0;
    radii[1414] = std::nan("");
    REQUIRE_THROWS_WITH(cells.build_pairs(s.centers, radii, 0.1, out), Catch::Contains("body 1414 "));
  }
  omp_set_num_threads(threads);
}

}  // namespace
}  // namespace polydem
