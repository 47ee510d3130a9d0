// Mesh contact geometry against brute-force references: one contact per touch, with the gap
// and normal of the analytic surface (plane, box), on flat meshes, edges, vertices and valleys.
#include <catch2/catch.hpp>

#include <random>

#include "driver/mesh.hpp"
#include "mesh_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kR = 0.004;  // m, sphere radius

// Distance from p to the box [-h, h]^3 (outside) and the unit direction from the box to p.
std::pair<double, Vec3> box_distance(const Vec3& p, double h) {
  const Vec3 closest = p.cwiseMax(Vec3::Constant(-h)).cwiseMin(Vec3::Constant(h));
  const Vec3 u = p - closest;
  return {u.norm(), u.normalized()};
}

}  // namespace

TEST_CASE("a sphere over a meshed floor has one contact, that of a plane, wherever it is", "[driver][mesh]") {
  TempFolder dir;
  write_ascii_stl(dir.file("floor.stl"), floor_triangles(8, 0.005));
  const Drivers drivers({stl_spec(dir.file("floor.stl"))});
  const Shape sphere = one_vertex_shape(kR);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> xy(-0.015, 0.015), z(0.0035, 0.004);
  std::vector<Vec3> spots = {{0, 0, 0.0039}, {0.005, 0.005, 0.0039}, {0.0025, 0.0025, 0.0039}, {0.001, 0.001, 0.0039}};
  for (int k = 0; k < 300; ++k) spots.push_back({xy(rng), xy(rng), z(rng)});
  for (const Vec3& x : spots) {
    for (double side : {1.0, -1.0}) {  // two-sided: from above and from below
      const Vec3 at(x.x(), x.y(), side * x.z());
      const Placed p(sphere, at);
      const auto contacts = driver_contacts(drivers, 0, p.body);
      INFO("at " << at.transpose());
      REQUIRE(contacts.size() == 1);  // a point over a shared edge or vertex: still one face
      CHECK(contacts[0].first.type == PairType::vertex_face);
      CHECK(contacts[0].second.gap == Approx(std::abs(at.z()) - kR).margin(1e-15));
      CHECK((contacts[0].second.normal - side * Vec3::UnitZ()).norm() < 1e-15);
    }
  }
}

TEST_CASE("a tilted float32 floor, not quite coplanar, still gives one contact everywhere", "[driver][mesh]") {
  TempFolder dir;
  const Quat tilt(Eigen::AngleAxisd(0.3, Vec3(1, 2, 0.5).normalized()));
  std::vector<Tri> tris = floor_triangles(8, 0.005);
  for (Tri& t : tris) t = {tilt * t.a + Vec3(0.3, 0.2, 0.1), tilt * t.b + Vec3(0.3, 0.2, 0.1), tilt * t.c + Vec3(0.3, 0.2, 0.1)};
  write_binary_stl(dir.file("tilted.stl"), tris);  // rounded to float: ~1e-8 m off the plane
  const Drivers drivers({stl_spec(dir.file("tilted.stl"))});
  CHECK(std::get<MeshDriver>(drivers.kind(0)).features().edges.size() == 32);  // still flat inside: only the rim is made of features
  const Shape sphere = one_vertex_shape(kR);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> xy(-0.015, 0.015), z(0.0035, 0.004);
  for (int k = 0; k < 3000; ++k) {
    const Vec3 local(k < 100 ? 0.005 * std::round(xy(rng) / 0.005) : xy(rng), xy(rng), z(rng));  // some over edges
    const Placed p(sphere, tilt * local + Vec3(0.3, 0.2, 0.1));
    const auto contacts = driver_contacts(drivers, 0, p.body);
    INFO("local " << local.transpose());
    REQUIRE(contacts.size() == 1);
    CHECK(contacts[0].second.gap == Approx(local.z() - kR).margin(1e-7));
  }
}

