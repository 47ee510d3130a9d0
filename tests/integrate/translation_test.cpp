// Translation: velocity Verlet is exact for a constant force (closed form x0 + v0 t + g t^2/2).
#include <catch2/catch.hpp>

#include "integrate/integrate.hpp"

using namespace polydem;

namespace {

// One engine step with a constant force: kick(dt/2); drift(dt); forces; kick(dt/2).
void fall_step(Bodies& b, double dt, const Vec3& gravity) {
  kick(b, 0.5 * dt);
  drift(b, dt);
  b.force[0] = b.mass[0] * gravity;
  kick(b, 0.5 * dt);
}

}  // namespace

TEST_CASE("free fall matches x0 + v0 t + g t^2/2 at two time steps", "[integrate]") {
  const Vec3 gravity(0.3, -0.2, -9.81);  // m/s^2, tilted so every component is exercised
  const Vec3 x0(1.0, -2.0, 3.0);         // m
  const Vec3 v0(0.5, 0.25, 2.0);         // m/s
  const double t_end = 1.0;              // s
  for (const int steps : {1000, 2000}) {
    const double dt = t_end / steps;
    Bodies b;
    b.resize(1);
    b.mass[0] = 2.5;
    b.inertia[0] = Vec3::Constant(0.1);
    b.position[0] = x0;
    b.velocity[0] = v0;
    b.force[0] = b.mass[0] * gravity;
    for (int n = 0; n < steps; ++n) fall_step(b, dt, gravity);
    const Vec3 x_exact = x0 + v0 * t_end + 0.5 * gravity * t_end * t_end;
    const Vec3 v_exact = v0 + gravity * t_end;
    // Round-off only: ~steps * eps * |x| ~ 1e-12 m; the scheme itself has no error here.
    CHECK((b.position[0] - x_exact).norm() < 1e-11);
    CHECK((b.velocity[0] - v_exact).norm() < 1e-11);
  }
}

TEST_CASE("a half kick with h adds F/m h to v", "[integrate]") {
  Bodies b;
  b.resize(2);
  b.mass = {2.0, 4.0};
  b.inertia = {Vec3::Constant(1.0), Vec3(1.0, 2.0, 3.0)};
  b.force = {Vec3(2.0, 0.0, -4.0), Vec3(0.0, 8.0, 0.0)};
  kick(b, 0.25);
  CHECK(b.velocity[0].isApprox(Vec3(0.25, 0.0, -0.5)));
  CHECK(b.velocity[1].isApprox(Vec3(0.0, 0.5, 0.0)));
}
