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

// What moves with body b (its rotation, world vertices v and centre), made in place: no temporary
// pose to copy. `box`: its shape's corners where it is a box (the same bits in a third of the
// arithmetic), else null; `scale` b's. The caller reads v and scale: the vertices' stores may
// alias anything, so a read after them is a reload.
[[gnu::always_inline]] inline void pose_motion(const PoseArrays& a, std::uint32_t b, const Shape& s,
                                               const BoxCorners* box, double scale, Vec3* v, PosedBody& posed) {
  const Vec3 position = a.position[b];  // m, read once into locals as v and scale
  posed.rotation = a.orientation[b].toRotationMatrix();  // once per body and step
  if (!box)
    pose_vertices(s, scale, position, posed.rotation, v);
  else
    pose_box(*box, scale, position, posed.rotation, v);
  posed.position = position;
}

// Body b's rotation and world vertices, filled in place, and what stays until the next rebuild:
// its shape, vertices' address, radius and scale. A box's pose only where a.box_vertices: a step's
// walk makes it (with_vertices).
[[gnu::always_inline]] inline void pose_body(const PoseArrays& a, std::uint32_t b) {
  const std::optional<BoxCorners>& box = a.boxes[a.shape[b]];
  if (box && !a.box_vertices) return;
  const Shape& s = a.shapes[a.shape[b]];
  Vec3* v = a.world_vertices + a.vertex_offset[b];
  PosedBody& posed = a.posed[b];
  const double scale = a.scale[b];
  pose_motion(a, b, s, box ? &*box : nullptr, scale, v, posed);
  posed.shape = &s;
  posed.vertices = v;
  posed.radius = s.radius * scale;
  posed.scale = scale;
}

// pose_body of a body whose whole pose a rebuild has made since the lists were built (every
// listed body's: the rebuild poses its newcomers whole): only what moved is made again (~12
// instructions a cube-step fewer behind the walk).
[[gnu::always_inline]] inline void repose_body(const PoseArrays& a, std::uint32_t b) {
  const std::optional<BoxCorners>& box = a.boxes[a.shape[b]];
  if (box && !a.box_vertices) return;
  pose_motion(a, b, a.shapes[a.shape[b]], box ? &*box : nullptr, a.scale[b], a.world_vertices + a.vertex_offset[b],
              a.posed[b]);
}

}  // namespace engine_detail

// The listed bodies' poses (ContactEngine::listed_poses), made for the next step right behind the
// walk (TrailingPass), each body's by repose_body: its rotation, vertices and centre as the step's pose
// pass makes them (the same bits), the rest kept from the rebuild that listed it.
struct ListedPoses {
  engine_detail::PoseArrays arrays;  // `listed`: the bodies of some pair, increasing
  std::uint32_t count = 0;           // of arrays.listed
  bool boxes_only = false;           // every body a box: no body's shape is asked whether it is one
  // The listed bodies of [first, last).
  void pose(std::uint32_t first, std::uint32_t last) const {
    const engine_detail::PoseArrays a = arrays;
    std::uint32_t e = std::uint32_t(std::lower_bound(a.listed, a.listed + count, first) - a.listed);
    if (!boxes_only) {
      for (; e < count && a.listed[e] < last; ++e) engine_detail::repose_body(a, a.listed[e]);
      return;
    }
    if (!a.box_vertices) return;  // a made walk makes every box's pose
    for (; e < count && a.listed[e] < last; ++e) {  // repose_body's, ~6 instructions a cube-step fewer
      const std::uint32_t b = a.listed[e];
      engine_detail::pose_motion(a, b, a.shapes[a.shape[b]], &*a.boxes[a.shape[b]], a.scale[b],
                                 a.world_vertices + a.vertex_offset[b], a.posed[b]);
    }
  }
};

}  // namespace polydem
