#include "sim/last_good.hpp"

namespace polydem {

namespace {

// A kept body as bytes: its id and moving state (108 bytes).
struct KeptBody {
  std::uint32_t id;
  double position[3], velocity[3], angular_velocity[3], orientation[4];
};

void put(double* out, const double* in, int n) { std::copy(in, in + n, out); }

}  // namespace

LastGood LastGood::gathered(const RankLink& link) const {
  std::vector<char> bytes;
  for (std::size_t k = 0; k < ids.size(); ++k) {
    KeptBody kept{ids[k], {}, {}, {}, {0.0, 0.0, 0.0, 1.0}};  // Eigen's coefficients: x, y, z, w
    put(kept.position, position[k].data(), 3);
    put(kept.velocity, velocity[k].data(), 3);
    put(kept.angular_velocity, angular_velocity[k].data(), 3);
    if (!orientation.empty()) put(kept.orientation, orientation[k].coeffs().data(), 4);
    append_record(bytes, kept);
  }
  LastGood all;
  const std::vector<std::vector<char>> from = link.gather(bytes, 0);
  std::size_t n = 0;
  for (const std::vector<char>& b : from) n += b.size() / sizeof(KeptBody);
  all.position.resize(n);
  all.velocity.resize(n);
  all.angular_velocity.resize(n);
  all.orientation.assign(n, Quat::Identity());
  for (const std::vector<char>& b : from)
    for (std::size_t at = 0; at < b.size(); at += sizeof(KeptBody)) {
      KeptBody kept;
      std::memcpy(static_cast<void*>(&kept), b.data() + at, sizeof kept);
      put(all.position[kept.id].data(), kept.position, 3);
      put(all.velocity[kept.id].data(), kept.velocity, 3);
      put(all.angular_velocity[kept.id].data(), kept.angular_velocity, 3);
      put(all.orientation[kept.id].coeffs().data(), kept.orientation, 4);
    }
  return all;
}

}  // namespace polydem
