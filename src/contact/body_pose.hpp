#pragma once
// A body's pose for the pair walk (PosedBody: its rotation, and its world vertices where stored),
// made by the contact engine's pose pass, or right behind the last step's walk (sim/trailing_pass).
#include <algorithm>
#include <cstdint>
#include <optional>

#include "geometry/box_pose.hpp"
#include "geometry/features.hpp"

namespace polydem {

namespace engine_detail {

// What a pose reads and writes, by address (ContactEngine::pose).
struct PoseArrays {
  const Vec3* position;  // m
  const Quat* orientation;
  const int* shape;
  const double* scale;
  const Shape* shapes;
  const std::optional<BoxCorners>* boxes;  // per shape
  const std::uint32_t* listed;
  const std::uint32_t* vertex_offset;
  Vec3* world_vertices;  // m
  PosedBody* posed;
  bool box_vertices;  // a box's too (a rebuild's readers); else a box's pose is left as it was, made where read (made_pose.hpp)
};

// Body b's rotation and world vertices, filled in place: no temporary pose to copy.
// A box's pose only where a.box_vertices: a step's walk makes it (with_vertices).
[[gnu::always_inline]] inline void pose_body(const PoseArrays& a, std::uint32_t b) {
  const std::optional<BoxCorners>& box = a.boxes[a.shape[b]];
  if (box && !a.box_vertices) return;
  const Shape& s = a.shapes[a.shape[b]];
  Vec3* v = a.world_vertices + a.vertex_offset[b];
  PosedBody& posed = a.posed[b];
  // Read once into locals: the vertices' stores may alias anything, so each read reloaded them.
  const Vec3 position = a.position[b];  // m
  const double scale = a.scale[b];
  posed.rotation = a.orientation[b].toRotationMatrix();  // once per body and step
  if (!box)
    pose_vertices(s, scale, position, posed.rotation, v);
  else
    pose_box(*box, scale, position, posed.rotation, v);  // the same bits in a third of the arithmetic
  posed.shape = &s;
  posed.vertices = v;
  posed.position = position;
  posed.radius = s.radius * scale;
  posed.scale = scale;
}

}  // namespace engine_detail

// The listed bodies' poses (ContactEngine::listed_poses), made for the next step right behind the
// walk (TrailingPass), each body's by pose_body as the step's pose pass makes it (the same bits).
struct ListedPoses {
  engine_detail::PoseArrays arrays;  // `listed`: the bodies of some pair, increasing
  std::uint32_t count = 0;           // of arrays.listed
  // The listed bodies of [first, last).
  void pose(std::uint32_t first, std::uint32_t last) const {
    const engine_detail::PoseArrays a = arrays;
    std::uint32_t e = std::uint32_t(std::lower_bound(a.listed, a.listed + count, first) - a.listed);
    for (; e < count && a.listed[e] < last; ++e) engine_detail::pose_body(a, a.listed[e]);
  }
};

}  // namespace polydem
