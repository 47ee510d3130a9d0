#pragma once
// Volume moments of a non-convex rounded body: the union of its swept elements (a ball per
// vertex, a cylinder per edge, a slab per face), overlaps counted once.
#include "polydem/shape.hpp"
#include "shape/moments.hpp"

namespace polydem {

// Balls apart from each other (a cluster without edges or faces, no two closer than 2 r): the
// sum of their closed forms, relative_error 0. Otherwise lines along z through the centres of a
// cells x cells grid over the body's xy box: each line meets every element in an interval, the
// union of the intervals is integrated exactly (1, z, z^2), the grid by the midpoint rule.
// The lines run along a fixed generic direction, not along an axis of the shape's frame.
// relative_error: 4 x the largest relative change of the volume and of the inertia tensor
// (about the centre of mass, Frobenius norm) from the grid of cells/2 to this one, a bound of
// the error of this grid (tests/shape/union_mass_test.cpp checks it against closed forms: the
// midpoint rule's error falls as cells^-1.5 at the silhouettes, not evenly). At the default
// 1024 cells: below 1e-4 on the alpha3 cross, 2e-5 on a lens. Vertices about the origin.
Moments union_moments(const Shape& s, int cells, double& relative_error);

}  // namespace polydem
