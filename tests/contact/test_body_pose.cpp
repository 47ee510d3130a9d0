// The pose behind the walk (ListedPoses, repose_body) against the pose pass's (pose_body), bit for
// bit: it makes a listed body's rotation, world vertices and centre again and keeps the rest of
// its pose (shape, vertices' address, radius, scale) from the rebuild that posed it whole.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "contact/body_pose.hpp"
#include "../geometry/test_shapes.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// Two shapes, body b of shape b % 2, at random poses; `posed` and `vertices` are the arrays a pose
// fills. Boxes only, or a box and an octahedron (pose_box's and pose_vertices' paths).
struct PoseSet {
  std::vector<Shape> shapes;
  std::vector<std::optional<BoxCorners>> boxes;
  std::vector<int> shape;
  std::vector<double> scale;
  std::vector<Vec3> position;  // m
  std::vector<Quat> orientation;
  std::vector<std::uint32_t> listed, vertex_offset{0};
  std::vector<Vec3> vertices;  // m
  std::vector<PosedBody> posed;
  std::mt19937_64 rng{11};

  PoseSet(std::uint32_t n, bool boxes_only)
      : shapes{make_cube(0.5, 0.05), boxes_only ? make_plate(0.05) : make_octahedron(0.6, 0.05)},
        boxes{box_corners(shapes[0]), box_corners(shapes[1])},
        posed(n) {
    for (std::uint32_t b = 0; b < n; ++b) {
      shape.push_back(int(b % 2));
      scale.push_back(1.0 + 0.25 * b);
      listed.push_back(b);
      vertex_offset.push_back(vertex_offset.back() + std::uint32_t(shapes[b % 2].vertices.size()));
    }
    vertices.resize(vertex_offset.back());
    move();
  }
  void move() {  // new random positions and orientations
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    position.clear(), orientation.clear();
    for (std::size_t b = 0; b < shape.size(); ++b)
      position.emplace_back(u(rng), u(rng), u(rng)), orientation.push_back(random_rotation(rng));
  }
  engine_detail::PoseArrays arrays() {
    return {position.data(),      orientation.data(), shape.data(), scale.data(), shapes.data(), boxes.data(),
            listed.data(), vertex_offset.data(), vertices.data(), posed.data(), true};
  }
};

// Poses [1, 5) of six bodies behind the walk after a rebuild's whole pose and a move.
void check_pose_behind(bool boxes_only) {
  PoseSet set(6, boxes_only);
  REQUIRE(set.boxes[1].has_value() == boxes_only);
  const ListedPoses listed{set.arrays(), std::uint32_t(set.listed.size()), boxes_only};
  for (std::uint32_t b = 0; b < 6; ++b) engine_detail::pose_body(set.arrays(), b);  // the rebuild's whole pose
  const std::vector<PosedBody> rebuilt = set.posed;
  set.move();
  // What a body's pose keeps until the next rebuild, marked: a pose behind the walk leaves it.
  for (PosedBody& p : set.posed) p.radius = -1.0;
  listed.pose(1, 5);
  const std::vector<Vec3> behind = set.vertices;
  const std::vector<PosedBody> posed_behind = set.posed;
  for (std::uint32_t b = 0; b < 6; ++b) engine_detail::pose_body(set.arrays(), b);  // the pose pass's
  for (std::uint32_t b = 0; b < 6; ++b) {
    INFO("body " << b);
    const PosedBody &p = posed_behind[b], &q = set.posed[b];
    const std::size_t nv = set.vertex_offset[b + 1] - set.vertex_offset[b];
    const bool same_vertices =
        std::memcmp(&behind[set.vertex_offset[b]], &set.vertices[set.vertex_offset[b]], nv * sizeof(Vec3)) == 0;
    if (b < 1 || b >= 5) {  // outside [1, 5): untouched
      CHECK(p.position == rebuilt[b].position);
      CHECK_FALSE(same_vertices);
      continue;
    }
    CHECK(same_vertices);
    CHECK(std::memcmp(&p.rotation, &q.rotation, sizeof(Mat3)) == 0);
    CHECK(std::memcmp(&p.position, &q.position, sizeof(Vec3)) == 0);
    CHECK(p.radius == -1.0);  // kept, not made again
    CHECK(p.shape == rebuilt[b].shape);
    CHECK(p.vertices == rebuilt[b].vertices);
    CHECK(p.scale == rebuilt[b].scale);
  }
}

}  // namespace

TEST_CASE("a listed body posed again behind the walk equals the pose pass's, and keeps its rebuild's pose") {
  check_pose_behind(false);
}

TEST_CASE("every body a box: the pose behind the walk asks no shape and keeps the same bits") {
  check_pose_behind(true);
}
