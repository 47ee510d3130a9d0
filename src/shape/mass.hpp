#pragma once
// Mass properties of a spheropolyhedron (vertices, edges and faces swept by a sphere of radius r).
#include "polydem/shape.hpp"

namespace polydem {

// Volume, centre of mass and inertia of the ROUNDED body, for a shape given in any frame.
// Moves the vertices into the principal frame about the centre of mass (moments ascending,
// right-handed), sets input_center/input_rotation, inertia_per_mass, bounding_radius,
// face_normals and edge_planes, and fills `edges` from the faces when it is empty. A convex
// core (sphere, segment, convex polyhedron, plate) has closed forms: only round-off error.
// Any other shape is the union of its swept elements (union_mass.hpp): spheres apart from
// each other are closed forms; otherwise a quadrature on `quadrature_cells`^2 lines, its
// relative error bound in mass_error.
// Throws InputError "shape 'NAME': ..." for bad indices, degenerate elements, a zero volume or
// a quadrature error bound above kMassErrorLimit.
inline constexpr int kQuadratureCells = 1024;
inline constexpr double kMassErrorLimit = 1e-2;  // larger quadrature bounds are refused
void compute_mass_properties(Shape& s, int quadrature_cells = kQuadratureCells);

// For shapes whose mass properties were given (a .shp with preCompDone y): checks the
// topology, orients the faces outward, fills edges, face_normals, edge_planes and
// bounding_radius, and leaves the vertices where they are.
void compute_derived_geometry(Shape& s);

}  // namespace polydem
