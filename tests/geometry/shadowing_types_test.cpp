// find_contacts keeps a pair's found types as one bit mask: the mask's answers must be those of
// shadows and may_be_shadowed over the types in it, for every set of types.
#include <catch2/catch.hpp>

#include "geometry/shadowing.hpp"

using namespace polydem;

TEST_CASE("a set of pair types shadows and may be shadowed as its members do") {
  for (unsigned types = 0; types < (1u << kPairTypeCount); ++types) {
    bool shadowing = false, shadowable = false;
    for (int t = 0; t < kPairTypeCount; ++t) {
      if (!(types & (1u << t))) continue;
      shadowing |= shadows(PairType(t));
      shadowable |= may_be_shadowed(PairType(t));
    }
    CAPTURE(types);
    CHECK(shadows_any(types) == shadowing);
    CHECK(may_be_shadowed_any(types) == shadowable);
  }
}
