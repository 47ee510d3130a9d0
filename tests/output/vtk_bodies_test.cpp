// bodies .vtu read back by VTK's own reader: topology, posed points, cell fields, rounded shapes.
#include <cmath>

#include "output/vtk.hpp"
#include "output_test_util.hpp"
#include "scene_fixture.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

Vec3 point_of(const Json& data, std::size_t k) {
  const Json& p = data["points"][k];
  return {p[0].number, p[1].number, p[2].number};
}

Vec3 vec_of(const Json& values, std::size_t k) {
  return {values[3 * k].number, values[3 * k + 1].number, values[3 * k + 2].number};
}

// Volume enclosed by cells [first, last) by the divergence theorem, fan-triangulated about the
// polygon's first point, with `origin` as apex: independent of origin only for a closed surface.
double enclosed_volume(const Json& data, std::size_t first, std::size_t last, const Vec3& origin) {
  double volume = 0.0;
  for (std::size_t c = first; c < last; ++c) {
    const Json& cell = data["cells"][c];
    const Vec3 a = point_of(data, std::size_t(cell[0].number)) - origin;
    for (std::size_t k = 1; k + 1 < cell.size(); ++k) {
      const Vec3 b = point_of(data, std::size_t(cell[k].number)) - origin;
      const Vec3 d = point_of(data, std::size_t(cell[k + 1].number)) - origin;
      volume += a.dot(b.cross(d)) / 6.0;
    }
  }
  return volume;
}

// Smallest distance from `centre` to the planes of cells [first, last): the inscribed ball.
double inscribed_radius(const Json& data, std::size_t first, std::size_t last, const Vec3& centre) {
  double r = INFINITY;
  for (std::size_t c = first; c < last; ++c) {
    const Json& cell = data["cells"][c];
    const Vec3 a = point_of(data, std::size_t(cell[0].number));
    const Vec3 n = (point_of(data, std::size_t(cell[1].number)) - a)
                       .cross(point_of(data, std::size_t(cell[2].number)) - a)
                       .normalized();
    r = std::min(r, std::abs((a - centre).dot(n)));
  }
  return r;
}

struct Scene {
  std::vector<Shape> shapes{cube_shape(0.01, 0.001), sphere_shape(0.005), capsule_shape(0.01, 0.002)};
  Bodies bodies;
  Scene() {
    add_body(bodies, 0, {0.1, 0.2, 0.3}, axis_angle({1, 2, 3}, 0.7), 1.5, {1, -2, 3}, {0.5, 0.25, -4}, 7);
    add_body(bodies, 0, {-1, 0, 2}, Quat::Identity(), 1.0, {0, 0, -9.5}, {0, 0, 0}, 8);
    add_body(bodies, 1, {0.5, 0.5, 0.5}, Quat::Identity(), 2.0, {0.125, 0, 0}, {3, 0, 0}, 9);
    add_body(bodies, 2, {0, 1, 0}, axis_angle({0, 1, 1}, 1.1), 0.5, {0, 0, 0}, {0, 0, 1e-3}, 10);
  }
};

constexpr std::size_t kIcoFaces = 80, kIcoPoints = 42;  // icosahedron subdivided once: 20 x 4, 12 + 30

}  // namespace

TEST_CASE("bodies vtu: VTK reads one polygon per face at the posed vertices", "[output][vtk]") {
  const Scene s;
  const TempDir tmp("bodies");
  const std::string path = tmp.path + "/bodies_000000.vtu";
  write_bodies_vtu(path, s.bodies, s.shapes);
  const Json data = read_with_vtk(path);

  CHECK(data["n_cells"].number == 6 + 6 + kIcoFaces + kIcoFaces);
  CHECK(data["n_points"].number == 8 + 8 + kIcoPoints + kIcoPoints);
  for (std::size_t c = 0; c < data["cell_types"].size(); ++c) CHECK(data["cell_types"][c].number == 7);  // VTK_POLYGON

  // x = position + R (scale v): the first 16 points are the two cubes' vertices in shape order.
  for (std::size_t b = 0; b < 2; ++b)
    for (std::size_t k = 0; k < 8; ++k) {
      const Vec3 local = s.bodies.scale[b] * s.shapes[0].vertices[k];
      const Vec3 expected = s.bodies.position[b] + s.bodies.orientation[b] * local;
      CHECK((point_of(data, 8 * b + k) - expected).norm() < 1e-12);
    }
  // Faces keep the shape's vertex order, offset by the body's first point.
  for (std::size_t f = 0; f < 6; ++f)
    for (std::size_t k = 0; k < 4; ++k) CHECK(data["cells"][6 + f][k].number == 8 + s.shapes[0].faces[f][k]);
}

