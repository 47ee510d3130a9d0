#pragma once
// A pair of bodies found by the broad phase, and the one distance test every search shares.
#include <cstdint>

namespace polydem {

struct BodyPair {
  std::uint32_t i, j;  // body indices, i < j
  friend bool operator==(const BodyPair&, const BodyPair&) = default;
};

// True when two bounding spheres are within `skin` (m) of touching: |xa - xb| < ra + rb + skin.
// Symmetric bit for bit in (a, b), so the cell search and the brute-force reference agree exactly.
inline bool within_reach(double ax, double ay, double az, double ra, double bx, double by,
                         double bz, double rb, double skin) {
  const double dx = ax - bx;
  const double dy = ay - by;
  const double dz = az - bz;
  const double reach = ra + rb + skin;
  return dx * dx + dy * dy + dz * dz < reach * reach;
}

}  // namespace polydem
