#pragma once
// Scenes built in code for the physics tests: shapes, bodies and settings without YAML.
#include <cmath>
#include <cstring>
#include <vector>

#include "io/scene_settings.hpp"
#include "polydem/shape_library.hpp"
#include "shape/mass.hpp"
#include "sim/simulation.hpp"

namespace polydem::test {

inline Shape sphere_shape(double radius, const char* name = "sphere") {
  Shape s;
  s.name = name;
  s.radius = radius;
  s.vertices = {Vec3::Zero()};
  compute_mass_properties(s);
  return s;
}

// A right prism over a regular n-gon (circumradius c, height h) rounded by r.
inline Shape prism_shape(int n, double c, double h, double r, const char* name) {
  Shape s;
  s.name = name;
  s.radius = r;
  std::vector<int> bottom, top;
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * kPi * (k + 0.5) / n;
    s.vertices.push_back({c * std::cos(a), c * std::sin(a), -0.5 * h});
    s.vertices.push_back({c * std::cos(a), c * std::sin(a), 0.5 * h});
  }
  for (int k = 0; k < n; ++k) {
    const int b0 = 2 * k, t0 = 2 * k + 1, b1 = 2 * ((k + 1) % n), t1 = b1 + 1;
    s.edges.push_back({b0, b1});
    s.edges.push_back({t0, t1});
    s.edges.push_back({b0, t0});
    s.faces.push_back({b0, b1, t1, t0});  // side, counter-clockwise seen from outside
    bottom.insert(bottom.begin(), b0);    // reversed: seen from below
    top.push_back(t0);
  }
  s.faces.push_back(bottom);
  s.faces.push_back(top);
  compute_mass_properties(s);
  return s;
}

// A cube of core side a rounded by r (a square prism with circumradius a / sqrt(2)).
inline Shape cube_shape(double a, double r) { return prism_shape(4, a / std::sqrt(2.0), a, r, "cube"); }

inline ContactParams law(double kn, double en, double mu = 0.0, double kt = 0.0) {
  ContactParams p;
  p.kn = kn;
  p.kt = kt;
  p.mu = mu;
  p.en = en;
  return p;
}

// A scene with a contact law and, optionally, a floor wall at z = 0 and gravity.
inline Scene base_scene(const ContactParams& config, bool floor, std::optional<Vec3> gravity = std::nullopt) {
  Scene s;
  s.path = "test.yaml";
  s.simulation.duration = 1.0;
  s.forces.gravity = gravity;
  s.forces.contact.present = true;
  s.forces.contact.config = config;
  s.forces.contact.config_driver = config;
  s.forces.contact.has_config_driver = true;
  if (floor) {
    DriverSettings d;  // a wall through the origin, normal +z
    d.name = "floor";
    s.drivers.push_back(d);
  }
  return s;
}

inline BodySpec body(const char* shape, Vec3 x, Vec3 v = Vec3::Zero(), Quat q = Quat::Identity()) {
  BodySpec b;
  b.shape = shape;
  b.position = x;
  b.velocity = v;
  b.orientation = q;
  return b;
}

inline ShapeLibrary library(std::vector<Shape> shapes) {
  ShapeLibrary lib;
  lib.shapes = std::move(shapes);
  return lib;
}

// Steps `sim` through `seconds` of simulated time (rounded to whole steps).
inline void run_for(Simulation& sim, double seconds) {
  for (long long s = std::llround(seconds / sim.dt()); s > 0; --s) sim.step();
}

// Steps until the bodies have touched and every contact has ended again (an impact and its
// rebound), at most max_steps. Returns false when nothing touched.
inline bool run_through_impact(Simulation& sim, int max_steps) {
  bool touched = false;
  for (int s = 0; s < max_steps && !(touched && sim.engine().stats().contacts == 0); ++s) {
    sim.step();
    touched = touched || sim.engine().stats().contacts > 0;
  }
  return touched;
}

// Whether two arrays hold the same bytes (bitwise determinism checks; empty ones have no data to compare).
template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(static_cast<const void*>(a.data()), static_cast<const void*>(b.data()),
                                             a.size() * sizeof(T)) == 0);
}

}  // namespace polydem::test