TEST_CASE("bodies vtu: per-cell id, group, radius, velocities repeat each body's values", "[output][vtk]") {
  const Scene s;
  const TempDir tmp("body_fields");
  const std::string path = tmp.path + "/bodies.vtu";
  write_bodies_vtu(path, s.bodies, s.shapes);
  const Json cd = read_with_vtk(path)["cell_data"];
  CHECK(cd["id"]["type"].text == "long long");
  CHECK(cd["group"]["type"].text == "int");
  CHECK(cd["velocity"]["components"].number == 3);
  const std::size_t cells_of[] = {6, 6, kIcoFaces, kIcoFaces};
  std::size_t c = 0;
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    for (std::size_t k = 0; k < cells_of[b]; ++k, ++c) {
      CHECK(cd["id"]["values"][c].number == double(b));
      CHECK(cd["group"]["values"][c].number == s.bodies.group[b]);
      CHECK(cd["radius"]["values"][c].number == s.shapes[s.bodies.shape[b]].radius * s.bodies.scale[b]);
      CHECK(vec_of(cd["velocity"]["values"], c) == s.bodies.velocity[b]);
      CHECK(vec_of(cd["angular_velocity"]["values"], c) == s.bodies.angular_velocity[b]);
    }
  CHECK(c == cd["id"]["values"].size());
}

TEST_CASE("bodies vtu: closed surfaces, outward faces, cube volume exact", "[output][vtk]") {
  const Scene s;
  const TempDir tmp("volume");
  const std::string path = tmp.path + "/bodies.vtu";
  write_bodies_vtu(path, s.bodies, s.shapes);
  const Json data = read_with_vtk(path);
  const std::size_t first[] = {0, 6, 12, 12 + kIcoFaces, 12 + 2 * kIcoFaces};
  for (std::size_t b = 0; b < 4; ++b) {
    const double v0 = enclosed_volume(data, first[b], first[b + 1], s.bodies.position[b]);
    const double v1 = enclosed_volume(data, first[b], first[b + 1], Vec3(3, -2, 5));
    CHECK(v0 > 0);                                // faces counter-clockwise seen from outside
    CHECK(std::abs(v1 - v0) < 1e-12 * (1 + v0));  // no hole: the volume ignores the apex
  }
  // Cube: (2 h scale)^3.
  CHECK(enclosed_volume(data, 0, 6, Vec3::Zero()) == Approx(std::pow(2 * 0.01 * 1.5, 3)).epsilon(1e-12));
  // Capsule inscribed in the rounded segment: below pi R^2 L + 4/3 pi R^3, R = 0.002 x 0.5, L = 0.02 x 0.5.
  const double r = 0.001, length = 0.01;
  CHECK(enclosed_volume(data, first[3], first[4], Vec3::Zero()) < kPi * r * r * length + 4.0 / 3.0 * kPi * r * r * r);
  // Every capsule point lies on the rounded segment's surface.
  const Vec3 axis = s.bodies.orientation[3] * Vec3(0, 0, 0.5 * length);
  for (std::size_t k = 16 + kIcoPoints; k < 16 + 2 * kIcoPoints; ++k) {
    const Vec3 p = point_of(data, k) - s.bodies.position[3];
    const double t = std::clamp(p.dot(axis) / axis.squaredNorm(), -1.0, 1.0);
    CHECK(std::abs((p - t * axis).norm() - r) < 1e-12);
  }
}

TEST_CASE("bodies vtu: a sphere's bounds are its centre +- rounded radius", "[output][vtk]") {
  const std::vector<Shape> shapes{sphere_shape(0.005)};
  const double r = 0.005 * 2.0;
  const Vec3 centre(0.5, -0.25, 2.0);
  const Quat rotation = GENERATE(Quat::Identity(), axis_angle({1, -2, 0.5}, 0.9));
  Bodies bodies;
  add_body(bodies, 0, centre, rotation, 2.0, Vec3::Zero(), Vec3::Zero(), 0);
  const TempDir tmp("sphere");
  const std::string path = tmp.path + "/sphere.vtu";
  write_bodies_vtu(path, bodies, shapes);
  const Json data = read_with_vtk(path);
  // Vertices lie on the sphere, so the mesh holds the ball of its smallest face distance:
  // every half-width of the bounds lies in [inscribed, r]; unrotated, the +-axis vertices make it r.
  const double inscribed = inscribed_radius(data, 0, kIcoFaces, centre);
  CHECK(inscribed > 0.9 * r);
  const bool unrotated = rotation.isApprox(Quat::Identity(), 0.0);
  for (int a = 0; a < 3; ++a) {
    const double lo = centre[a] - data["bounds"][2 * a].number, hi = data["bounds"][2 * a + 1].number - centre[a];
    for (double half : {lo, hi}) {
      CHECK(half <= r + 1e-12);
      CHECK(half >= inscribed - 1e-12);
      if (unrotated) CHECK(half == Approx(r).epsilon(1e-12));
    }
  }
}

