#include "io/placement.hpp"

#include <algorithm>
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

// Closest point to p on triangle (a, b, c), by its Voronoi regions (Ericson, Real-Time
// Collision Detection, 5.1.5); the triangle has a nonzero area.
Vec3 closest_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
    return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// Cells per axis at most: a flat 1 m plate gets 128 x 128 cells.
constexpr int kMaxMeshCells = 128;

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

DriverClearance::DriverClearance(const std::vector<DriverSettings>& drivers) {
  for (const DriverSettings& d : drivers) {
    if (d.motion.remove_at && *d.motion.remove_at <= 0.0) continue;  // gone at t = 0
    if (const MeshSettings* mesh = std::get_if<MeshSettings>(&d.kind))
      meshes_.push_back(load_mesh(*mesh));
    else
      shapes_.push_back(d.kind);
  }
}

DriverClearance::Mesh DriverClearance::load_mesh(const MeshSettings& s) {
  TriangleMesh file;
  try {
    file = read_stl(s.file);
  } catch (const InputError& e) {
    throw InputError(s.where + e.what());
  }
  Mesh m;
  const Quat q = s.rotation.normalized();
  Vec3 upper = Vec3::Constant(-1e300);
  m.lower = Vec3::Constant(1e300);
  double size_sum = 0.0;  // m, sum of the triangles' largest bounding-box sides
  for (const auto& t : file.triangles) {
    std::array<Vec3, 3> w;
    for (int k = 0; k < 3; ++k) w[k] = s.translation + q * (s.scale * file.vertices[t[k]]);
    // Zero area: the driver skips it (with a warning).
    if ((w[1] - w[0]).cross(w[2] - w[0]).squaredNorm() == 0.0) continue;
    const Vec3 lo = w[0].cwiseMin(w[1]).cwiseMin(w[2]), hi = w[0].cwiseMax(w[1]).cwiseMax(w[2]);
    m.lower = m.lower.cwiseMin(lo);
    upper = upper.cwiseMax(hi);
    size_sum += (hi - lo).maxCoeff();
    m.triangles.push_back(w);
  }
  if (m.triangles.empty()) return m;
  const Vec3 extent = upper - m.lower;
  // Cells about one triangle wide, so a triangle lands in a few cells and a cell holds a few.
  m.cell = std::max({size_sum / m.triangles.size(), extent.maxCoeff() / kMaxMeshCells, 1e-9});
  for (int k = 0; k < 3; ++k)
    m.dims[k] = std::clamp(static_cast<int>(std::ceil(extent[k] / m.cell)), 1, kMaxMeshCells);
  auto coord = [&m](double x, int k) {
    return std::clamp(static_cast<int>(std::floor((x - m.lower[k]) / m.cell)), 0, m.dims[k] - 1);
  };
  m.begin.assign(static_cast<std::size_t>(m.dims[0]) * m.dims[1] * m.dims[2] + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {  // count the entries per cell, then fill them
    std::vector<std::uint32_t> fill(m.begin.begin(), m.begin.end() - 1);
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
      const auto& w = m.triangles[t];
      const Vec3 lo = w[0].cwiseMin(w[1]).cwiseMin(w[2]), hi = w[0].cwiseMax(w[1]).cwiseMax(w[2]);
      std::array<int, 3> a, b;
      for (int k = 0; k < 3; ++k) a[k] = coord(lo[k], k), b[k] = coord(hi[k], k);
      for (int k = a[2]; k <= b[2]; ++k)
        for (int j = a[1]; j <= b[1]; ++j)
          for (int i = a[0]; i <= b[0]; ++i) {
            const std::size_t c = (static_cast<std::size_t>(k) * m.dims[1] + j) * m.dims[0] + i;
            if (pass == 0) ++m.begin[c + 1]; else m.entries[fill[c]++] = t;
          }
    }
    if (pass == 0) {
      for (std::size_t c = 1; c < m.begin.size(); ++c) m.begin[c] += m.begin[c - 1];
      m.entries.resize(m.begin.back());
    }
  }
  return m;
}

bool DriverClearance::mesh_clear(const Mesh& m, const Vec3& center, double radius, double touch) {
  if (m.triangles.empty()) return true;
  const double reach = radius - touch;  // m, a triangle closer than this overlaps the sphere
  std::array<int, 3> a, b;
  for (int k = 0; k < 3; ++k) {
    const double lo = (center[k] - reach - m.lower[k]) / m.cell,
                 hi = (center[k] + reach - m.lower[k]) / m.cell;
    if (hi < 0.0 || lo >= m.dims[k]) return true;  // the sphere's box misses the grid
    a[k] = std::max(0, static_cast<int>(std::floor(lo)));
    b[k] = std::min(m.dims[k] - 1, static_cast<int>(std::floor(hi)));
  }
  for (int k = a[2]; k <= b[2]; ++k)
    for (int j = a[1]; j <= b[1]; ++j)
      for (int i = a[0]; i <= b[0]; ++i) {
        const std::size_t c = (static_cast<std::size_t>(k) * m.dims[1] + j) * m.dims[0] + i;
        for (std::uint32_t e = m.begin[c]; e < m.begin[c + 1]; ++e) {
          const auto& w = m.triangles[m.entries[e]];
          const Vec3 q = closest_on_triangle(center, w[0], w[1], w[2]);
          if ((q - center).squaredNorm() < reach * reach) return false;
        }
      }
  return true;
}

bool DriverClearance::shape_clear(const KindSettings& kind, const Vec3& center, double radius,
                                  double touch) {
  if (const WallSettings* s = std::get_if<WallSettings>(&kind))  // the particles' side is along the normal
    return (center - s->point).dot(s->normal.normalized()) > radius - touch;
  if (const BallSettings* s = std::get_if<BallSettings>(&kind))
    return (center - s->center).norm() > s->radius + radius - touch;
  const CylinderSettings& s = std::get<CylinderSettings>(kind);
  const Vec3 axis = s.axis.normalized();
  const Vec3 rel = center - s.center;
  double along = rel.dot(axis);
  const double half = s.length ? 0.5 * *s.length : 1e300;  // m, half the length; infinite: no end
  if (s.inside)  // a sphere past an open end cannot reach the mantle
    return std::abs(along) >= half + radius ||
           (rel - along * axis).norm() < s.radius - radius + touch;
  along = std::clamp(along, -half, half);  // outside: the axis segment swept by R
  return (rel - along * axis).norm() > s.radius + radius - touch;
}

bool DriverClearance::clear(const Vec3& center, double radius) const {
  const double touch = 1e-9 * radius;  // m, round-off of a sphere placed exactly against a driver
  for (const KindSettings& s : shapes_)
    if (!shape_clear(s, center, radius, touch)) return false;
  for (const Mesh& m : meshes_)
    if (!mesh_clear(m, center, radius, touch)) return false;
  return true;
}

}  // namespace polydem
