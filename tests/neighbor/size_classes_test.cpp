// Bodies of very different sizes: each size class in its own grid, the same pairs as brute
// force, and a candidate count set by each class's own size, not by the largest body.
#include <catch2/catch.hpp>
#include <cmath>

#include "neighbor/broad_phase.hpp"
#include "brute_force_check.hpp"
#include "scenes.hpp"

namespace polydem {
namespace {

using test::Scene;
using test::require_same_as_brute_force;

// `count` bodies of one radius, uniform in a cube of side `side`, appended to s.
void add_uniform(Scene& s, std::size_t count, double side, double radius, std::uint64_t seed) {
  const Scene part = test::uniform_scene(count, side, radius, radius, seed);
  s.centers.insert(s.centers.end(), part.centers.begin(), part.centers.end());
  s.radii.insert(s.radii.end(), part.radii.begin(), part.radii.end());
}

TEST_CASE("equal bodies share one grid, a size ratio of 2 or more splits them", "[broad_phase]") {
  CellList cells;
  std::vector<BodyPair> out;
  Scene s = test::uniform_scene(500, 8.0, 0.5, 0.5, 31);
  cells.build_pairs(s.centers, s.radii, 0.0, out);
  REQUIRE(cells.levels() == 1);
  // Reach 2 R: 1.0 (x margin) for the large, 0.4 for the small; halved cells 0.5 still hold 0.4.
  add_uniform(s, 500, 8.0, 0.2, 32);
  cells.build_pairs(s.centers, s.radii, 0.0, out);
  REQUIRE(cells.levels() == 2);
  require_same_as_brute_force(s, 0.0);
  require_same_as_brute_force(s, 0.3);
}

TEST_CASE("a 1:10 bimodal mix costs what its own size classes cost", "[broad_phase]") {
  // 8,000 small spheres r = 0.1 and 80 large R = 1 in a cube of side L = 15, skin 0. Cells:
  // h0 = 2 R m for the large (m = 1 + 2^-10, the rounding margin), h3 = h0 / 8 = 0.25 m for the
  // small (the finest halving still holding 2 r m). In the bulk, per body (rho = count / L^3):
  // small-small 13.5 rho_s h3^3 (own cell half, 13 forward cells), small-large 27 rho_l h0^3
  // (the 27 large cells around a small body), large-large 13.5 rho_l h0^3. One grid of side h0
  // for all would cost 13.5 (rho_s + rho_l) h0^3 per body, about 45 times more.
  const double side = 15.0;
  const std::size_t n_small = 8000;
  const std::size_t n_large = 80;
  Scene s;
  add_uniform(s, n_large, side, 1.0, 41);
  add_uniform(s, n_small, side, 0.1, 42);
  const double margin = 1.0 + 1.0 / 1024.0;
  const double h0 = 2.0 * margin;
  const double h3 = h0 / 8.0;
  const double volume = side * side * side;
  const double rho_s = static_cast<double>(n_small) / volume;
  const double rho_l = static_cast<double>(n_large) / volume;
  const double bulk = static_cast<double>(n_small) * (13.5 * rho_s * std::pow(h3, 3) +
                                                      27.0 * rho_l * std::pow(h0, 3)) +
                      static_cast<double>(n_large) * 13.5 * rho_l * std::pow(h0, 3);
  const double one_grid =
      static_cast<double>(n_small + n_large) * 13.5 * (rho_s + rho_l) * std::pow(h0, 3);
  CellList cells;
  std::vector<BodyPair> out;
  cells.build_pairs(s.centers, s.radii, 0.0, out);
  const double tests = static_cast<double>(cells.candidate_tests());
  INFO("tests " << tests << ", bulk estimate " << bulk << ", one grid " << one_grid);
  REQUIRE(cells.levels() == 2);
  REQUIRE(tests < 1.05 * bulk);
  REQUIRE(tests > 0.5 * bulk);  // the walls remove part of the stencils, not most of it
  REQUIRE(tests * 30.0 < one_grid);
  require_same_as_brute_force(s, 0.0);
  require_same_as_brute_force(s, 0.05);
}

TEST_CASE("bodies far outside another size class's grid are looked up safely", "[broad_phase]") {
  // Small bodies far below and above the large bodies' grid: their cell coordinates there are
  // clamped (below -1 or beyond 2^40), which must neither overflow nor lose a pair.
  Scene s = test::uniform_scene(1500, 10.0, 0.05, 0.05, 51);
  add_uniform(s, 20, 10.0, 2.0, 52);  // their grid is dense: coordinates from its own corner
  s.centers.emplace_back(-1e12, 3.0, 3.0);
  s.radii.push_back(0.05);
  s.centers.emplace_back(1e12, 3.0, 3.0);
  s.radii.push_back(0.05);
  require_same_as_brute_force(s, 0.1);
  // Extreme coordinates: differences to a grid's corner overflow to infinity; both grids hashed.
  s.centers.emplace_back(-1e308, 1e308, 0.0);
  s.radii.push_back(0.05);
  s.centers.emplace_back(1e308, -1e308, 5.0);
  s.radii.push_back(3.0);
  s.centers.emplace_back(1e308, -1e308, 5.5);
  s.radii.push_back(0.05);
  require_same_as_brute_force(s, 0.1);
  // A huge plate-like body (bounding radius 40) over a bed of grains: the finest grid is 1/128
  // of the coarsest, smaller grains share it.
  Scene bed = test::uniform_scene(3000, 12.0, 0.02, 0.1, 53);
  bed.centers.emplace_back(6.0, 6.0, 45.0);
  bed.radii.push_back(40.0);
  CellList cells;
  std::vector<BodyPair> out;
  cells.build_pairs(bed.centers, bed.radii, 0.01, out);
  REQUIRE(cells.levels() <= CellList::kMaxLevels);
  require_same_as_brute_force(bed, 0.01);
}

}  // namespace
}  // namespace polydem
