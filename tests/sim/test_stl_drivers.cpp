// STL mesh drivers in a running simulation: a sphere rests on a meshed floor as on a wall, a
// cube slides on one with the wall's deceleration mu g, and a sphere rebounds from a mesh
// cube's face, edge and vertex as from the analytic shape (e_n along the contact normal).
#include <catch2/catch.hpp>

#include <cmath>
#include <memory>

#include "../driver/mesh_fixtures.hpp"
#include "sim_fixtures.hpp"

using namespace polydem;
using namespace polydem::test;

namespace {

constexpr double kG = 9.807, kRadius = 0.005, kKn = 1e5;

// A scene with the contact law, gravity, and either a wall at z = 0 or the STL file there.
Scene floor_scene(const ContactParams& law, std::optional<Vec3> gravity, const std::string& stl) {
  Scene scene = base_scene(law, stl.empty(), gravity);
  if (!stl.empty()) scene.drivers.push_back(stl_spec(stl, "floor"));
  return scene;
}

}  // namespace

TEST_CASE("a sphere rests on an STL floor with the overlap m g / kn it has on a wall", "[driver][stl]") {
  TempFolder dir;
  write_binary_stl(dir.file("floor.stl"), floor_triangles(8, 0.0078125));
  const ShapeLibrary lib = library({sphere_shape(kRadius)});
  const Vec3 start(0.0078125, 0.0, kRadius);  // over a shared vertex of the mesh
  Simulation on_mesh(floor_scene(law(kKn, 0.3, 0.5, kKn), Vec3(0, 0, -kG), dir.file("floor.stl")), lib,
                     {body("sphere", start)});
  Simulation on_wall(floor_scene(law(kKn, 0.3, 0.5, kKn), Vec3(0, 0, -kG), ""), lib, {body("sphere", start)});
  run_for(on_mesh, 0.1);
  run_for(on_wall, 0.1);
  const double overlap = kRadius - on_mesh.bodies.position[0].z();
  CHECK(overlap == Approx(on_mesh.bodies.mass[0] * kG / kKn).epsilon(1e-3));
  CHECK(on_mesh.bodies.position[0].z() == Approx(on_wall.bodies.position[0].z()).epsilon(1e-12));
  CHECK(on_mesh.drivers[0].force.z() == Approx(-on_mesh.bodies.mass[0] * kG).epsilon(1e-3));
  CHECK(on_mesh.engine().stats().contacts == 1);  // one spring over a vertex shared by six triangles
}

TEST_CASE("a cube sliding on a meshed floor decelerates at mu g, as on a wall", "[driver][stl][friction]") {
  TempFolder dir;
  write_binary_stl(dir.file("floor.stl"), floor_triangles(40, 0.00390625));  // 80 x 80 mm of 3.9 mm squares
  const double mu = 0.3, v0 = 0.3, a = 0.01, r = 0.0005;  // m/s, m: core side, rounding
  const ShapeLibrary lib = library({cube_shape(a, r)});
  const ContactParams contact = law(kKn, 0.3, mu, kKn);
  auto slide = [&](const std::string& stl) {
    Scene scene = floor_scene(contact, Vec3(0, 0, -kG), stl);
    auto sim = std::make_unique<Simulation>(scene, lib, std::vector<BodySpec>{body("cube", {-0.01, 0.0013, 0.5 * a + r - 1e-6}, {v0, 0, 0})});
    return sim;
  };
  auto on_mesh = slide(dir.file("floor.stl"));
  auto on_wall = slide("");
  run_for(*on_mesh, 0.06);
  run_for(*on_wall, 0.06);
  const double t = on_mesh->time();
  const double expected = v0 - mu * kG * t;  // m/s, Coulomb sliding (still sliding: stops at 0.1 s)
  CHECK(on_mesh->bodies.velocity[0].x() == Approx(expected).epsilon(0.03));
  CHECK(on_mesh->bodies.velocity[0].x() == Approx(on_wall->bodies.velocity[0].x()).epsilon(1e-9));
  CHECK(on_mesh->bodies.position[0].x() == Approx(on_wall->bodies.position[0].x()).epsilon(1e-9));
  CHECK(on_mesh->bodies.position[0].x() > 0.0);  // each vertex crossed about six flat mesh edges
}

