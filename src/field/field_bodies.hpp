#pragma once
// What the field stage reads and writes of each body, by row: one process's Bodies (every row
// its own), or a distributed run's LocalStore (its owned bodies; ghosts skipped: their owners
// apply their forces), so drag and fluid forces need no body of another rank.
#include <cstddef>
#include <cstdint>

#include "polydem/bodies.hpp"

namespace polydem {

struct FieldBodies {
  const Vec3* position;     // m
  const Quat* orientation;  // principal frame -> world frame
  const Vec3* velocity;     // m/s
  const int* shape;
  const double* scale;
  Vec3* force = nullptr;                 // N, the operators add to it (null: read only)
  const std::uint8_t* ghost = nullptr;   // 1: a row another process moves (null: none)
  std::size_t size = 0;                  // rows

  bool owned(std::size_t k) const { return !ghost || !ghost[k]; }
};

// Every row of `a` (Bodies, or a rank's LocalStore) read only, or with its forces written.
template <class Arrays>
FieldBodies field_rows(const Arrays& a) {
  return {a.position.data(), a.orientation.data(), a.velocity.data(), a.shape.data(), a.scale.data(),
          nullptr,           nullptr,              a.position.size()};
}
template <class Arrays>
FieldBodies field_rows(Arrays& a) {
  FieldBodies f = field_rows(static_cast<const Arrays&>(a));
  f.force = a.force.data();
  return f;
}

}  // namespace polydem
