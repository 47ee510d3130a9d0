#pragma once
// Contact geometry of the analytic driver surfaces against a posed body. A plane, and the
// inside of a cylinder, meet a convex body first at its vertices (the farthest point of a
// convex body from an axis is a vertex), so their candidates are the body's vertices; a ball
// is a one-vertex spheropolyhedron and uses the body-body kernels.
#include <vector>

#include "driver/drivers.hpp"

namespace polydem {

void wall_candidates(const Driver& d, const PosedBody& a, double range, std::vector<FeaturePair>& out);
bool wall_contact(const Driver& d, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out);

bool cylinder_near(const Driver& d, const Vec3& center, double reach);
void cylinder_candidates(const Driver& d, const PosedBody& a, double range, std::vector<FeaturePair>& out);
bool cylinder_contact(const Driver& d, const PosedBody& a, FeaturePair f, double max_gap, ContactPoint& out);

Shape ball_shape(const std::string& name, double radius);
// The ball as a posed body: its one vertex at its current centre.
PosedBody ball_pose(const Driver& d);

}  // namespace polydem
