#pragma once
// The two partners of the pair walk (pair_kernel.hpp's Partner): the other body of a body pair,
// or the driver of a body-driver pair. What the kernels read of the pair's second side.
#include <cstdint>
#include <variant>

#include "contact/made_pose.hpp"
#include "contact/pair_kernel.hpp"
#include "driver/drivers.hpp"

namespace polydem::engine_detail {

// The partner of a body-body pair: the other body. kMade: a box's vertices are made where read
// (made_pose.hpp); else every pose's are stored, and read with no test (chosen once a step).
template <bool kMade>
struct BodyPartner {
  static constexpr bool kRetires = true;  // the kernels' allowances hold between two bodies (pair_kernel.hpp)
  static constexpr bool kMadeVertices = kMade;
  const PosedBody* posed;
  const Vec3* position;          // m
  const Vec3* velocity;          // m/s
  const Vec3* angular_velocity;  // rad/s
  const Vec3* velocity_end;      // m/s, predicted for the end of the step
  const Vec3* angular_velocity_end;  // rad/s, likewise
  const double* mass;            // kg
  const double* displacement;  // m, per body since the lists were built
  const Vec3* world_vertices;  // m, the stored poses' vertices
  const std::uint32_t* vertex_offset;  // body j's vertices: world_vertices[vertex_offset[j] ...]
  ShapeBoxes boxes;
  // Starts loading what the kernels will read of body j: its pose (a box's orientation: its pose
  // is made from it), vertices and velocities sit anywhere in memory, and the next pair's loads
  // would otherwise stall.
  void prefetch(std::uint32_t j) const {
    if (kMade && boxes.is_box(j)) {
      __builtin_prefetch(&boxes.orientation[j]);
      __builtin_prefetch(&position[j]);
    } else {
      const char* pose = reinterpret_cast<const char*>(&posed[j]);
      __builtin_prefetch(pose);
      __builtin_prefetch(pose + 64);
      const char* v = reinterpret_cast<const char*>(world_vertices + vertex_offset[j]);
      const char* v_end = reinterpret_cast<const char*>(world_vertices + vertex_offset[j + 1]);
      for (; v < v_end; v += 64) __builtin_prefetch(v);
    }
    __builtin_prefetch(&velocity[j]);
    __builtin_prefetch(&angular_velocity[j]);
    __builtin_prefetch(&velocity_end[j]);
    __builtin_prefetch(&angular_velocity_end[j]);
  }
  const PosedBody& posed_of(std::uint32_t j, PairScratch& s) const {
    if constexpr (kMade) {
      MadeWalk& w = *s.made;  // made by the caller (pair_forces_into)
      return with_vertices(posed, j, boxes, w.corners, w.made_j, w.made_i);
    }
    return posed[j];
  }
  bool contact(const PosedBody& a, const PosedBody& b, FeaturePair f, double max_gap, ContactPoint& out) const {
    return feature_contact(a, b, f, max_gap, out);
  }
  double allowance(const PosedBody& a, const PosedBody& b, FeaturePair f) const { return rejection_allowance(a, b, f); }  // m
  // Rigorous: a feature distance shrinks by at most the two bodies' displacement bounds.
  bool apart(const PairList& list, std::uint32_t k, double band) const {
    const BodyPair p = list.pairs[k];
    return list.gap_at_build[k] - displacement[p.i] - displacement[p.j] >= band;
  }
  double moved(std::uint32_t i, std::uint32_t j) const { return displacement[i] + displacement[j]; }  // m
  bool separated(const PosedBody& a, const PosedBody& b, double band) const { return separated_along_centres(a, b, band); }
  // Of body j's pose b (posed_of's): a made box's is read where it was made, not in `posed`.
  double radius(const PosedBody& b) const { return b.radius; }
  double r_star(double r_i, const PosedBody& b) const { return r_i * b.radius / (r_i + b.radius); }  // m
  bool convex(const PosedBody& b) const { return b.shape->convex; }
  const Shape* shape(const PosedBody& b) const { return b.shape; }
  Vec3 center(std::uint32_t j) const { return position[j]; }
  RigidMotion motion(std::uint32_t j) const {
    return {velocity[j], angular_velocity[j], position[j], velocity_end[j], angular_velocity_end[j]};
  }
  double point_inverse_mass(const PosedBody& b, std::uint32_t j, const Vec3& point, const Vec3& n) const {
    return polydem::point_inverse_mass(b, mass_of(j), point - position[j], n);
  }
  double m_eff(std::uint32_t i, std::uint32_t j) const {
    const double mi = mass_of(i), mj = mass_of(j);
    return mi * mj / (mi + mj);
  }
  // kg; a made walk's alike bodies read body 0's (ShapeBoxes::body_mask), the stored walk each one's.
  double mass_of(std::uint32_t b) const { return mass[kMade ? b & boxes.body_mask : b]; }
};

// The partner of a body-driver pair: a driver of infinite mass (m_eff = m_i, SPEC). kMade: as BodyPartner's.
template <bool kMade>
struct DriverPartner {
  static constexpr bool kRetires = false;  // a driver's kernels pose their partner anew: no allowance
  static constexpr bool kMadeVertices = kMade;
  const Drivers* drivers;
  const double* mass;  // kg, per local body
  std::uint32_t body_mask = ~0u;  // a made walk's ShapeBoxes::body_mask: 0, every body body 0's mass
  std::uint32_t posed_of(std::uint32_t j, PairScratch&) const { return j; }  // its kernels pose it themselves
  // A wall's (most driver pairs') inline, not through the variant's jump: ~5 instructions a slot.
  bool contact(const PosedBody& a, std::uint32_t j, FeaturePair f, double max_gap, ContactPoint& out) const {
    if (const Wall* wall = std::get_if<Wall>(&drivers->kind(j)))
      return (*drivers)[j].active && wall->contact((*drivers)[j], a, f, max_gap, out);
    return drivers->contact(a, j, f, max_gap, out);
  }
  bool apart(const PairList&, std::uint32_t, double) const { return false; }  // a moving driver has no bound
  double moved(std::uint32_t, std::uint32_t) const { return 0.0; }  // its slots' gaps are -inf
  bool separated(const PosedBody&, std::uint32_t, double) const { return false; }  // walls: slots are cheap
  // Of driver j (posed_of's): as BodyPartner's of a body's pose.
  double radius(std::uint32_t j) const { return drivers->rounding(j); }  // balls and posts: a rounded point, segment
  double r_star(double r_i, std::uint32_t j) const { return drivers->r_star(j, r_i); }  // m
  bool convex(std::uint32_t) const { return true; }
  const Shape* shape(std::uint32_t) const { return nullptr; }
  Vec3 center(std::uint32_t j) const {
    if (const Wall* wall = std::get_if<Wall>(&drivers->kind(j))) return wall->reference((*drivers)[j]);  // as contact's
    return drivers->center(j);
  }
  RigidMotion motion(std::uint32_t j) const {  // as Drivers::velocity_at
    const DriverState& d = (*drivers)[j];
    return {d.velocity, d.omega, d.pivot, d.velocity, d.omega};
  }
  double m_eff(std::uint32_t i, std::uint32_t) const { return mass[kMade ? i & body_mask : i]; }
  double point_inverse_mass(std::uint32_t, std::uint32_t, const Vec3&, const Vec3&) const { return 0.0; }  // infinitely massive
  void prefetch(std::uint32_t) const {}  // few drivers: they stay in cache
};

}  // namespace polydem::engine_detail
