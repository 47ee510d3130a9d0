#pragma once
// Volume integrals of 1, x and x x^T over a body or a piece of it.
#include "polydem/math.hpp"

namespace polydem {

struct Moments {
  double volume = 0.0;          // m^3
  Vec3 first = Vec3::Zero();    // m^4
  Mat3 second = Mat3::Zero();   // m^5

  void add(const Moments& o) {
    volume += o.volume;
    first += o.first;
    second += o.second;
  }
};

}  // namespace polydem
