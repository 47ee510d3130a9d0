#pragma once
// The laws a fast kernel is checked under against the general path, bit for bit: both
// readings of the normal dashpot, the tangential dashpot, rolling with cohesion, Hertz.
#include <vector>

#include "sim_fixtures.hpp"

namespace polydem::test {

struct LawCase {
  const char* name;
  ContactParams config;
  bool exact_step;
};

inline std::vector<LawCase> kernel_law_cases() {
  ContactParams dashpot = law(1e5, 0.5, 0.4, 0.8e5);
  dashpot.damp_tangential = 0.2;
  ContactParams rolling = law(1e5, 0.3, 0.5, 0.8e5);
  rolling.kr = 1e-3;
  rolling.mur = 0.1;
  rolling.fc = 0.05;
  rolling.dncut = 2e-4;
  ContactParams hertz = law(0.0, 0.5, 0.4);
  hertz.hertz = true;
  hertz.young = 5e6;
  hertz.poisson = 0.3;
  return {{"linear, exact step", law(1e5, 0.5, 0.4, 0.8e5), true},
          {"linear, end-of-step dashpot", law(1e5, 0.5, 0.4, 0.8e5), false},
          {"tangential dashpot", dashpot, true},
          {"rolling and cohesion", rolling, true},
          {"hertz", hertz, false}};
}

}  // namespace polydem::test
