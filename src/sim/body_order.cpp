#include "sim/body_order.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace polydem {

namespace {

// m: the largest bounding diameter of the bodies (0 when none is known: unknown shapes are
// build_bodies' to report).
double cell_size(const std::vector<BodySpec>& specs, const ShapeLibrary& library) {
  double d = 0.0;
  for (const BodySpec& s : specs) {
    const int shape = library.find(s.shape);
    if (shape >= 0) d = std::max(d, 2.0 * library.shapes[shape].bounding_radius * s.scale);
  }
  return d;
}

}  // namespace

std::vector<std::uint32_t> identity_order(std::size_t n) {
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  return order;
}

std::vector<std::uint32_t> spatial_order(const std::vector<BodySpec>& specs, const ShapeLibrary& library) {
  std::vector<std::uint32_t> order = identity_order(specs.size());
  const double cell = cell_size(specs, library);
  if (specs.empty() || !(cell > 0.0) || !std::isfinite(cell)) return order;
  Vec3 low = specs[0].position;
  for (const BodySpec& s : specs) {
    if (!s.position.allFinite()) return order;  // no order to sort by (the run refuses it later)
    low = low.cwiseMin(s.position);
  }
  using Key = std::array<double, 4>;  // cell z, y, x (whole numbers), then the user id
  std::vector<Key> key(specs.size());
  for (std::size_t b = 0; b < specs.size(); ++b) {
    const Vec3 c = (specs[b].position - low) / cell;
    key[b] = {std::floor(c.z()), std::floor(c.y()), std::floor(c.x()), double(b)};
  }
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
  return order;
}

bool is_order_of(const std::vector<std::uint32_t>& order, std::size_t n) {
  if (order.size() != n) return false;
  std::vector<std::uint8_t> seen(n, 0);
  for (std::uint32_t id : order)
    if (id >= n || seen[id]++) return false;
  return true;
}

// In place, cycle by cycle: the set-up holds one list of specs, not two (~210 bytes a body of
// the scene at its peak, on every rank).
std::vector<BodySpec> in_order(std::vector<BodySpec> specs, const std::vector<std::uint32_t>& order) {
  std::vector<std::uint8_t> placed(specs.size(), 0);
  for (std::size_t start = 0; start < specs.size(); ++start) {
    if (placed[start]) continue;
    BodySpec first = std::move(specs[start]);
    std::size_t k = start;
    for (; order[k] != start; k = order[k]) {  // k takes what order[k] held, still unmoved
      specs[k] = std::move(specs[order[k]]);
      placed[k] = 1;
    }
    specs[k] = std::move(first);
    placed[k] = 1;
  }
  return specs;
}

std::vector<std::uint32_t> by_user_id(const Bodies& bodies, std::vector<std::uint32_t> of) {
  std::sort(of.begin(), of.end(), [&](std::uint32_t a, std::uint32_t b) { return bodies.id[a] < bodies.id[b]; });
  return of;
}

}  // namespace polydem
