#pragma once
// Exact mass properties of a spheropolyhedron (core polyhedron swept by a sphere of radius r).
#include "polydem/shape.hpp"

namespace polydem {

// Volume, centre of mass and inertia of the ROUNDED body, for a shape given in any frame.
// Moves the vertices into the principal frame about the centre of mass (moments ascending,
// right-handed), sets input_center/input_rotation, inertia_per_mass, bounding_radius,
// face_normals and edge_planes, and fills `edges` from the faces when it is empty. Exact
// (closed forms, no quadrature): only round-off error. Supported topologies: one vertex
// (sphere), two vertices and one edge (segment), or faces closing every edge twice (a solid or
// a two-sided plate).
// Throws InputError "shape 'NAME': ..." for any other topology or a zero volume.
void compute_mass_properties(Shape& s);

// For shapes whose mass properties were given (a .shp with preCompDone y): checks the
// topology, orients the faces outward, fills edges, face_normals, edge_planes and
// bounding_radius, and leaves the vertices where they are.
void compute_derived_geometry(Shape& s);

}  // namespace polydem
