#include "neighbor/broad_phase.hpp"

namespace polydem {

void brute_force_pairs(const std::vector<Vec3>& centers, const std::vector<double>& radii,
                       double skin, std::vector<BodyPair>& out) {
  out.clear();
  const std::size_t n = centers.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& a = centers[i];
    for (std::size_t j = i + 1; j < n; ++j) {
      const Vec3& b = centers[j];
      if (within_reach(a.x(), a.y(), a.z(), radii[i], b.x(), b.y(), b.z(), radii[j], skin)) {
        out.push_back({static_cast<std::uint32_t>(i), static_cast<std::uint32_t>(j)});
      }
    }
  }
}

}  // namespace polydem
