#pragma once
// Contact geometry of the driver surfaces against a posed body. A plane, and the inside of a
// cylinder, meet a convex body first at its vertices (the farthest point of a convex body from
// an axis is a vertex), so their candidates are the body's vertices; a ball is a one-vertex
// spheropolyhedron and the outside of a cylinder a segment (its axis) swept by its radius:
// both use the body-body kernels. Meshes: see mesh.hpp.
#include <vector>

#include "driver/drivers.hpp"

namespace polydem {

void wall_candidates(const Driver& d, const PosedBody& a, double range, std::vector<FeaturePair>& out);
bool wall_contact(const Driver& d, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out);

bool cylinder_near(const Driver& d, const Vec3& center, double reach);
void cylinder_candidates(const Driver& d, const PosedBody& a, double range, std::vector<FeaturePair>& out);
bool cylinder_contact(const Driver& d, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out);

// Outside of a cylinder: a finite one has rounded (hemispherical) ends, the capsule around
// its axis segment; an infinite one is the segment through the body's projection on the axis,
// longer than the body, so its ends never touch.
bool outer_cylinder_near(const Driver& d, const Vec3& center, double reach);
void outer_cylinder_candidates(const Driver& d, const PosedBody& a, double range, std::vector<FeaturePair>& out);
bool outer_cylinder_contact(const Driver& d, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out);

bool mesh_near(const Driver& d, const Vec3& center, double reach);
void mesh_candidates(const Driver& d, const PosedBody& a, double range, std::vector<FeaturePair>& out);
bool mesh_contact(const Driver& d, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out);

Shape axis_shape(const std::string& name, double radius);  // outer cylinder: two vertices, one edge
// The ball as a posed body: its one vertex at its current centre.
PosedBody ball_pose(const Driver& d);

}  // namespace polydem