TEST_CASE("a sphere rebounds from an STL face, edge and vertex as from the analytic cube", "[driver][stl][impact]") {
  TempFolder dir;
  const double h = 0.0078125;  // m, exact in float32
  write_binary_stl(dir.file("cube.stl"), cube_triangles(h));
  const ShapeLibrary lib = library({sphere_shape(kRadius)});
  const double en = 0.5, speed = 1.0;
  struct Hit { const char* what; Vec3 normal; Vec3 along; };  // along: a velocity the contact must keep
  const Hit hits[] = {{"face", Vec3(0, 0, 1), Vec3(0.3, 0.1, 0)},
                      {"edge", Vec3(1, 1, 0).normalized(), Vec3(0, 0, 0.4)},
                      {"vertex", Vec3(1, 1, 1).normalized(), Vec3::Zero()}};
  for (const Hit& hit : hits) {
    Scene scene = base_scene(law(kKn, en), false);
    scene.drivers.push_back(stl_spec(dir.file("cube.stl"), "cube"));
    scene.simulation.dt = kPi * std::sqrt(2700.0 * lib.shapes[0].volume / kKn) / 400.0;
    const Vec3 corner = hit.normal.cwiseSign().cwiseAbs().cwiseProduct(Vec3::Constant(h));  // closest box point
    const Vec3 start = corner + (kRadius + 2e-4) * hit.normal - 2e-4 / speed * hit.along;
    Simulation sim(scene, lib, {body("sphere", start, -speed * hit.normal + hit.along)});
    REQUIRE(run_through_impact(sim, 40000));
    const Vec3 v = sim.bodies.velocity[0];
    INFO(hit.what << ": v after " << v.transpose());
    CHECK(v.dot(hit.normal) == Approx(en * speed).epsilon(0.005));  // exact e_n of the law, m_eff = m
    CHECK((v - v.dot(hit.normal) * hit.normal - hit.along).norm() < 1e-6);  // frictionless: tangential kept
  }
}

TEST_CASE("a cube's edge crossing an STL edge rebounds head-on with e_n and no spin", "[driver][stl][impact]") {
  TempFolder dir;
  const double h = 0.0078125, a = 0.01, r = 0.0005, en = 0.5, speed = 1.0;  // m, m/s
  write_binary_stl(dir.file("cube.stl"), cube_triangles(h));
  const ShapeLibrary lib = library({cube_shape(a, r)});
  Scene scene = base_scene(law(kKn, en), false);
  scene.drivers.push_back(stl_spec(dir.file("cube.stl"), "cube"));
  const Vec3 n = Vec3(1, 1, 0).normalized();  // out of the mesh's vertical edge at (h, h, z)
  // The particle's edge between its +x and +y faces turned to face -n, lying along (1, -1, 0).
  Mat3 from, to;
  from << Vec3(1, 1, 0).normalized(), Vec3(-1, 1, 0).normalized(), Vec3::UnitZ();
  to << -n, -Vec3::UnitZ(), Vec3(1, -1, 0).normalized();
  const Quat q(to * from.transpose());
  const Vec3 start = Vec3(h, h, 0) + (0.5 * a * std::sqrt(2.0) + r + 2e-4) * n;  // its edge 0.2 mm away
  const double mass = 2700.0 * lib.shapes[0].volume;
  scene.simulation.dt = kPi * std::sqrt(mass / kKn) / 400.0;
  Simulation sim(scene, lib, {body("cube", start, -speed * n, q)});
  int edge_edge_steps = 0, other_steps = 0;  // steps with an active contact of each kind
  for (int s = 0; s < 40000 && sim.bodies.velocity[0].dot(n) < 0.0; ++s) {
    sim.step();
    const PairList& list = sim.engine().driver_pairs();
    for (std::size_t k = 0; k < list.slot_count(); ++k)
      if (list.active[k]) ++(list.features[k].type == PairType::edge_edge ? edge_edge_steps : other_steps);
  }
  REQUIRE(run_through_impact(sim, 40000));
  CHECK(edge_edge_steps > 100);
  CHECK(other_steps == 0);
  CHECK(sim.bodies.velocity[0].dot(n) == Approx(en * speed).epsilon(0.005));  // force through the centre
  CHECK((sim.bodies.velocity[0] - sim.bodies.velocity[0].dot(n) * n).norm() < 1e-9);
  CHECK(sim.bodies.angular_velocity[0].norm() < 1e-6);
}
