#pragma once
// A box's pose made where the pair walk reads it (issue 19): the step's pose pass leaves a box's
// PosedBody as it was, and the walk makes it, rotation and eight corners (pose_box), from the
// body's orientation, position and scale: the pass's arithmetic and bits. At scale the pose was
// written every step and read back after ~70 MB of other traffic: its 192 bytes of vertices a
// cube were ~6 of a cube-step's 34 last-level lines at 216,000 cubes, its 128 bytes ~2 of 17 at
// 54,000. Other shapes keep their stored poses, and a rebuild stores every listed body's (its
// candidate searches read them there).
#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/box_pose.hpp"

namespace polydem {

// The engine's shapes and each one's box corners (ContactEngine::boxes_), and the body arrays a
// box's pose is made from (pose_body's).
struct ShapeBoxes {
  const Shape* shapes = nullptr;
  const std::optional<BoxCorners>* boxes = nullptr;  // per shape
  const int* shape = nullptr;                        // per body, into `shapes`
  const double* scale = nullptr;                     // per body
  const Vec3* position = nullptr;                    // m, per body
  const Quat* orientation = nullptr;                 // per body
  bool all_boxes = false;                            // every body a box: is_box reads no array
  // ~0u, or 0 where every body has body 0's shape, scale and mass (alike_bodies): a made walk reads
  // body b's at b & body_mask, so equal cubes stream none of the three arrays (issue 19).
  std::uint32_t body_mask = ~0u;
  bool is_box(std::uint32_t b) const { return all_boxes || boxes[shape[b & body_mask]].has_value(); }
};

// Whether every body has body 0's shape, scale and mass (ShapeBoxes::body_mask 0); none: false.
inline bool alike_bodies(const std::vector<int>& shape, const std::vector<double>& scale,
                         const std::vector<double>& mass) {
  for (std::size_t b = 1; b < shape.size(); ++b)
    if (shape[b] != shape[0] || scale[b] != scale[0] || mass[b] != mass[0]) return false;
  return !shape.empty();
}

// A box's pose with its corners made.
struct MadeBox {
  PosedBody pose;  // its vertices: `vertices`
  std::array<Vec3, 8> vertices;  // m, world
};

// A thread's boxes made in one walk, kept by body (slot b mod kSlots): bodies in space order
// (cells z, y, x) meet their pairs within about two layers of cells of the pile (~450 bodies),
// so a cube's corners are made about once a walk, not once for each of its ~4.6 pair ends.
// Held inline: a walk's MadeWalk is made once (on the heap), and each lookup then loads no array's address.
struct MadeCorners {
  static constexpr std::uint32_t kSlots = 1024;  // 320 KB: a core's L2 (1 MB here), not the last level
  std::array<std::uint32_t, kSlots> body;       // per slot, whose pose it holds; ~0: none
  std::array<MadeBox, kSlots> made;
  MadeCorners() { body.fill(~0u); }
};

// The box pose a kernel reads of one side of the walked pair (PairScratch).
struct MadePose {
  std::uint32_t body = ~0u;  // whose pose `pose` is; ~0: none yet
  const PosedBody* pose = nullptr;
  MadeBox own;  // where the body's slot holds the other side's body
};

// Box b's pose and corners in `box`, as pose_body makes them (the same bits).
[[gnu::always_inline]] inline void make_box(std::uint32_t b, ShapeBoxes boxes, MadeBox& box) {
  const int shape = boxes.shape[b & boxes.body_mask];
  const Shape& s = boxes.shapes[shape];
  PosedBody& pose = box.pose;
  pose.scale = boxes.scale[b & boxes.body_mask];
  pose.position = boxes.position[b];
  pose.rotation = boxes.orientation[b].toRotationMatrix();
  pose.shape = &s;
  pose.vertices = box.vertices.data();
  pose.radius = s.radius * pose.scale;
  pose_box(*boxes.boxes[shape], pose.scale, pose.position, pose.rotation, box.vertices.data());
}

// with_vertices' slot lookup, and the make where b is not there (inline: out of line, +93
// instructions a cube-step at 54,000; the walk of stored vertices is another instance, no test).
[[gnu::always_inline]] inline const PosedBody& find_or_make(std::uint32_t b, ShapeBoxes boxes, MadeCorners& corners,
                                                       MadePose& made, const MadePose& other) {
  const std::uint32_t slot = b % MadeCorners::kSlots;
  made.body = b;
  if (corners.body[slot] != b) {
    const bool taken = other.body != ~0u && corners.body[slot] == other.body;
    MadeBox& box = taken ? made.own : corners.made[slot];
    if (!taken) corners.body[slot] = b;
    make_box(b, boxes, box);
    made.pose = &box.pose;
  } else {
    made.pose = &corners.made[slot].pose;
  }
  return *made.pose;
}

// A walk's made boxes: a made walk's scratch holds it from its first pair read (pair_forces_into);
// a sphere walk's scratch stays small (held inline, it cost the sphere bed's walk +0.45% instructions).
struct MadeWalk {
  MadeCorners corners;
  MadePose made_i, made_j;  // the walked pair's box poses with their corners
};
inline MadeWalk& made_walk(std::unique_ptr<MadeWalk>& walk) {
  if (!walk) walk.reset(new MadeWalk);  // default-initialised: make_unique would zero its 320 KB first
  return *walk;
}

// Body b's pose as the kernels read it: a box's made in `corners` (or found there), another
// shape's stored, posed[b]. The slot of `other` (the pair's other side, whose pose the kernels
// read beside) is never taken: b is then made in made.own (rare). A box's posed[b] is not read:
// the step's pose pass leaves it as the last rebuild posed it.
[[gnu::always_inline]] inline const PosedBody& with_vertices(const PosedBody* posed, std::uint32_t b, ShapeBoxes boxes,
                                                             MadeCorners& corners, MadePose& made,
                                                             const MadePose& other) {
  if (made.body == b) return *made.pose;
  if (!boxes.is_box(b)) return posed[b];
  return find_or_make(b, boxes, corners, made, other);
}

}  // namespace polydem