TEST_CASE("a sphere around a cube mesh touches its face, edge or vertex like the analytic box", "[driver][mesh]") {
  TempFolder dir;
  const double h = 0.0078125;  // m, exact in float32: the binary STL holds the analytic box
  write_binary_stl(dir.file("cube.stl"), cube_triangles(h));
  const Drivers drivers({stl_spec(dir.file("cube.stl"))});
  const Shape sphere = one_vertex_shape(kR);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coord(-h - kR, h + kR);
  int faces = 0, edges = 0, vertices = 0;
  for (int k = 0; k < 4000; ++k) {
    const Vec3 x(coord(rng), coord(rng), coord(rng));
    const auto [distance, normal] = box_distance(x, h);
    if (distance <= 1e-6 || distance >= kR) continue;  // touching spots outside the box only
    const Placed p(sphere, x);
    const auto contacts = driver_contacts(drivers, 0, p.body);
    INFO("at " << x.transpose() << ", distance " << distance);
    REQUIRE(contacts.size() == 1);
    CHECK(contacts[0].second.gap == Approx(distance - kR).margin(1e-12));
    CHECK((contacts[0].second.normal - normal).norm() < 1e-9);
    const PairType t = contacts[0].first.type;
    faces += t == PairType::vertex_face;
    edges += t == PairType::vertex_edge;
    vertices += t == PairType::vertex_vertex;
  }
  CHECK(faces > 50);  // every kind of feature was exercised
  CHECK(edges > 20);
  CHECK(vertices > 5);
}

TEST_CASE("a cube particle lying on a meshed floor has the four springs it has on a wall", "[driver][mesh]") {
  TempFolder dir;
  write_ascii_stl(dir.file("floor.stl"), floor_triangles(10, 0.004));
  const DriverSettings wall;  // a wall through the origin, normal +z
  const Drivers drivers({stl_spec(dir.file("floor.stl")), wall});
  const double h = 0.003, r = 0.0005;
  const Shape cube = cube_particle(h, r);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> xy(-0.01, 0.01), yaw(0.0, kPi), depth(0.0, 1e-5);
  for (int k = 0; k < 200; ++k) {
    const Quat q(Eigen::AngleAxisd(k == 0 ? 0.0 : yaw(rng), Vec3::UnitZ()));
    const Vec3 x(k == 0 ? 0.0 : xy(rng), k == 0 ? 0.0 : xy(rng), h + r - depth(rng));
    const Placed p(cube, x, q);
    const auto on_mesh = driver_contacts(drivers, 0, p.body);
    const auto on_wall = driver_contacts(drivers, 1, p.body);
    INFO("at " << x.transpose() << " yaw " << 2.0 * std::acos(q.w()));
    REQUIRE(on_wall.size() == 4);
    REQUIRE(on_mesh.size() == 4);
    for (int c = 0; c < 4; ++c) {
      CHECK(on_mesh[c].first.type == PairType::vertex_face);
      CHECK(on_mesh[c].second.gap == Approx(on_wall[c].second.gap).margin(1e-15));
    }
  }
}

TEST_CASE("a sphere in a V-shaped valley touches both slopes and never the concave edge", "[driver][mesh]") {
  TempFolder dir;
  const double s = 0.5;  // slope of each side: z = s |x|
  const Vec3 a(0, -0.02, 0), b(0, 0.02, 0);
  const Vec3 left(-0.02, 0, 0.02 * s), right(0.02, 0, 0.02 * s);
  write_ascii_stl(dir.file("valley.stl"), {{a, b, left + b}, {a, left + b, left + a},
                                           {a, right + a, right + b}, {a, right + b, b}});
  const Drivers drivers({stl_spec(dir.file("valley.stl"))});
  const Shape sphere = one_vertex_shape(kR);
  const double lift = kR * std::sqrt(1.0 + s * s);  // height of a sphere touching both slopes
  for (double z : {lift - 1e-5, lift - 2e-6}) {
    const Placed p(sphere, Vec3(0, 0.003, z));
    const auto contacts = driver_contacts(drivers, 0, p.body);
    REQUIRE(contacts.size() == 2);
    for (const auto& [f, c] : contacts) {
      CHECK(f.type == PairType::vertex_face);
      CHECK(c.gap == Approx(z / std::sqrt(1.0 + s * s) - kR).margin(1e-12));  // distance to a slope
    }
  }
  const Placed under(sphere, Vec3(0, 0.003, -kR + 1e-5));  // below the ridge (the other side): the edge
  const auto ridge = driver_contacts(drivers, 0, under.body);
  REQUIRE(ridge.size() == 1);
  CHECK(ridge[0].first.type == PairType::vertex_edge);
  CHECK(ridge[0].second.gap == Approx(-1e-5).margin(1e-12));
}
