// The box corners' pose against pose_vertices, bit for bit: the products shared by the corners
// must not change a vertex's round-off (the runs' bits).
#include <catch2/catch.hpp>

#include <cstring>

#include "geometry/box_pose.hpp"
#include "test_shapes.hpp"

using namespace polydem;
using namespace polydem::test;

TEST_CASE("a box's corners pose to the same bits as pose_vertices") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Shape cube = make_cube(0.0045, 0.0005), needle = make_needle(0.05);
  for (const Shape* s : {&cube, &needle}) {
    const std::optional<BoxCorners> box = box_corners(*s);
    REQUIRE(box);
    for (int trial = 0; trial < 20000; ++trial) {
      // Quarter turns and the origin too: exact zeros and cancelling columns keep their signs.
      const Quat q = trial % 4 == 0 ? Quat(Eigen::AngleAxisd(kPi / 4 * (trial % 8), Vec3::Unit(trial % 3)))
                                    : random_rotation(rng);
      const Vec3 position = trial % 3 == 0 ? Vec3::Zero() : Vec3(u(rng), u(rng), u(rng));  // m
      const double scale = 1.0 + 0.5 * u(rng);
      Vec3 expected[8], got[8];
      const Mat3 rotation = q.toRotationMatrix();
      pose_vertices(*s, scale, position, rotation, expected);
      pose_box(*box, scale, position, rotation, got);
      REQUIRE(std::memcmp(expected, got, sizeof got) == 0);
    }
  }
}

TEST_CASE("only boxes about their centre pose as boxes") {
  CHECK_FALSE(box_corners(make_octahedron(0.6, 0.05)));
  CHECK_FALSE(box_corners(make_tetrahedron(0.4, 0.05)));
  Shape shifted = make_cube(0.5, 0.05);
  shifted.vertices[3].x() += 1e-3;
  CHECK_FALSE(box_corners(shifted));
}
