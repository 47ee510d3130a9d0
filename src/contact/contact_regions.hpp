#pragma once
// Contact regions of a pair with a non-convex body: the face-patch rule (one spring kn per flat
// contact whatever its vertex count) applies per region, so a cross on three arm tips is three
// springs and a straight polyline lying flat is one.
#include <cstddef>
#include <vector>

#include "geometry/features.hpp"

namespace polydem {

// True when two sub-contacts of one pair touch in one region: on each non-convex body, their
// features lie on one common feature (the same one, a vertex of an edge or face, two ends of an
// edge, two corners of a face). The core between the two contact points is then a segment of
// that feature, whose distance to a convex feature of the other body is a convex function along
// it, so it stays in contact between them. `b` is null for a driver (its features count as one).
bool same_region(const Shape& a, const Shape* b, FeaturePair x, FeaturePair y);

// Patch weights per region: w_k = s_k / (sum of s over k's region), s_k = band - gap_k (m), the
// rule of patch_weights (pair_kernel.hpp) within each region. Regions are the connected groups
// of same_region, found in sub-contact order (deterministic). Equal shares when a region's sum
// is not > 0.
template <class KeyAt, class GapAt>
void region_patch_weights(std::size_t n, const KeyAt& key_at, const GapAt& gap_at, const Shape& a, const Shape* b,
                          double band, std::vector<double>& weight, std::vector<std::uint32_t>& region) {
  weight.resize(n);
  region.resize(n);
  for (std::size_t k = 0; k < n; ++k) {  // label: the first earlier sub-contact's region it joins
    region[k] = std::uint32_t(k);
    for (std::size_t l = 0; l < k; ++l)
      if (same_region(a, b, key_at(l), key_at(k))) {
        const std::uint32_t from = region[k], to = region[l];
        if (from == to) continue;
        for (std::size_t m = 0; m <= k; ++m)  // merge k's current region into l's
          if (region[m] == from) region[m] = to;
      }
  }
  for (std::size_t k = 0; k < n; ++k) weight[k] = band - gap_at(k);
  for (std::size_t r = 0; r < n; ++r) {
    double total = 0.0;
    std::size_t count = 0;
    for (std::size_t k = 0; k < n; ++k)
      if (region[k] == r) total += weight[k], ++count;
    if (count == 0) continue;
    for (std::size_t k = 0; k < n; ++k)
      if (region[k] == r) weight[k] = total > 0.0 ? weight[k] / total : 1.0 / double(count);
  }
}

}  // namespace polydem
