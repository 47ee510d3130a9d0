#pragma once
// The determinism tests' scene: 150 cubes and spheres packed close in a walled box.
#include <random>
#include <utility>

#include "sim_fixtures.hpp"

namespace polydem::test {

// The four side walls of a 9 cm box, named "side".
inline void add_side_walls(Scene& scene) {
  for (auto [point, normal] : {std::pair{Vec3(-0.045, 0, 0), Vec3(1, 0, 0)}, {Vec3(0.045, 0, 0), Vec3(-1, 0, 0)},
                               {Vec3(0, -0.045, 0), Vec3(0, 1, 0)}, {Vec3(0, 0.045, 0), Vec3(0, -1, 0)}}) {
    DriverSettings d;
    d.name = "side";
    d.kind = WallSettings{point, normal, std::nullopt};
    scene.drivers.push_back(d);
  }
}

// 150 cubes and spheres (`cubes_only`: cubes alone; `count` of them, in layers of 25) packed close
// with random velocities and fast spins in a walled box.
struct Pile {
  Scene scene = base_scene(law(1e5, 0.5, 0.4, 1e5), true, Vec3(0, 0, -9.807));
  ShapeLibrary lib = library({cube_shape(0.009, 0.0005), sphere_shape(0.005)});
  std::vector<BodySpec> specs;
  explicit Pile(double damp_tangential = 0.0, bool cubes_only = false, int count = 150) {
    scene.forces.contact.config.damp_tangential = scene.forces.contact.config_driver.damp_tangential = damp_tangential;
    add_side_walls(scene);
    std::mt19937_64 rng(7);
    auto u = [&] { return double(rng() >> 11) * 0x1.0p-53 - 0.5; };
    for (int k = 0; k < count; ++k) {  // a 5 x 5 x 6 lattice, bounding spheres 1 mm apart, moving into each other
      const Vec3 x(0.0175 * (k % 5 - 2), 0.0175 * ((k / 5) % 5 - 2), 0.01 + 0.0175 * (k / 25));
      BodySpec b = body(cubes_only || k % 3 ? "cube" : "sphere", x, 2.0 * Vec3(u(), u(), u()),
                        Quat(Eigen::Vector4d(u(), u(), u(), u())).normalized());
      b.angular_velocity = 200.0 * Vec3(u(), u(), u());  // rad/s: fast rotations stress the Verlet lists
      specs.push_back(b);
    }
  }
};


}  // namespace polydem::test
