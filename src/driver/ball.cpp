#include "driver/ball.hpp"

#include <cmath>

#include "output/vtk.hpp"

namespace polydem {

namespace {

constexpr int kSegments = 48;  // around the ball: smooth enough to look round

}  // namespace

Ball::Ball(const BallSettings& s, Placement& at) : shape_(sphere_shape("", s.radius)) { at.center = s.center; }

DriverMesh Ball::drawing(const Placement& at, const std::string& name, const ViewFrame&) const {
  const int rings = kSegments / 2;
  const Vec3 u = Vec3::UnitX(), w = Vec3::UnitY(), z = Vec3::UnitZ();
  DriverMesh m{name, {}, {}};
  for (int i = 0; i <= rings; ++i) {
    const double polar = kPi * i / rings;
    for (int k = 0; k < kSegments; ++k) {
      const double az = 2.0 * kPi * k / kSegments;
      m.points.push_back(at.center + shape_.radius * (std::sin(polar) * (std::cos(az) * u + std::sin(az) * w) +
                                                      std::cos(polar) * z));
    }
  }
  for (int i = 0; i < rings; ++i)
    for (int k = 0; k < kSegments; ++k) {
      const int next = (k + 1) % kSegments;
      m.polygons.push_back({i * kSegments + k, i * kSegments + next, (i + 1) * kSegments + next, (i + 1) * kSegments + k});
    }
  return m;
}

}  // namespace polydem
