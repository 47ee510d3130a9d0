#pragma once
// The broad phase's reference: the cell list must give exactly the brute-force pairs, in order.
#include <catch2/catch.hpp>

#include <vector>

#include "neighbor/broad_phase.hpp"
#include "scenes.hpp"

namespace polydem::test {

inline void require_same_as_brute_force(const Scene& s, double skin) {
  std::vector<BodyPair> fast;
  std::vector<BodyPair> slow;
  CellList cells;
  cells.build_pairs(s.centers, s.radii, skin, fast);
  brute_force_pairs(s.centers, s.radii, skin, slow);
  REQUIRE(fast.size() == slow.size());
  REQUIRE(fast == slow);
}

}  // namespace polydem::test