TEST_CASE("bodies vtu: an empty body list is a valid file", "[output][vtk]") {
  const TempDir tmp("empty_bodies");
  const std::string path = tmp.path + "/bodies.vtu";
  write_bodies_vtu(path, Bodies{}, {});
  const Json data = read_with_vtk(path);
  CHECK(data["n_points"].number == 0);
  CHECK(data["n_cells"].number == 0);
}

TEST_CASE("bodies vtu: a cross is drawn as its swept shape, a sphere per tip and a tube per arm", "[output][vtk]") {
  Shape cross;
  cross.name = "alpha3";
  cross.radius = 0.002;
  const double a = 0.005;
  cross.vertices = {{a, 0, 0}, {-a, 0, 0}, {0, a, 0}, {0, -a, 0}, {0, 0, a}, {0, 0, -a}};
  cross.edges = {{0, 1}, {2, 3}, {4, 5}};
  cross.convex = false;
  Bodies bodies;
  const Vec3 centre(0.1, 0.2, 0.3);
  const Quat q = axis_angle({1, 2, 3}, 0.7);
  add_body(bodies, 0, centre, q, 1.5, Vec3::Zero(), Vec3::Zero(), 0);
  const TempDir tmp("cross");
  const std::string path = tmp.path + "/cross.vtu";
  write_bodies_vtu(path, bodies, {cross});
  const Json data = read_with_vtk(path);
  CHECK(data["n_cells"].number == 6 * kIcoFaces + 3 * 16);
  // Every point lies on a tip's sphere or an arm's tube: at distance r (scaled) from a tip, or
  // from an arm (a segment through the centre) at a foot inside it. Not the hull of the tips.
  const double r = 0.002;
  for (std::size_t k = 0; k < std::size_t(data["n_points"].number); ++k) {
    const Vec3 p = q.conjugate() * (point_of(data, k) - centre) / 1.5;  // in the shape frame, unscaled
    double off = INFINITY;  // m, smallest | distance to an element - r |
    for (const Vec3& v : cross.vertices) off = std::min(off, std::abs((p - v).norm() - r));
    for (int axis = 0; axis < 3; ++axis)
      if (std::abs(p[axis]) <= a) {
        Vec3 foot = Vec3::Zero();
        foot[axis] = p[axis];
        off = std::min(off, std::abs((p - foot).norm() - r));
      }
    CHECK(off < 1e-12);
  }
}

TEST_CASE("vtu: rounded output draws a cube's swept surface, every point at its rounding from the core",
          "[output][vtk]") {
  const double h = 0.01, r = 0.001, scale = 1.5;  // m, half side and rounding; homothety
  const std::vector<Shape> shapes{cube_shape(h, r)};
  Bodies bodies;
  const Quat q = axis_angle({1, 2, 3}, 0.7);
  const Vec3 x(0.1, 0.2, 0.3);
  add_body(bodies, 0, x, q, scale, Vec3::Zero(), Vec3::Zero(), 0);
  const TempDir tmp("vtu_rounded");
  write_bodies_vtu(tmp.path + "/rounded.vtu", bodies, shapes, true);
  const Json data = read_with_vtk(tmp.path + "/rounded.vtu");
  REQUIRE(data["n_points"].number == 42);  // the icosphere's directions, one surface point each
  double far = 0.0;  // m, the largest point distance along a body axis: the rounded half side
  for (std::size_t k = 0; k < data["points"].size(); ++k) {
    const Vec3 local = q.conjugate() * (point_of(data, k) - x) / scale;  // body frame, scale 1
    const Vec3 outside = (local.cwiseAbs() - Vec3::Constant(h)).cwiseMax(0.0);  // m, beyond the core cube
    CHECK(outside.norm() == Approx(r).epsilon(1e-12));
    far = std::max(far, local.cwiseAbs().maxCoeff());
  }
  CHECK(far == Approx(h + r).epsilon(1e-12));  // the icosphere holds the six axis directions
  // Closed and convex: the volume is that of the rounded cube up to the facets' chords.
  const double volume = enclosed_volume(data, 0, std::size_t(data["n_cells"].number), x) / std::pow(scale, 3);
  const double rounded = 8 * h * h * h + 6 * 4 * h * h * r + 3 * kPi * 2 * h * r * r + 4.0 / 3.0 * kPi * r * r * r;
  CHECK(volume < rounded);
  CHECK(volume > 0.97 * rounded);
}
