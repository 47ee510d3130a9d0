// The Hertz sphere-wall restitution error (accuracy_cases.hpp, worst of 16 touch places) for
// en 0.1 to 0.9 at 0.3, 0.2, 0.1, 0.05 and 0.025 x critical, and the order between
// neighbours from 0.2 down. Hidden: a table to paste (tools/bench/accuracy/README.md), not a
// check (test_accuracy.cpp checks). `tests_validation "[.hertz_table]"`.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "accuracy_cases.hpp"

using namespace polydem::validation::accuracy;

TEST_CASE("accuracy: Hertz restitution error table", "[.hertz_table]") {
  std::printf("| en | 0.3 x critical | 0.2 | 0.1 | 0.05 | 0.025 | order 0.2 -> 0.1 | 0.1 -> 0.05 | 0.05 -> 0.025 |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|\n");
  for (double en : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    const double at_03 = hertz_impact(0.3, en), at_02 = hertz_impact(0.2, en), at_01 = hertz_impact(0.1, en);
    const double at_005 = hertz_impact(0.05, en), at_0025 = hertz_impact(0.025, en);
    std::printf("| %.1f | %.2e | %.2e | %.2e | %.2e | %.2e | %.2f | %.2f | %.2f |\n", en, at_03, at_02, at_01, at_005, at_0025,
                std::log2(at_02 / at_01), std::log2(at_01 / at_005), std::log2(at_005 / at_0025));
    std::fflush(stdout);
  }
}
