#include "io/placement.hpp"

#include <algorithm>
#include <optional>
#include <cmath>

#include "io/random.hpp"
#include "polydem/error.hpp"
#include "shape/point_sources.hpp"

namespace polydem {
namespace {

// Two unit vectors completing `axis` to a right-handed orthonormal frame.
void radial_frame(const Vec3& axis, Vec3& e1, Vec3& e2) {
  const Vec3 helper = std::abs(axis.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  e1 = (helper - helper.dot(axis) * axis).normalized();
  e2 = axis.cross(e1);
}

// Lattice coordinates k*spacing (k = 0..n-1) centred in [0, extent]; n may be 0.
std::vector<double> centred_sites(double extent, double spacing) {
  const int n = static_cast<int>(std::floor(extent / spacing * (1.0 + 1e-12)));
  const double offset = 0.5 * (extent - n * spacing) + 0.5 * spacing;
  std::vector<double> sites;
  for (int k = 0; k < n; ++k) sites.push_back(offset + k * spacing);
  return sites;
}

}  // namespace

Region::Region(const std::variant<BoxRegion, CylinderRegion>& region)
    : is_box_(std::holds_alternative<BoxRegion>(region)) {
  if (is_box_) {
    box_ = std::get<BoxRegion>(region);
    lower_ = box_.min;
    upper_ = box_.max;
    return;
  }
  cylinder_ = std::get<CylinderRegion>(region);
  radial_frame(cylinder_.axis, e1_, e2_);
  const Vec3 top = cylinder_.center + cylinder_.length * cylinder_.axis;
  // A disc of radius r normal to a reaches r sqrt(1 - a_k^2) along axis k.
  const Vec3 reach =
      cylinder_.radius * (Vec3::Ones() - cylinder_.axis.cwiseAbs2()).cwiseMax(0.0).cwiseSqrt();
  lower_ = cylinder_.center.cwiseMin(top) - reach;
  upper_ = cylinder_.center.cwiseMax(top) + reach;
}

bool Region::fits(double radius) const {
  if (is_box_) return ((box_.max - box_.min).array() >= 2.0 * radius).all();
  return cylinder_.radius >= radius && cylinder_.length >= 2.0 * radius;
}

Vec3 Region::sample(double radius, std::mt19937_64& rng) const {
  if (is_box_) {
    Vec3 c;
    for (int k = 0; k < 3; ++k) {
      const double lo = box_.min[k] + radius, hi = box_.max[k] - radius;
      c[k] = lo + (hi - lo) * uniform01(rng);
    }
    return c;
  }
  const double along = radius + (cylinder_.length - 2.0 * radius) * uniform01(rng);
  const double rho = (cylinder_.radius - radius) * std::sqrt(uniform01(rng));  // uniform in area
  const double phi = 2.0 * kPi * uniform01(rng);
  return cylinder_.center + along * cylinder_.axis +
         rho * (std::cos(phi) * e1_ + std::sin(phi) * e2_);
}

std::vector<Vec3> Region::lattice(double spacing) const {
  std::vector<Vec3> sites;
  if (is_box_) {
    const Vec3 extent = box_.max - box_.min;
    const auto xs = centred_sites(extent.x(), spacing), ys = centred_sites(extent.y(), spacing),
               zs = centred_sites(extent.z(), spacing);
    for (double z : zs)
      for (double y : ys)
        for (double x : xs) sites.push_back(box_.min + Vec3(x, y, z));
    return sites;
  }
  const double reach =
      cylinder_.radius - 0.5 * spacing;  // m, largest centre distance from the axis
  if (reach < 0.0) return sites;
  const int n = static_cast<int>(std::floor(reach / spacing * (1.0 + 1e-12)));
  for (double w : centred_sites(cylinder_.length, spacing))
    for (int j = -n; j <= n; ++j)
      for (int i = -n; i <= n; ++i) {
        const double u = i * spacing, v = j * spacing;
        if (u * u + v * v > reach * reach * (1.0 + 1e-12)) continue;
        sites.push_back(cylinder_.center + w * cylinder_.axis + u * e1_ + v * e2_);
      }
  return sites;
}

SphereGrid::SphereGrid(const Vec3& lower, const Vec3& upper, double max_radius,
                       std::size_t expected)
    : lower_(lower) {
  const Vec3 extent = (upper - lower).cwiseMax(1e-300);
  // Cells at least one diameter wide, and not many more cells than spheres in a huge region.
  const double max_cells = std::max(64.0, 4.0 * static_cast<double>(expected));
  cell_size_ = std::max(2.0 * max_radius, std::cbrt(extent.prod() / max_cells));
  for (int k = 0; k < 3; ++k)
    dims_[k] =
        std::max(1, static_cast<int>(std::min(std::ceil(extent[k] / cell_size_), max_cells)));
  head_.assign(static_cast<std::size_t>(dims_[0]) * dims_[1] * dims_[2], -1);
}

int SphereGrid::cell_coord(double x, int axis) const {
  const int c = static_cast<int>(std::floor((x - lower_[axis]) / cell_size_));
  return std::clamp(c, 0, dims_[axis] - 1);
}

std::size_t SphereGrid::cell_of(int i, int j, int k) const {
  return (static_cast<std::size_t>(k) * dims_[1] + j) * dims_[0] + i;
}

bool SphereGrid::overlaps(const Vec3& center, double radius) const {
  const int ci = cell_coord(center.x(), 0), cj = cell_coord(center.y(), 1),
            ck = cell_coord(center.z(), 2);
  for (int k = std::max(0, ck - 1); k <= std::min(dims_[2] - 1, ck + 1); ++k)
    for (int j = std::max(0, cj - 1); j <= std::min(dims_[1] - 1, cj + 1); ++j)
      for (int i = std::max(0, ci - 1); i <= std::min(dims_[0] - 1, ci + 1); ++i)
        for (int s = head_[cell_of(i, j, k)]; s >= 0; s = next_[s]) {
          const double reach = radius + radii_[s];
          if ((centers_[s] - center).squaredNorm() < reach * reach) return true;
        }
  return false;
}

void SphereGrid::insert(const Vec3& center, double radius) {
  const std::size_t cell =
      cell_of(cell_coord(center.x(), 0), cell_coord(center.y(), 1), cell_coord(center.z(), 2));
  next_.push_back(head_[cell]);
  head_[cell] = static_cast<int>(centers_.size());
  centers_.push_back(center);
  radii_.push_back(radius);
}

DriverClearance::DriverClearance(const std::vector<DriverSettings>& drivers) : drivers_(drivers) {
  for (std::uint32_t j = 0; j < drivers.size(); ++j) {
    const std::optional<double>& removed = drivers[j].motion.remove_at;
    if (!removed || *removed > 0.0) present_.push_back(j);  // not gone at t = 0
  }
}

bool DriverClearance::clear(const Vec3& center, double radius) const {
  const double touch = 1e-9 * radius;  // m, round-off of a sphere placed exactly against a driver
  for (std::uint32_t j : present_)
    if (drivers_.overlaps(j, center, radius - touch)) return false;
  return true;
}

}  // namespace polydem
