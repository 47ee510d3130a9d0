#pragma once
// Random placements of two bodies at a chosen separation (negative: overlap), for the
// brute-force and separation tests. Parallel edges and coplanar faces are made on purpose.
#include <memory>
#include <random>
#include <vector>

#include "gjk.hpp"
#include "test_shapes.hpp"

namespace polydem::test {

// Shapes of every kind the tests mix: sphere, cube, thin plate, needle, octahedron,
// tetrahedron, hexagonal prism (hexagonal faces).
inline const std::vector<Shape>& shape_zoo() {
  static const std::vector<Shape> zoo = {make_sphere(0.3),       make_cube(0.5, 0.05),         make_plate(0.02),
                                         make_needle(0.03),      make_octahedron(0.6, 0.04),   make_tetrahedron(0.4, 0.05),
                                         make_hex_prism(0.5, 0.3, 0.05)};
  return zoo;
}

struct PairPose {
  const Shape* sa;
  const Shape* sb;
  double scale_a, scale_b;
  Quat qa, qb;
  Vec3 direction;  // unit, from B's centre to A's
  Vec3 lateral;    // m, offset of A across `direction`
};

// m, distance between the rounded bodies with A's centre at lateral + along * direction, B at 0.
inline double rounded_distance(const PairPose& p, double along) {
  const Posed a(*p.sa, p.scale_a, p.lateral + along * p.direction, p.qa), b(*p.sb, p.scale_b, Vec3::Zero(), p.qb);
  return hull_distance(a.world, b.world) - a.body().radius - b.body().radius;
}

// Centre distance along `direction` at which the rounded bodies about touch, from above
// (never overlapping): conservative advancement, as the distance is 1-Lipschitz in the shift.
inline double touching_distance(const PairPose& p) {
  double along = p.scale_a * p.sa->bounding_radius + p.scale_b * p.sb->bounding_radius + p.lateral.norm();
  for (int k = 0; k < 30; ++k) {
    const double gap = rounded_distance(p, along);
    if (gap <= 1e-4) break;  // m, about touching at the scale of these unit-size shapes
    along -= gap;
  }
  return along;
}

inline PairPose random_pair_pose(std::mt19937_64& rng, int trial) {
  const std::vector<Shape>& zoo = shape_zoo();
  std::uniform_int_distribution<std::size_t> pick(0, zoo.size() - 1);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PairPose p;
  p.sa = &zoo[pick(rng)];
  p.sb = &zoo[pick(rng)];
  // Every third trial is axis-aligned: parallel edges, coplanar faces, vertices above vertices.
  const bool aligned = trial % 3 == 0;
  p.scale_a = aligned ? 1.0 : 0.5 + 0.5 * (u(rng) + 1.0);
  p.scale_b = aligned ? 1.0 : 0.5 + 0.5 * (u(rng) + 1.0);
  p.qa = aligned ? random_axis_rotation(rng) : random_rotation(rng);
  p.qb = aligned ? random_axis_rotation(rng) : random_rotation(rng);
  p.direction = aligned ? Vec3(p.qb * Vec3::Unit(trial % 2 == 0 ? 2 : 0)) : random_unit(rng);
  const Vec3 side = p.direction.unitOrthogonal();
  p.lateral = aligned ? Vec3(0.25 * std::round(2.0 * u(rng)) * side) : Vec3::Zero();
  return p;
}

}  // namespace polydem::test
