#include "sim/slabs.hpp"

#include <algorithm>
#include <numeric>

namespace polydem {

int Slabs::owner(const Vec3& x) const {
  return int(std::upper_bound(cuts.begin(), cuts.end(), x[axis]) - cuts.begin());
}

double Slabs::distance(int p, const Vec3& x) const {
  const double c = x[axis];
  if (p > 0 && c < cuts[p - 1]) return cuts[p - 1] - c;
  if (p < int(cuts.size()) && c >= cuts[p]) return c - cuts[p];
  return 0.0;
}

Slabs cut_slabs(const std::vector<Vec3>& x, int parts) {
  Slabs s;
  if (x.empty() || parts < 2) return s;
  Vec3 lo = x[0], hi = x[0];
  for (const Vec3& c : x) {
    lo = lo.cwiseMin(c);
    hi = hi.cwiseMax(c);
  }
  (hi - lo).maxCoeff(&s.axis);
  std::vector<double> coord(x.size());
  for (std::size_t b = 0; b < x.size(); ++b) coord[b] = x[b][s.axis];
  std::sort(coord.begin(), coord.end());
  for (int p = 1; p < parts; ++p) s.cuts.push_back(coord[x.size() * std::size_t(p) / std::size_t(parts)]);
  return s;
}

// A part in a million over the reach: the slab distance and the pair test round differently.
double ghost_halo(double max_bounding_radius, double range) { return (2.0 * max_bounding_radius + range) * (1.0 + 1e-6); }

}  // namespace polydem
