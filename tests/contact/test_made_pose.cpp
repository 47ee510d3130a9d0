// A box's world vertices made where the walk reads them (made_pose.hpp) against the pose pass's
// stored ones, bit for bit: the runs' bits rest on it. Bodies whose slots collide must each
// keep their own corners while the kernels read the pair.
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
// poses it: pose_vertices) and the same pose with none (as a step's pose pass leaves a box's).
struct PosedSet {
  std::vector<Shape> shapes;
  std::vector<std::optional<BoxCorners>> boxes;
  std::vector<Vec3> stored;  // m, 8 a body
  std::vector<PosedBody> with, without;

  PosedSet(const Shape& shape, std::size_t n) : shapes{shape}, boxes{box_corners(shape)} {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::size_t nv = shape.vertices.size();
    stored.resize(n * nv);
    for (std::size_t b = 0; b < n; ++b) {
      const Mat3 rotation = random_rotation(rng).toRotationMatrix();
      const Vec3 position(u(rng), u(rng), u(rng));  // m
      const double scale = 1.0 + 0.5 * u(rng);
      pose_vertices(shapes[0], scale, position, rotation, &stored[b * nv]);
      with.push_back(PosedBody{&shapes[0], &stored[b * nv], rotation, position, shapes[0].radius * scale, scale});
      without.push_back(with.back());
      without.back().vertices = nullptr;
    }
  }
  ShapeBoxes view() const { return {shapes.data(), boxes.data()}; }
  bool same(const PosedBody& made, std::size_t b) const {  // the stored vertices, bit for bit
    return std::memcmp(made.vertices, with[b].vertices, shapes[0].vertices.size() * sizeof(Vec3)) == 0;
  }
};

}  // namespace

TEST_CASE("a box's corners made where read equal the stored pose's, bit for bit") {
  const PosedSet cubes(make_cube(0.0045, 0.0005), 2 * MadeCorners::kSlots + 3);
  MadeCorners corners;
  MadePose a, b;
  // A walk's pairs: runs of one first body, partners near and far, and bodies a slot apart.
  const std::uint32_t kSlots = MadeCorners::kSlots;
  const std::uint32_t pairs[][2] = {{0, 1}, {0, 5}, {0, kSlots}, {1, 5}, {1, kSlots + 1}, {kSlots + 1, 1},
                                    {2, 2 * kSlots + 2}, {2 * kSlots + 2, kSlots + 2}, {5, 0}, {kSlots, 0}};
  for (const auto& p : pairs) {
    const PosedBody& pa = with_vertices(cubes.without[p[0]], p[0], cubes.view(), corners, a, b);
    const PosedBody& pb = with_vertices(cubes.without[p[1]], p[1], cubes.view(), corners, b, a);
    INFO("pair " << p[0] << ", " << p[1]);
    CHECK(cubes.same(pa, p[0]));  // still its own once its partner's corners are made
    CHECK(cubes.same(pb, p[1]));
    CHECK(pa.rotation == cubes.with[p[0]].rotation);
    CHECK(pb.position == cubes.with[p[1]].position);
  }
}

TEST_CASE("stored vertices are read where they are: a general polyhedron's, a rebuild's box") {
  const PosedSet rocks(make_octahedron(0.6, 0.05), 4), cubes(make_cube(0.5, 0.05), 4);
  MadeCorners corners;
  MadePose a, b;
  CHECK(&with_vertices(rocks.with[2], 2, rocks.view(), corners, a, b) == &rocks.with[2]);
  CHECK(&with_vertices(cubes.with[3], 3, cubes.view(), corners, a, b) == &cubes.with[3]);
  CHECK(std::count(corners.body.begin(), corners.body.end(), ~0u) == MadeCorners::kSlots);  // nothing made
}
