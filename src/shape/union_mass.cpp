#include "shape/union_mass.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "shape/topology.hpp"

namespace polydem {
namespace {

struct Interval {
  double lo, hi;  // m, along z
};

// Where a line (x, y, t) satisfies a + b t >= 0: narrows [lo, hi]; false when empty.
bool keep_side(double a, double b, double& lo, double& hi) {
  if (b > 0.0) {
    lo = std::max(lo, -a / b);
  } else if (b < 0.0) {
    hi = std::min(hi, -a / b);
  } else if (a < 0.0) {
    return false;
  }
  return lo < hi;
}

// Where a line (x, y, t) satisfies A t^2 + B t + C <= 0 with A >= 0: narrows [lo, hi].
bool keep_inside_quadric(double A, double B, double C, double& lo, double& hi) {
  if (A <= 1e-14) return keep_side(-C, -B, lo, hi);  // a line along the axis: linear
  const double disc = B * B - 4.0 * A * C;
  if (disc <= 0.0) return false;
  const double root = std::sqrt(disc);
  lo = std::max(lo, (-B - root) / (2.0 * A));
  hi = std::min(hi, (-B + root) / (2.0 * A));
  return lo < hi;
}

// One swept element: a ball, an edge's cylinder (no caps: its balls close it) or a face's slab.
struct Element {
  enum Kind { ball, cylinder, slab } kind = ball;
  Vec3 a = Vec3::Zero();   // m, centre, axis start, or a face vertex
  Vec3 u = Vec3::Zero();   // unit axis, or unit face normal
  double length = 0.0;     // m, of the axis
  std::vector<Vec3> corners, inward;  // slab: polygon corners and in-plane inward edge normals
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;  // m, box in the xy plane
};

bool meets(const Element& e, double r, double x, double y, Interval& out) {
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  const Vec3 w0(x - e.a.x(), y - e.a.y(), -e.a.z());  // m, line point at t = 0, from a
  switch (e.kind) {
    case Element::ball:
      if (!keep_inside_quadric(1.0, 2.0 * w0.z(), w0.squaredNorm() - r * r, lo, hi)) return false;
      break;
    case Element::cylinder: {
      const Vec3 ez_perp = Vec3::UnitZ() - e.u.z() * e.u;
      const Vec3 w_perp = w0 - w0.dot(e.u) * e.u;
      if (!keep_inside_quadric(ez_perp.squaredNorm(), 2.0 * w_perp.dot(ez_perp), w_perp.squaredNorm() - r * r, lo, hi))
        return false;
      if (!keep_side(w0.dot(e.u), e.u.z(), lo, hi) || !keep_side(e.length - w0.dot(e.u), -e.u.z(), lo, hi))
        return false;
      break;
    }
    case Element::slab: {
      const double h = w0.dot(e.u);  // m, height over the face plane at t = 0
      if (!keep_side(r + h, e.u.z(), lo, hi) || !keep_side(r - h, -e.u.z(), lo, hi)) return false;
      for (std::size_t k = 0; k < e.corners.size(); ++k) {
        const Vec3 c(x - e.corners[k].x(), y - e.corners[k].y(), -e.corners[k].z());
        if (!keep_side(c.dot(e.inward[k]), e.inward[k].z(), lo, hi)) return false;
      }
      break;
    }
  }
  out = {lo, hi};
  return true;
}

void set_box(Element& e, const std::vector<Vec3>& points, double r) {
  e.xmin = e.ymin = std::numeric_limits<double>::infinity();
  e.xmax = e.ymax = -std::numeric_limits<double>::infinity();
  for (const Vec3& p : points) {
    e.xmin = std::min(e.xmin, p.x() - r), e.xmax = std::max(e.xmax, p.x() + r);
    e.ymin = std::min(e.ymin, p.y() - r), e.ymax = std::max(e.ymax, p.y() + r);
  }
}

std::vector<Element> elements_of(const Shape& s) {
  std::vector<Element> out;
  const double r = s.radius;
  for (const Vec3& v : s.vertices) {
    Element e;
    e.kind = Element::ball;
    e.a = v;
    set_box(e, {v}, r);
    out.push_back(e);
  }
  for (const auto& edge : s.edges) {
    const Vec3 &p = s.vertices[edge[0]], &q = s.vertices[edge[1]];
    Element e;
    e.kind = Element::cylinder;
    e.a = p;
    e.length = (q - p).norm();
    e.u = (q - p) / e.length;
    set_box(e, {p, q}, r);
    out.push_back(e);
  }
  for (const auto& face : s.faces) {
    Element e;
    e.kind = Element::slab;
    e.a = s.vertices[face[0]];
    e.u = polygon_normal(s.vertices, face);  // corners counter-clockwise about it
    for (std::size_t k = 0; k < face.size(); ++k) {
      const Vec3& p = s.vertices[face[k]];
      e.corners.push_back(p);
      e.inward.push_back(e.u.cross(s.vertices[face[(k + 1) % face.size()]] - p).normalized());
    }
    set_box(e, e.corners, r);
    out.push_back(e);
  }
  return out;
}

// Integrals of 1, z, z^2 along the union of the intervals (sorted in place).
void integrate_union(std::vector<Interval>& parts, double& l0, double& l1, double& l2) {
  std::sort(parts.begin(), parts.end(), [](const Interval& a, const Interval& b) { return a.lo < b.lo; });
  l0 = l1 = l2 = 0.0;
  std::size_t k = 0;
  while (k < parts.size()) {
    double lo = parts[k].lo, hi = parts[k].hi;
    for (++k; k < parts.size() && parts[k].lo <= hi; ++k) hi = std::max(hi, parts[k].hi);
    l0 += hi - lo;
    l1 += 0.5 * (hi * hi - lo * lo);
    l2 += (hi * hi * hi - lo * lo * lo) / 3.0;
  }
}

Moments midpoint_grid(const std::vector<Element>& elements, double r, double x0, double x1, double y0, double y1,
                      int cells) {
  const double hx = (x1 - x0) / cells, hy = (y1 - y0) / cells, area = hx * hy;
  Moments m;
  std::vector<const Element*> column;
  std::vector<Interval> parts;
  for (int i = 0; i < cells; ++i) {
    const double x = x0 + (i + 0.5) * hx;
    column.clear();
    for (const Element& e : elements)
      if (e.xmin <= x && x <= e.xmax) column.push_back(&e);
    for (int j = 0; j < cells; ++j) {
      const double y = y0 + (j + 0.5) * hy;
      parts.clear();
      Interval seg;
      for (const Element* e : column)
        if (e->ymin <= y && y <= e->ymax && meets(*e, r, x, y, seg)) parts.push_back(seg);
      if (parts.empty()) continue;
      double l0, l1, l2;
      integrate_union(parts, l0, l1, l2);
      m.volume += area * l0;
      m.first += area * Vec3(x * l0, y * l0, l1);
      Mat3 q;
      q << x * x * l0, x * y * l0, x * l1, x * y * l0, y * y * l0, y * l1, x * l1, y * l1, l2;
      m.second += area * q;
    }
  }
  return m;
}

// m^2, inertia per unit mass about the centre of mass.
Mat3 inertia_per_mass(const Moments& m) {
  const Vec3 c = m.first / m.volume;
  const Mat3 spread = m.second / m.volume - c * c.transpose();
  return spread.trace() * Mat3::Identity() - spread;
}

// Balls (no edge, no face) none of which overlaps another.
bool apart_balls(const Shape& s) {
  if (!s.edges.empty() || !s.faces.empty()) return false;
  for (std::size_t i = 0; i < s.vertices.size(); ++i)
    for (std::size_t j = i + 1; j < s.vertices.size(); ++j)
      if ((s.vertices[i] - s.vertices[j]).norm() < 2.0 * s.radius) return false;
  return true;
}

Moments balls(const Shape& s) {
  const double r = s.radius, v = 4.0 / 3.0 * kPi * r * r * r;
  Moments m;
  for (const Vec3& c : s.vertices) {
    m.volume += v;
    m.first += v * c;
    m.second += v * (c * c.transpose() + r * r / 5.0 * Mat3::Identity());
  }
  return m;
}

constexpr double kSafety = 4.0;  // bound over the change from the half grid

// The moments of the shape turned by `turn`, turned back.
Moments turned_back(const Moments& m, const Mat3& turn) {
  Moments out;
  out.volume = m.volume;
  out.first = turn.transpose() * m.first;
  out.second = turn.transpose() * m.second * turn;
  return out;
}

}  // namespace

Moments union_moments(const Shape& given, int cells, double& relative_error) {
  relative_error = 0.0;
  if (apart_balls(given)) return balls(given);
  // Lines along a generic direction: shapes given along the axes (a cross, a box) would put
  // their silhouettes along the grid lines, where the midpoint rule's errors add up.
  const Mat3 turn = Quat(Eigen::AngleAxisd(0.7, Vec3(0.3, 0.5, 0.8).normalized())).toRotationMatrix();
  Shape s = given;
  for (Vec3& v : s.vertices) v = turn * v;
  const std::vector<Element> elements = elements_of(s);
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const Element& e : elements) {
    x0 = std::min(x0, e.xmin), x1 = std::max(x1, e.xmax);
    y0 = std::min(y0, e.ymin), y1 = std::max(y1, e.ymax);
  }
  const Moments fine = midpoint_grid(elements, s.radius, x0, x1, y0, y1, cells);
  const Moments coarse = midpoint_grid(elements, s.radius, x0, x1, y0, y1, std::max(1, cells / 2));
  if (!(fine.volume > 0.0) || !(coarse.volume > 0.0)) return turned_back(fine, turn);
  const Mat3 i_fine = inertia_per_mass(fine);
  // Four times the change: the midpoint rule's error at a sphere's silhouette falls as cells^-1.5
  // on average but not evenly (a lens's inertia changed by 1.1e-6 where its error was 2.3e-6).
  relative_error = kSafety * std::max(std::abs(fine.volume - coarse.volume) / fine.volume,
                                      (i_fine - inertia_per_mass(coarse)).norm() / i_fine.norm());
  return turned_back(fine, turn);
}

}  // namespace polydem
