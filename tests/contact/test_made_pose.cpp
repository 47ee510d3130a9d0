// A box's pose and world vertices made where the walk reads them (made_pose.hpp) against the pose
// pass's stored ones, bit for bit: the runs' bits rest on it. Bodies whose slots collide must each
// keep their own corners while the kernels read the pair; a box's stale stored pose is never read.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <vector>

#include "contact/made_pose.hpp"
#include "../geometry/test_shapes.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

// Bodies of one shape at random poses: each one's pose with its vertices stored (as a rebuild
// poses it: pose_vertices), the body arrays a made box's pose is made from, and stale poses (as
// a step's pose pass leaves a box's: the last rebuild's, here another body's), which no made box reads.
struct PosedSet {
  std::vector<Shape> shapes;
  std::vector<std::optional<BoxCorners>> boxes;
  std::vector<Vec3> stored;  // m, 8 a body
  std::vector<PosedBody> with, stale;
  std::vector<int> shape;
  std::vector<double> scale;
  std::vector<Vec3> position;  // m
  std::vector<Quat> orientation;

  PosedSet(const Shape& s, std::size_t n) : shapes{s}, boxes{box_corners(s)}, shape(n, 0) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::size_t nv = s.vertices.size();
    stored.resize(n * nv);
    for (std::size_t b = 0; b < n; ++b) {
      orientation.push_back(random_rotation(rng));
      position.emplace_back(u(rng), u(rng), u(rng));
      scale.push_back(1.0 + 0.5 * u(rng));
      const Mat3 rotation = orientation[b].toRotationMatrix();
      pose_vertices(shapes[0], scale[b], position[b], rotation, &stored[b * nv]);
      with.push_back(PosedBody{&shapes[0], &stored[b * nv], rotation, position[b], shapes[0].radius * scale[b], scale[b]});
    }
    for (std::size_t b = 0; b < n; ++b) stale.push_back(with[(b + 1) % n]);
  }
  ShapeBoxes view() const {
    return {shapes.data(), boxes.data(), shape.data(), scale.data(), position.data(), orientation.data(), false};
  }
  bool same(const PosedBody& made, std::size_t b) const {  // the stored pose, bit for bit
    return std::memcmp(made.vertices, with[b].vertices, shapes[0].vertices.size() * sizeof(Vec3)) == 0 &&
           made.rotation == with[b].rotation && made.position == with[b].position && made.radius == with[b].radius &&
           made.scale == with[b].scale && made.shape == with[b].shape;
  }
};

}  // namespace

TEST_CASE("a box's pose made where read equals the stored pose, bit for bit, whatever its stale pose") {
  const PosedSet cubes(make_cube(0.0045, 0.0005), 2 * MadeCorners::kSlots + 3);
  MadeCorners corners;
  MadePose a, b;
  // A walk's pairs: runs of one first body, partners near and far, and bodies a slot apart.
  const std::uint32_t kSlots = MadeCorners::kSlots;
  const std::uint32_t pairs[][2] = {{0, 1}, {0, 5}, {0, kSlots}, {1, 5}, {1, kSlots + 1}, {kSlots + 1, 1},
                                    {2, 2 * kSlots + 2}, {2 * kSlots + 2, kSlots + 2}, {5, 0}, {kSlots, 0}};
  for (const auto& p : pairs) {
    const PosedBody& pa = with_vertices(cubes.stale.data(), p[0], cubes.view(), corners, a, b);
    const PosedBody& pb = with_vertices(cubes.stale.data(), p[1], cubes.view(), corners, b, a);
    INFO("pair " << p[0] << ", " << p[1]);
    CHECK(cubes.same(pa, p[0]));  // still its own once its partner's is made
    CHECK(cubes.same(pb, p[1]));
  }
}

TEST_CASE("a general polyhedron's stored pose is read where it is, every box made") {
  const PosedSet rocks(make_octahedron(0.6, 0.05), 4), cubes(make_cube(0.5, 0.05), 4);
  MadeCorners corners;
  MadePose a, b;
  CHECK(&with_vertices(rocks.with.data(), 2, rocks.view(), corners, a, b) == &rocks.with[2]);
  CHECK(std::count(corners.body.begin(), corners.body.end(), ~0u) == MadeCorners::kSlots);  // nothing made
  ShapeBoxes all = cubes.view();
  all.all_boxes = true;
  const PosedBody& made = with_vertices(cubes.with.data(), 3, all, corners, a, b);  // a rebuild's stored pose
  CHECK(&made != &cubes.with[3]);
  CHECK(cubes.same(made, 3));
}

TEST_CASE("alike bodies: one shape, scale and mass for all, and a made box then reads body 0's") {
  const std::vector<int> shape(5, 0);
  const std::vector<double> scale(5, 1.5), mass(5, 2.7e-3);  // -, kg
  CHECK(alike_bodies(shape, scale, mass));
  CHECK_FALSE(alike_bodies({}, {}, {}));
  std::vector<int> other_shape = shape;
  other_shape[4] = 1;
  std::vector<double> other_scale = scale, other_mass = mass;
  other_scale[3] = 1.25;
  other_mass[2] = 2.8e-3;  // kg
  CHECK_FALSE(alike_bodies(other_shape, scale, mass));
  CHECK_FALSE(alike_bodies(shape, other_scale, mass));
  CHECK_FALSE(alike_bodies(shape, scale, other_mass));

  // body_mask 0: body b's box is made with body 0's shape and scale, its own orientation and position.
  PosedSet alike(make_cube(0.0045, 0.0005), 6);
  const std::size_t nv = alike.shapes[0].vertices.size();
  for (std::size_t b = 0; b < alike.with.size(); ++b) {  // stored again at body 0's scale
    alike.scale[b] = alike.scale[0];
    pose_vertices(alike.shapes[0], alike.scale[b], alike.position[b], alike.with[b].rotation, &alike.stored[b * nv]);
    alike.with[b].radius = alike.shapes[0].radius * alike.scale[b];
    alike.with[b].scale = alike.scale[b];
  }
  ShapeBoxes masked = alike.view();
  masked.body_mask = 0;
  const std::vector<int> one_shape{0};
  const std::vector<double> one_scale{alike.scale[0]};
  masked.shape = one_shape.data();  // body 0's alone: a read of another body's would leave the arrays
  masked.scale = one_scale.data();
  MadeCorners corners;
  MadePose a, b;
  for (std::uint32_t k = 0; k < alike.with.size(); ++k) {
    INFO("body " << k);
    CHECK(masked.is_box(k));
    CHECK(alike.same(with_vertices(alike.stale.data(), k, masked, corners, a, b), k));
  }
}
