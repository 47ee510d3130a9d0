// Walls and infinite cylinders cut to the view frame: closed-form corners of known boxes.
#include <catch2/catch.hpp>

#include "output/frame.hpp"

using namespace polydem;

namespace {

// The five walls of an open box [-a, a]^2 x [0, ...), inner sides towards the particles.
ViewFrame open_box(double a, const Box3& box) {
  return {box, {{{0, 0, 0}, {0, 0, 1}}, {{-a, 0, 0}, {1, 0, 0}}, {{a, 0, 0}, {-1, 0, 0}},
                {{0, -a, 0}, {0, 1, 0}}, {{0, a, 0}, {0, -1, 0}}}};
}

bool has_corner(const std::vector<Vec3>& polygon, const Vec3& p, double tolerance) {
  for (const Vec3& q : polygon)
    if ((q - p).norm() <= tolerance) return true;
  return false;
}

}  // namespace

TEST_CASE("frame: the walls of an open box are its faces, meeting at its edges", "[output][frame]") {
  const double a = 0.1, top = 0.63;
  const Box3 box{{-0.13, -0.12, -0.03}, {0.11, 0.14, top}};  // wider than the walls, unevenly
  const ViewFrame frame = open_box(a, box);
  const std::vector<Vec3> floor = framed_plane(frame.walls[0].point, frame.walls[0].normal, frame);
  REQUIRE(floor.size() == 4);
  for (const Vec3& c : {Vec3(-a, -a, 0), Vec3(a, -a, 0), Vec3(a, a, 0), Vec3(-a, a, 0)})
    CHECK(has_corner(floor, c, 1e-15));
  const std::vector<Vec3> left = framed_plane(frame.walls[1].point, frame.walls[1].normal, frame);
  REQUIRE(left.size() == 4);
  for (const Vec3& c : {Vec3(-a, -a, 0), Vec3(-a, a, 0), Vec3(-a, a, top), Vec3(-a, -a, top)})
    CHECK(has_corner(left, c, 1e-15));
  // Counter-clockwise about the normal: the polygon's area vector points along it.
  Vec3 area = Vec3::Zero();
  for (std::size_t k = 0; k < floor.size(); ++k) area += floor[k].cross(floor[(k + 1) % floor.size()]);
  CHECK(area.normalized().isApprox(Vec3::UnitZ(), 1e-15));
  CHECK(0.5 * area.norm() == Approx(4 * a * a).epsilon(1e-14));
}

TEST_CASE("frame: two inclined walls of a V meet on their common line", "[output][frame]") {
  const double s = std::sqrt(0.5);
  const ViewFrame frame{{{-1, -1, -1}, {1, 1, 1}}, {{{0.2, 0, 0}, {-s, 0, s}}, {{-0.2, 0, 0}, {s, 0, s}}}};
  const auto a = framed_plane(frame.walls[0].point, frame.walls[0].normal, frame);
  const auto b = framed_plane(frame.walls[1].point, frame.walls[1].normal, frame);
  // The planes z = x - 0.2 and z = -x - 0.2 meet on x = 0, z = -0.2, from y = -1 to 1.
  for (const Vec3& c : {Vec3(0, -1, -0.2), Vec3(0, 1, -0.2)}) {
    CHECK(has_corner(a, c, 1e-15));
    CHECK(has_corner(b, c, 1e-15));
  }
  for (const Vec3& p : a) CHECK(std::abs((p - frame.walls[0].point).dot(frame.walls[0].normal)) < 1e-15);
  for (const Vec3& p : a) CHECK((p - frame.walls[1].point).dot(frame.walls[1].normal) > -1e-15);
}

TEST_CASE("frame: a plane outside the frame falls back to a square, and size draws a square", "[output][frame]") {
  const ViewFrame frame{{{-1, -1, -1}, {1, 1, 1}}, {}};
  CHECK(framed_plane({0, 0, 2}, {0, 0, 1}, frame).empty());
  const auto fallback = framed_wall({0, 0, 2}, {0, 0, 1}, std::nullopt, frame);
  REQUIRE(fallback.size() == 4);
  CHECK((fallback[0] - fallback[2]).norm() == Approx(2.0 * std::sqrt(2.0)));
  const auto square = framed_wall({0.5, 0, 0}, {0, 0, 1}, 0.3, frame);
  REQUIRE(square.size() == 4);
  for (const Vec3& c : {Vec3(0.35, -0.15, 0), Vec3(0.65, 0.15, 0)}) CHECK(has_corner(square, c, 1e-15));
}

TEST_CASE("frame: an infinite cylinder's axis is cut by the box and the walls", "[output][frame]") {
  const ViewFrame frame{{{-1, -2, -3}, {1, 2, 3}}, {{{0, 0, -0.5}, {0, 0, 1}}}};
  const auto span = framed_axis({0, 0, 1}, {0, 0, 1}, std::nullopt, frame);
  CHECK(span.first == Approx(-1.5));  // the floor at z = -0.5
  CHECK(span.second == Approx(2.0));  // the box top at z = 3
  const auto finite = framed_axis({0, 0, 1}, {0, 0, 1}, 0.4, frame);
  CHECK(finite.first == -0.2);
  CHECK(finite.second == 0.2);
  CHECK_FALSE(framed_line({5, 0, 0}, {0, 0, 1}, frame));
}
